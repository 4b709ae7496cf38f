/* rfir-import: converts a plain-text sensor log (textlog 1) into a rawlog in
 * the project's layout, or a rawlog back into a text log. See docs/import.md. */
#include <rfir/common/cli.h>
#include <rfir/common/log_convert.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <filesystem>
#include <iostream>

namespace {
const char* kDescription =
    "Converts a plain-text sensor log (format textlog 1) into an MRPT rawlog in the "
    "rfir layout, or a rawlog back into a text log. The direction follows the file "
    "extensions: --input X.txt --output Y.rawlog imports, --input X.rawlog --output "
    "Y.txt exports. The whole input is checked before anything is written; a malformed "
    "line is reported as FILE:LINE: what is wrong, and nothing is written.";

int run(const std::string& in, const std::string& out, bool lossy, bool quiet) {
    using namespace rfir::common;
    const auto ki = logFileKind(in), ko = logFileKind(out);
    const bool toRawlog = ki == TLogFileKind::Text && ko == TLogFileKind::Rawlog;
    const bool toText = ki == TLogFileKind::Rawlog && ko == TLogFileKind::Text;
    if (!toRawlog && !toText) {
        std::cerr << "rfir-import: error: cannot tell the direction from the file names '"
                  << in << "' -> '" << out
                  << "': use --input X.txt --output Y.rawlog (import) or --input "
                     "X.rawlog --output Y.txt (export)\n";
        return 2;
    }
    if (lossy && toRawlog) {
        std::cerr << "rfir-import: error: --lossy applies to rawlog -> text only\n";
        return 2;
    }
    if (!std::filesystem::is_regular_file(in)) {
        std::cerr << "rfir-import: error: " << in
                  << (std::filesystem::is_directory(in) ? ": is a directory, not a file\n"
                                                        : ": no such file\n");
        return 1;
    }
    TConvertOptions opts;
    opts.lossy = lossy;
    opts.progress = quiet ? nullptr : &std::cerr;
    const auto rep = toRawlog ? convertTextLogToRawlog(in, out, opts)
                              : convertRawlogToTextLog(in, out, opts);
    if (!quiet) {
        std::cerr << "rfir-import: wrote " << out << ": " << rep.instants
                  << " sensing instant(s), " << rep.timedRecords << " timed record(s)\n";
        for (const auto& [what, n] : rep.dropped)
            std::cerr << "  left out (--lossy): " << n << " x " << what << "\n";
    }
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    try {
        TCLAP::CmdLine cmd(kDescription, ' ', RFIR_VERSION);
        TCLAP::ValueArg<std::string> in(
            "i", "input",
            std::string("input file: .txt or .rawlog") + rfir::common::kRawlogClassesHelp,
            true, "", "FILE", cmd);
        TCLAP::ValueArg<std::string> out("o", "output", "output file: .rawlog or .txt",
                                         true, "", "FILE", cmd);
        TCLAP::SwitchArg lossy("", "lossy",
                               "rawlog -> text: write what textlog 1 can hold and list "
                               "what it cannot, instead of failing",
                               cmd, false);
        TCLAP::SwitchArg quiet("q", "quiet", rfir::common::kQuietHelp, cmd, false);
        if (const auto code = rfir::common::parseCommandLine(cmd, argc, argv))
            return *code;
        return run(in.getValue(), out.getValue(), lossy.getValue(), quiet.getValue());
    } catch (const std::exception& e) {
        std::cerr << "rfir-import: error: " << e.what() << "\n";
        return 1;
    }
}
