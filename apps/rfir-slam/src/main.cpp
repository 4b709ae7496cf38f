/* rfir-slam: offline SLAM (PF-SLAM, PS-SLAM, FastSLAM 1.0) on a rawlog. */
#include <rfir/slamapp/slam_app.h>

#include <rfir/common/cli.h>
#include <rfir/common/gui_args.h>
#include <rfir/common/ini_key_docs.h>
#ifdef RFIR_WITH_GUI
#include <rfir/view/CLiveView.h>
#endif

#include <algorithm>
#include <iostream>
#include <memory>
#include <vector>

int main(int argc, char** argv) {
    try {
        std::vector<std::string> args(argv, argv + argc);
        // --help-keys reads no rawlog and writes nothing: those options are
        // then optional.
        const bool listKeys =
            std::find(args.begin(), args.end(), "--help-keys") != args.end();
        TCLAP::CmdLine cmd(
            "rfir-slam: PF-SLAM, PS-SLAM or FastSLAM on a project rawlog. Writes "
            "path.tum, map.txt, settings.ini, stats.json, path_map.png, scene.3Dscene "
            "(and errors.json, error_time.png with ground truth) into --out-dir. --gui "
            "shows the run live; --gui-record DIR also writes its frames as PNG files "
            "(docs/live-view.md).",
            ' ', RFIR_VERSION);
        TCLAP::ValueArg<std::string> rawlog(
            "", "rawlog", std::string("input rawlog") + rfir::common::kRawlogClassesHelp,
            !listKeys, "", "FILE", cmd);
        TCLAP::ValueArg<std::string> outDir("", "out-dir", "output folder", !listKeys, "",
                                            "DIR", cmd);
        std::vector<std::string> methods = {"pf", "ps", "fastslam", "odometry"};
        TCLAP::ValuesConstraint<std::string> methodNames(methods);
        TCLAP::ValueArg<std::string> method(
            "", "method", "the method (default: the INI's [slam] method, or pf)", false,
            "", &methodNames, cmd);
        rfir::common::CConfigArg config(
            "", "config",
            "INI file, or a stock one by name (e.g. slam_ps); default: the method's "
            "stock INI",
            false, cmd, "slam_");
        TCLAP::MultiArg<std::string> sets(
            "", "set",
            "override an INI key, e.g. --set slam.robot_particles=200 (repeatable)",
            false, "SECTION.KEY=VALUE", cmd);
        rfir::common::CNumberArg<uint64_t> seed("", "seed", "random seed (default 1)",
                                                false, 1, "N", cmd);
        rfir::common::CNumberListArg<double> start(
            "", "start", "start pose X Y PHI, or \"X Y PHI\" (default: the rawlog's)",
            false, "X Y PHI", cmd, ' ', 3);
        TCLAP::ValueArg<std::string> gtPath(
            "", "gt-path",
            "ground-truth path (TUM; default: <stem>.gt.tum beside the rawlog)", false,
            "", "TUM", cmd);
        TCLAP::ValueArg<std::string> gtMap(
            "", "gt-map",
            "ground-truth map (default: <stem>.gt_map.txt beside the rawlog)", false, "",
            "FILE", cmd);
        TCLAP::SwitchArg smooth(
            "", "smooth",
            "also smooth the run offline (odometry + RFID reads, from the filter's "
            "output; beyond the papers): path_smoothed.tum, map_smoothed.txt, "
            "path_map_smoothed.png, errors_smoothed.json",
            cmd, false);
        TCLAP::SwitchArg quiet("q", "quiet", rfir::common::kQuietHelp, cmd, false);
        TCLAP::SwitchArg helpKeys("", "help-keys", rfir::common::kHelpKeysHelp, cmd,
                                  false);
        rfir::common::CGuiArgs gui(cmd);
        rfir::common::foldOptionValues(args, "--start", 3);
        if (const auto code = rfir::common::parseCommandLine(cmd, args)) return *code;
        gui.check();
#ifdef RFIR_WITH_GUI
        std::unique_ptr<rfir::view::CLiveView> view;  // checks the display first
        if (gui.requested() && !listKeys)
            view = std::make_unique<rfir::view::CLiveView>(
                rfir::view::TLiveViewOptions{"rfir-slam", gui.recordDir(), gui.every()});
#else
        if (gui.requested())
            throw rfir::common::CUsageError(
                rfir::common::guiNotBuiltMessage("rfir-slam"));
#endif

        rfir::slamapp::TAppArgs a;
        if (start.isSet())
            a.start = {start.values()[0], start.values()[1], start.values()[2]};
        a.rawlog = rawlog.getValue();
        a.outDir = outDir.getValue();
        // runSlam writes nothing without a folder (the Python module's runs).
        if (a.outDir.empty() && !listKeys)
            throw rfir::common::CUsageError("--out-dir: an empty folder name");
        if (method.isSet()) a.method = method.getValue();
        if (config.isSet()) a.config = config.getValue();
        if (gtPath.isSet()) a.gtPath = gtPath.getValue();
        if (gtMap.isSet()) a.gtMap = gtMap.getValue();
        a.seed = seed.getValue();
        a.smooth = smooth.getValue();
        a.sets = sets.getValue();
        a.quiet = quiet.getValue();
        a.helpKeys = helpKeys.getValue();
#ifdef RFIR_WITH_GUI
        if (view) a.onStep = view->slamObserver();
#endif
        return rfir::slamapp::runSlamApp(a);
    } catch (const rfir::common::CUsageError& e) {  // thrown before any work
        std::cerr << "rfir-slam: error: " << e.what() << "\n";
        return rfir::common::kUsageExitCode;
    } catch (const std::exception& e) {
        std::cerr << "rfir-slam: error: " << e.what() << "\n";
        return 1;
    }
}
