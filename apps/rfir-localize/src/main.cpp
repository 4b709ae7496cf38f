/* rfir-localize: Monte Carlo localization of a robot under the ceiling IR
 * emitters of thesis chapter 5, from an unknown start. See docs/ir.md. */
#include <rfir/common/install_paths.h>
#include <rfir/localize/localize_config.h>
#include <rfir/localize/localize_output.h>
#include <rfir/localize/localize_run.h>

#include <rfir/common/cli.h>
#include <rfir/common/gui_args.h>
#include <rfir/common/ini_key_docs.h>
#include <rfir/common/ini_override.h>
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/core/exceptions.h>
#ifdef RFIR_WITH_GUI
#include <rfir/view/CLiveView.h>
#endif

#include <algorithm>
#include <iostream>

namespace {
const char* kDescription =
    "Monte Carlo localization (thesis chapter 5, Algorithm 3) of a robot whose "
    "receivers read ceiling IR emitters of known positions, from an unknown start; the "
    "estimate is reported from the first unique-ID reading on. Raw receiver windows are "
    "FFT-decoded when the rawlog has no codes. Writes OUT/path.tum, stats.json, "
    "settings.ini, path_map.png, emitter_health.txt and, with a ground-truth path "
    "(--gt-path, or <stem>.gt.tum beside the rawlog), errors.json and error_time.png "
    "(errors_spots.json with <stem>.spots.tum). "
    "Default configuration: <exe_dir>/../share/rfir/config_ini/ir_localize.ini.";

std::string joinArgs(int argc, char** argv) {
    std::string s;
    for (int i = 0; i < argc; i++) s += (i ? " " : "") + std::string(argv[i]);
    return s;
}

int run(rfir::localize::TConfig& cfg, const std::string& emitters, const std::string& cmd,
        const rfir::localize::TStepObserver& onStep) {
    const auto job = rfir::localize::runLocalizeJob(cfg, emitters, cmd, onStep);
    if (!cfg.quiet) std::cout << job.summary.errorTable;
    return 0;
}

/** --help-keys: the keys of the INI with the --set edits, on stdout. */
int listKeys(const rfir::localize::TConfig& cfg, const std::string& emitters) {
    std::cout << rfir::common::describeKeys("rfir-localize", [&] {
        std::string text;
        rfir::common::loadWithIniEdits(cfg.overrides,
                                       [&](const std::vector<std::string>& e) {
                                           auto c = cfg;
                                           c.overrides = e;
                                           rfir::localize::loadConfig(c, emitters, false);
                                           text = rfir::localize::settingsIni(c, "");
                                       });
        return text;
    });
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    // --help-keys reads no rawlog and writes nothing: those options are then
    // optional.
    const bool keysOnly =
        std::find(argv, argv + argc, std::string("--help-keys")) != argv + argc;
    TCLAP::CmdLine cmd(kDescription, ' ', RFIR_VERSION);
    TCLAP::ValueArg<std::string> rawlog(
        "", "rawlog", std::string("input rawlog") + rfir::common::kRawlogClassesHelp,
        !keysOnly, "", "FILE", cmd);
    TCLAP::ValueArg<std::string> emitters(
        "", "emitters", "emitter map file (emitter <id> <x> <y> <z>); overrides the INI",
        false, "", "FILE", cmd);
    TCLAP::ValueArg<std::string> outDir("", "out-dir", "output folder", !keysOnly, "",
                                        "DIR", cmd);
    rfir::common::CConfigArg config(
        "", "config",
        "INI file, or a stock one by name (e.g. ir_localize); default: the stock one",
        false, cmd, "ir_localize");
    TCLAP::ValueArg<std::string> gtPath(
        "", "gt-path",
        "ground-truth path (TUM; default: <stem>.gt.tum beside the rawlog, if there)",
        false, "", "TUM", cmd);
    rfir::common::CNumberArg<uint64_t> seed("", "seed", "random seed (default 1)", false,
                                            1, "N", cmd);
    TCLAP::SwitchArg odoOnly("", "odometry-only",
                             "dead reckoning only, from the start pose (comparison)",
                             cmd);
    TCLAP::MultiArg<std::string> sets(
        "", "set",
        "override an INI key: SECTION.KEY=VALUE (repeatable), "
        "e.g. --set localization.num_particles=300",
        false, "SECTION.KEY=VALUE", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", rfir::common::kQuietHelp, cmd);
    TCLAP::SwitchArg helpKeys("", "help-keys", rfir::common::kHelpKeysHelp, cmd);
    rfir::common::CGuiArgs gui(cmd);
    try {
        if (const auto code = rfir::common::parseCommandLine(cmd, argc, argv))
            return *code;
        gui.check();
        rfir::obs::registerAllClasses();
        rfir::maps::registerIRClasses();
        rfir::localize::TConfig cfg;
        cfg.iniPath = config.isSet() ? config.getValue() : rfir::localize::stockIniPath();
        cfg.gtPath = gtPath.getValue();
        cfg.rawlogPath = rawlog.getValue();
        cfg.outDir = outDir.getValue();
        cfg.seed = seed.getValue();
        cfg.odometryOnly = odoOnly.getValue();
        cfg.quiet = quiet.getValue();
        cfg.overrides = sets.getValue();
        if (helpKeys.getValue()) return listKeys(cfg, emitters.getValue());
        rfir::localize::TStepObserver onStep;
#ifdef RFIR_WITH_GUI
        std::unique_ptr<rfir::view::CLiveView> view;  // checks the display first
        if (gui.requested()) {
            view = std::make_unique<rfir::view::CLiveView>(rfir::view::TLiveViewOptions{
                "rfir-localize", gui.recordDir(), gui.every()});
            onStep = view->localizeObserver();
        }
#else
        if (gui.requested())
            throw rfir::common::CUsageError(
                rfir::common::guiNotBuiltMessage("rfir-localize"));
#endif
        return run(cfg, emitters.getValue(), joinArgs(argc, argv), onStep);
    } catch (const rfir::common::CUsageError& e) {  // thrown before any work
        std::cerr << "rfir-localize: error: " << e.what() << "\n";
        return rfir::common::kUsageExitCode;
    } catch (const std::exception& e) {
        std::cerr << "rfir-localize: error: " << rfir::localize::cleanMessage(e) << "\n";
        return 1;
    }
}
