#include <rfir/common/cli.h>
#include <rfir/common/install_paths.h>

#include <filesystem>
#include <iostream>
#include <typeinfo>

namespace rfir::common {
namespace {
/** TCLAP's own output for --help and --version; errors as one line on stderr
 * naming the option (parse() returns false both after an error and after
 * --help / --version, so the output remembers which it was). */
class CRecordingOutput : public TCLAP::StdOutput {
  public:
    bool failed = false;
    void failure(TCLAP::CmdLineInterface& c, TCLAP::ArgException& e) override {
        failed = true;
        std::string id = e.argId();
        if (id.rfind("Argument: ", 0) == 0) id = id.substr(10);
        if (id.find_first_not_of(' ') == std::string::npos) id.clear();
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
            throw std::invalid_argument(opt + " needs " + std::to_string(n) +
                                        " values (or one quoted argument)");
        for (size_t k = 2; k <= n; k++) args[i + 1] += " " + args[i + k];
        args.erase(args.begin() + i + 2, args.begin() + i + n + 1);
    }
}

std::string resolveConfigFile(const std::string& name) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (name.empty() || fs::exists(name, ec) || name.find('/') != std::string::npos)
        return name;
    const fs::path dir = stockConfigDir();
    for (const std::string& cand : {name, name + ".ini"})
        if (fs::is_regular_file(dir / cand, ec)) return (dir / cand).string();
    return name;
}
}  // namespace rfir::common
