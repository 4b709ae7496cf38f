/* rfir: what every program's command line shares: one parse outcome (help and
 * version exit 0, any error exits 2 before any work, no argument at all prints
 * the usage), strictly parsed numbers and lists, stock INIs found by bare
 * name, deprecated option spellings. Every program's TCLAP::CmdLine gives
 * RFIR_VERSION (rfir/version.h) as its version. */
#pragma once

#include <rfir/common/usage_error.h>
#include <rfir/version.h>

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
 * printed (naming the option) or, when no argument at all was given, after
 * the usage was printed on stderr. MRPT's TCLAP returns false in all cases. */
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

/** parseNumber within [lo, hi], or CUsageError "<what>: '<s>' is not
 * <describeNumber>". */
template <typename T>
T parseNumberOrThrow(const std::string& what, const std::string& s,
                     T lo = std::numeric_limits<T>::lowest(),
                     T hi = std::numeric_limits<T>::max()) {
    const auto v = parseNumber<T>(s);
    if (!v || *v < lo || *v > hi)
        throw CUsageError(what + ": '" + s + "' is not " + describeNumber(lo, hi));
    return *v;
}

namespace detail {
/** The numbers of `s` into `v`; an empty string, or why not (for messages). */
template <typename T>
std::string numberList(const std::string& s, char sep, size_t count, T lo, T hi,
                       std::vector<T>& v) {
    v.clear();
    size_t i = 0;
    while (i <= s.size()) {
        if (sep == ' ') {
            i = s.find_first_not_of(" \t", i);
            if (i == std::string::npos) break;
        }
        size_t j = sep == ' ' ? s.find_first_of(" \t", i) : s.find(sep, i);
        if (j == std::string::npos) j = s.size();
        const std::string item = s.substr(i, j - i);
        const auto x = parseNumber<T>(item);
        if (!x || *x < lo || *x > hi)
            return "'" + item + "' is not " + describeNumber(lo, hi);
        v.push_back(*x);
        i = j + 1;
    }
    if (v.empty() || (count && v.size() != count))
        return "expected " +
               (count ? std::to_string(count) : std::string("one or more")) +
               " number(s), got '" + s + "'";
    return {};
}
}  // namespace detail

/** The numbers of a list separated by `sep` (' ' takes any run of blanks),
 * each by parseNumber within [lo, hi]; `count` (if not 0) is how many there
 * must be. Throws CUsageError "<what>: why". */
template <typename T>
std::vector<T> parseNumberList(const std::string& what, const std::string& s, char sep,
                               size_t count = 0, T lo = std::numeric_limits<T>::lowest(),
                               T hi = std::numeric_limits<T>::max()) {
    std::vector<T> v;
    const std::string why = detail::numberList(s, sep, count, lo, hi, v);
    if (!why.empty()) throw CUsageError(what + ": " + why);
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

/** A TCLAP option whose value is a list of numbers (parseNumberList), checked
 * while the command line is parsed: "X Y PHI", "100,500", ... */
template <typename T>
class CNumberListArg : public TCLAP::ValueArg<std::string> {
  public:
    CNumberListArg(const std::string& flag, const std::string& name,
                   const std::string& desc, bool req, const std::string& typeDesc,
                   TCLAP::CmdLineInterface& cmd, char sep, size_t count = 0,
                   T lo = std::numeric_limits<T>::lowest(),
                   T hi = std::numeric_limits<T>::max())
        : TCLAP::ValueArg<std::string>(flag, name, desc, req, "", typeDesc, cmd),
          sep_(sep),
          count_(count),
          lo_(lo),
          hi_(hi) {}

    bool processArg(int* i, std::vector<std::string>& args) override {
        if (!TCLAP::ValueArg<std::string>::processArg(i, args)) return false;
        const std::string why =
            detail::numberList(_value, sep_, count_, lo_, hi_, values_);
        if (!why.empty()) throw TCLAP::ArgParseException(why, toString());
        return true;
    }

    /** The numbers given (empty when the option was not given). */
    const std::vector<T>& values() const { return values_; }

  private:
    char sep_;
    size_t count_;
    T lo_, hi_;
    std::vector<T> values_;
};

/** Rewrites "OPT A B C" into "OPT 'A B C'" (TCLAP takes one token per value,
 * and negative numbers would look like options); a value already given as
 * one quoted token is kept as it is. Throws CUsageError if fewer than n
 * tokens follow. */
void foldOptionValues(std::vector<std::string>& args, const std::string& opt, size_t n);

/** An INI given as a path, or a stock INI by bare name: "slam_ps.ini" or
 * "slam_ps" finds <stockConfigDir()>/slam_ps.ini. std::nullopt when the name
 * is no file and no stock INI. */
std::optional<std::string> findConfigFile(const std::string& name);

/** findConfigFile, or `name` unchanged (for a loader to report). */
std::string resolveConfigFile(const std::string& name);

/** The stock INIs whose names start with `prefix`, without ".ini": "slam_pf,
 * slam_ps" (for messages). */
std::string stockIniNames(const std::string& prefix);

/** An INI option (--config): a path or a stock INI by bare name, found while
 * the command line is parsed; a value that names neither is a parse error
 * naming the option and the stock INIs whose names start with `stockPrefix`.
 * getValue() is the file found. */
class CConfigArg : public TCLAP::ValueArg<std::string> {
  public:
    CConfigArg(const std::string& flag, const std::string& name, const std::string& desc,
               bool req, TCLAP::CmdLineInterface& cmd, std::string stockPrefix)
        : TCLAP::ValueArg<std::string>(flag, name, desc, req, "", "INI", cmd),
          prefix_(std::move(stockPrefix)) {}
    bool processArg(int* i, std::vector<std::string>& args) override;

  private:
    std::string prefix_;
};

/** The subcommand of a program (rfir-ids encode|decode|...): the first
 * argument that is not an option; a name not in `names` is a parse error
 * listing them. An argument starting with '-' is never taken for it, so that
 * an unknown option is reported as one. */
class CSubcommandArg : public TCLAP::UnlabeledValueArg<std::string> {
  public:
    CSubcommandArg(const std::string& name, std::vector<std::string> names,
                   TCLAP::CmdLineInterface& cmd);
    bool processArg(int* i, std::vector<std::string>& args) override;

  private:
    std::vector<std::string> names_;
};

/** A folder option (--config-dir, ...) that must name an existing folder;
 * throws CUsageError "<option>: no folder '<dir>'" otherwise. */
void checkFolderOption(const std::string& option, const std::string& dir);
}  // namespace rfir::common
