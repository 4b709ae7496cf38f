/* rfir: what every program's command line shares: one parse outcome (help and
 * version exit 0, any error exits 2 before any work), strictly parsed
 * numbers, stock INIs found by bare name, deprecated option spellings. */
#pragma once

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace rfir::common {
/** Said in the help of every option that takes a rawlog. */
inline constexpr const char* kRawlogClassesHelp =
    " (records of MRPT classes rfir does not check are refused unless listed in the "
    "environment variable RFIR_TRUST_MRPT_CLASSES: docs/hardening.md)";

/** Exit code of a command-line error (unknown option, bad value, ...). */
constexpr int kUsageExitCode = 2;

/** What -q / --quiet means in every program. */
constexpr const char* kQuietHelp =
    "quiet: nothing on stdout, no progress or summary on stderr (errors and warnings "
    "still go to stderr)";

/** A spelling kept for old scripts: `old` is rewritten to `now` (also in
 * "old=value") with a warning on stderr. */
struct TOptionAlias {
    std::string old, now;
};

/** Parses `args` (args[0] is the program). Returns std::nullopt when the
 * program is to run; otherwise the exit code to return at once: 0 after
 * --help or --version was printed, kUsageExitCode after a parse error was
 * printed (naming the option). MRPT's TCLAP returns false in both cases. */
std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, std::vector<std::string> args,
                                    const std::vector<TOptionAlias>& aliases = {});
std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv,
                                    const std::vector<TOptionAlias>& aliases = {});

/** The whole of `s` as one number of type T: no sign on unsigned types, no
 * fraction or exponent on integers ("5e2", "1.5" refused), finite only (no
 * nan/inf), no blanks, in T's range. std::nullopt otherwise. */
template <typename T>
std::optional<T> parseNumber(const std::string& s) {
    static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>);
    T v{};
    const char* b = s.data();
    const char* e = b + s.size();
    if (b == e) return std::nullopt;
    std::from_chars_result r;
    if constexpr (std::is_floating_point_v<T>)
        r = std::from_chars(b, e, v, std::chars_format::general);
    else
        r = std::from_chars(b, e, v, 10);
    if (r.ec != std::errc() || r.ptr != e) return std::nullopt;
    if constexpr (std::is_floating_point_v<T>)
        if (!std::isfinite(v)) return std::nullopt;
    return v;
}

/** "a whole number >= 0", "a finite number in [0.5, 2]", ... for messages. */
template <typename T>
std::string describeNumber(T lo, T hi) {
    const bool whole = std::is_integral_v<T>;
    std::string d = whole ? "a whole number" : "a finite number";
    auto str = [](T x) {
        std::ostringstream o;
        o << +x;  // + prints a char-sized integer as a number
        return o.str();
    };
    const bool noLo = lo == std::numeric_limits<T>::lowest();
    const bool noHi = hi == std::numeric_limits<T>::max();
    if (noLo && noHi) return d;
    if (noHi) return d + " >= " + str(lo);
    if (noLo) return d + " <= " + str(hi);
    return d + " in [" + str(lo) + ", " + str(hi) + "]";
}

/** parseNumber within [lo, hi], or std::invalid_argument "<what>: '<s>' is
 * not <describeNumber>". */
template <typename T>
T parseNumberOrThrow(const std::string& what, const std::string& s,
                     T lo = std::numeric_limits<T>::lowest(),
                     T hi = std::numeric_limits<T>::max()) {
    const auto v = parseNumber<T>(s);
    if (!v || *v < lo || *v > hi)
        throw std::invalid_argument(what + ": '" + s + "' is not " +
                                    describeNumber(lo, hi));
    return *v;
}

/** The numbers of a list separated by `sep` (' ' takes any run of blanks),
 * each by parseNumberOrThrow; `count` (if not 0) is how many there must be. */
template <typename T>
std::vector<T> parseNumberList(const std::string& what, const std::string& s, char sep,
                               size_t count = 0, T lo = std::numeric_limits<T>::lowest(),
                               T hi = std::numeric_limits<T>::max()) {
    std::vector<T> v;
    size_t i = 0;
    while (i <= s.size()) {
        if (sep == ' ') {
            i = s.find_first_not_of(" \t", i);
            if (i == std::string::npos) break;
        }
        size_t j = sep == ' ' ? s.find_first_of(" \t", i) : s.find(sep, i);
        if (j == std::string::npos) j = s.size();
        v.push_back(parseNumberOrThrow<T>(what, s.substr(i, j - i), lo, hi));
        i = j + 1;
    }
    if (v.empty() || (count && v.size() != count))
        throw std::invalid_argument(what + ": expected " +
                                    (count ? std::to_string(count) : "one or more") +
                                    " number(s), got '" + s + "'");
    return v;
}

/** A TCLAP option whose value is parsed by parseNumber<T> and checked against
 * [lo, hi] while the command line is parsed, so that a bad value is a parse
 * error naming the option, before any work. */
template <typename T>
class CNumberArg : public TCLAP::ValueArg<std::string> {
  public:
    CNumberArg(const std::string& flag, const std::string& name, const std::string& desc,
               bool req, T def, const std::string& typeDesc, TCLAP::CmdLineInterface& cmd,
               T lo = std::numeric_limits<T>::lowest(),
               T hi = std::numeric_limits<T>::max())
        : TCLAP::ValueArg<std::string>(flag, name, desc, req, "", typeDesc, cmd),
          def_(def),
          value_(def),
          lo_(lo),
          hi_(hi) {}

    bool processArg(int* i, std::vector<std::string>& args) override {
        if (!TCLAP::ValueArg<std::string>::processArg(i, args)) return false;
        const auto v = parseNumber<T>(_value);
        if (!v || *v < lo_ || *v > hi_)
            throw TCLAP::ArgParseException(
                "'" + _value + "' is not " + describeNumber(lo_, hi_), toString());
        value_ = *v;
        return true;
    }

    /** The value given, else the default. */
    T getValue() const { return isSet() ? value_ : def_; }

  private:
    T def_, value_, lo_, hi_;
};

/** Rewrites "OPT A B C" into "OPT 'A B C'" (TCLAP takes one token per value,
 * and negative numbers would look like options); a value already given as
 * one quoted token is kept as it is. Throws if fewer than n tokens follow. */
void foldOptionValues(std::vector<std::string>& args, const std::string& opt, size_t n);

/** An INI given as a path, or a stock INI by bare name: "slam_ps.ini" or
 * "slam_ps" finds <stockConfigDir()>/slam_ps.ini. A name found nowhere is
 * returned unchanged, for the loader to report. */
std::string resolveConfigFile(const std::string& name);
}  // namespace rfir::common
