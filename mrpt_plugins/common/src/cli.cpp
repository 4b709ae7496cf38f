#include <rfir/common/cli.h>
#include <rfir/common/install_paths.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>
#include <typeinfo>

namespace rfir::common {
namespace {
/** TCLAP's own output for --help and --version; errors as one line on stderr
 * naming the option (parse() returns false both after an error and after
 * --help / --version, so the output remembers which it was); with no argument
 * at all, the usage instead. */
class CRecordingOutput : public TCLAP::StdOutput {
  public:
    bool failed = false;
    bool noArgument = false;
    void failure(TCLAP::CmdLineInterface& c, TCLAP::ArgException& e) override {
        failed = true;
        if (noArgument) return printUsage(c);
        std::string id = e.argId();
        if (id.rfind("Argument: ", 0) == 0) id = id.substr(10);
        if (id.find_first_not_of(' ') == std::string::npos) id.clear();
        // "-c (--config)" or "(--config)": the long name.
        const auto open = id.find("(--");
        if (open != std::string::npos && id.back() == ')')
            id = id.substr(open + 1, id.size() - open - 2);
        std::string missing;  // TCLAP does not say which
        const bool requiredMissing = e.error().find("required") != std::string::npos;
        for (const TCLAP::Arg* a : c.getArgList())
            if (requiredMissing && a->isRequired() && !a->isSet())
                missing += (missing.empty() ? "" : ", ") + a->longID();
        std::cerr << c.getProgramName() << ": error: " << (id.empty() ? "" : id + ": ")
                  << e.error();
        if (!missing.empty()) std::cerr << " (missing: " << missing << ")";
        std::cerr << "; see " << c.getProgramName() << " --help\n";
    }
    /** The short usage on stderr: what a run without arguments prints. */
    void printUsage(TCLAP::CmdLineInterface& c) {
        // MRPT's TCLAP writes the short usage to the output's own stream.
        struct CToStderr : TCLAP::StdOutput {
            CToStderr() : TCLAP::StdOutput(std::cerr) {}
            void shortUsage(TCLAP::CmdLineInterface& c) { _shortUsage(c, std::cerr); }
        } err;
        std::cerr << "usage:\n";
        err.shortUsage(c);
        std::cerr << "\n"
                  << c.getProgramName() << ": no argument; see " << c.getProgramName()
                  << " --help\n";
    }
};

std::string programName(const std::string& argv0) {
    return std::filesystem::path(argv0).filename().string();
}

void applyAliases(std::vector<std::string>& args,
                  const std::vector<TOptionAlias>& aliases) {
    for (size_t i = 1; i < args.size(); i++) {
        if (args[i] == "--") break;
        for (const auto& a : aliases) {
            const bool exact = args[i] == a.old;
            const bool withValue = args[i].rfind(a.old + "=", 0) == 0;
            if (!exact && !withValue) continue;
            std::cerr << programName(args[0]) << ": warning: " << a.old
                      << " is deprecated, use " << a.now << "\n";
            args[i] = a.now + args[i].substr(a.old.size());
            break;
        }
    }
}
}  // namespace

std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, std::vector<std::string> args,
                                    const std::vector<TOptionAlias>& aliases) {
    if (args.empty()) args.push_back("program");
    args[0] = programName(args[0]);
    applyAliases(args, aliases);
    std::vector<const char*> av;
    for (const auto& s : args) av.push_back(s.c_str());
    CRecordingOutput out;
    out.noArgument = args.size() == 1;
    TCLAP::CmdLineOutput* before = cmd.getOutput();
    cmd.setOutput(&out);
    const bool run = cmd.parse(int(av.size()), av.data());
    // TCLAP frees its own default output only while setOutput was never
    // called; once it was, putting that output back would leak it. It is a
    // stateless StdOutput: free it, and use one that lives as long as the
    // program.
    static TCLAP::StdOutput stdOutput;
    if (before != &stdOutput && typeid(*before) == typeid(TCLAP::StdOutput))
        delete before;
    cmd.setOutput(&stdOutput);
    if (run && out.noArgument) {  // a program that needs no option still says how
        out.printUsage(cmd);
        return kUsageExitCode;
    }
    if (run) return std::nullopt;
    return out.failed ? kUsageExitCode : 0;
}

std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv,
                                    const std::vector<TOptionAlias>& aliases) {
    return parseCommandLine(cmd, std::vector<std::string>(argv, argv + argc), aliases);
}

void foldOptionValues(std::vector<std::string>& args, const std::string& opt, size_t n) {
    for (size_t i = 1; i < args.size(); i++) {
        if (args[i] == "--") break;
        if (args[i] != opt) continue;
        if (i + 1 < args.size() && args[i + 1].find_first_of(" \t") != std::string::npos)
            continue;  // already one token: "X Y PHI"
        if (i + n >= args.size())
            throw CUsageError(opt + " needs " + std::to_string(n) +
                              " values (or one quoted argument)");
        for (size_t k = 2; k <= n; k++) args[i + 1] += " " + args[i + k];
        args.erase(args.begin() + i + 2, args.begin() + i + n + 1);
    }
}

std::optional<std::string> findConfigFile(const std::string& name) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (name.empty()) return std::nullopt;
    if (fs::is_regular_file(name, ec)) return name;
    if (name.find('/') != std::string::npos || fs::exists(name, ec)) return std::nullopt;
    const fs::path dir = stockConfigDir();
    for (const std::string& cand : {name, name + ".ini"})
        if (fs::is_regular_file(dir / cand, ec)) return (dir / cand).string();
    return std::nullopt;
}

std::string resolveConfigFile(const std::string& name) {
    return findConfigFile(name).value_or(name);
}

std::string stockIniNames(const std::string& prefix) {
    namespace fs = std::filesystem;
    std::set<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(stockConfigDir(), ec)) {
        const std::string f = e.path().filename().string();
        if (e.path().extension() == ".ini" && f.rfind(prefix, 0) == 0)
            names.insert(e.path().stem().string());
    }
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? "none" : s;
}

bool CConfigArg::processArg(int* i, std::vector<std::string>& args) {
    if (!TCLAP::ValueArg<std::string>::processArg(i, args)) return false;
    const auto found = findConfigFile(_value);
    if (!found)
        throw TCLAP::ArgParseException("'" + _value +
                                           "' is no INI file and no stock INI (stock: " +
                                           stockIniNames(prefix_) + ")",
                                       toString());
    _value = *found;
    return true;
}

namespace {
std::string listed(const std::vector<std::string>& v, const std::string& sep) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
    return s;
}
}  // namespace

CSubcommandArg::CSubcommandArg(const std::string& name, std::vector<std::string> names,
                               TCLAP::CmdLineInterface& cmd)
    : TCLAP::UnlabeledValueArg<std::string>(name, listed(names, " | "), true, "",
                                            listed(names, "|"), cmd),
      names_(std::move(names)) {}

bool CSubcommandArg::processArg(int* i, std::vector<std::string>& args) {
    if (isSet() || args[*i].rfind("-", 0) == 0) return false;
    if (std::find(names_.begin(), names_.end(), args[*i]) == names_.end())
        throw TCLAP::ArgParseException(  // no option to name
            "unknown command '" + args[*i] + "' (" + listed(names_, ", ") + ")");
    return TCLAP::UnlabeledValueArg<std::string>::processArg(i, args);
}

void checkFolderOption(const std::string& option, const std::string& dir) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
        throw CUsageError(option + ": no folder '" + dir + "'");
}
}  // namespace rfir::common
