/* rfir-slam: offline SLAM (PF-SLAM, PS-SLAM, FastSLAM 1.0) on a rawlog. */
#include <rfir/slamapp/slam_app.h>

#include <rfir/common/cli.h>

#include <iostream>
#include <vector>

namespace {
mrpt::poses::CPose2D parseStart(const std::string& s) {
    const auto v = rfir::common::parseNumberList<double>("--start X Y PHI", s, ' ', 3);
    return {v[0], v[1], v[2]};
}
}  // namespace

int main(int argc, char** argv) {
    try {
        TCLAP::CmdLine cmd(
            "rfir-slam: PF-SLAM, PS-SLAM or FastSLAM on a project rawlog. Writes "
            "path.tum, map.txt, settings.ini, stats.json, path_map.png, scene.3Dscene "
            "(and errors.json, error_time.png with ground truth) into --out-dir.",
            ' ', "0.1");
        TCLAP::ValueArg<std::string> rawlog(
            "", "rawlog", std::string("input rawlog") + rfir::common::kRawlogClassesHelp,
            true, "", "FILE", cmd);
        TCLAP::ValueArg<std::string> outDir("", "out-dir", "output folder", true, "",
                                            "DIR", cmd);
        TCLAP::ValueArg<std::string> method("", "method",
                                            "pf | ps | fastslam | odometry "
                                            "(default: the INI's [slam] method, or pf)",
                                            false, "", "NAME", cmd);
        TCLAP::ValueArg<std::string> config(
            "", "config",
            "INI file, or a stock one by name (e.g. slam_ps); default: the method's "
            "stock INI",
            false, "", "INI", cmd);
        TCLAP::MultiArg<std::string> sets(
            "", "set",
            "override an INI key, e.g. --set slam.robot_particles=200 (repeatable)",
            false, "SECTION.KEY=VALUE", cmd);
        rfir::common::CNumberArg<uint64_t> seed("", "seed", "random seed (default 1)",
                                                false, 1, "N", cmd);
        TCLAP::ValueArg<std::string> start(
            "", "start", "start pose X Y PHI, or \"X Y PHI\" (default: the rawlog's)",
            false, "", "X Y PHI", cmd);
        TCLAP::ValueArg<std::string> gtPath("", "gt-path", "ground-truth path (TUM)",
                                            false, "", "TUM", cmd);
        TCLAP::ValueArg<std::string> gtMap("", "gt-map", "ground-truth map", false, "",
                                           "FILE", cmd);
        TCLAP::SwitchArg smooth(
            "", "smooth",
            "also smooth the run offline (odometry + RFID reads, from the filter's "
            "output; beyond the seeds): path_smoothed.tum, map_smoothed.txt, "
            "path_map_smoothed.png, errors_smoothed.json",
            cmd, false);
        TCLAP::SwitchArg quiet("q", "quiet", rfir::common::kQuietHelp, cmd, false);
        std::vector<std::string> args(argv, argv + argc);
        try {
            rfir::common::foldOptionValues(args, "--start", 3);
        } catch (const std::invalid_argument& e) {
            std::cerr << "rfir-slam: error: " << e.what() << "\n";
            return rfir::common::kUsageExitCode;
        }
        if (const auto code = rfir::common::parseCommandLine(cmd, args)) return *code;

        rfir::slamapp::TAppArgs a;
        try {  // a bad --start is a usage error, reported before any work
            if (start.isSet()) a.start = parseStart(start.getValue());
        } catch (const std::invalid_argument& e) {
            std::cerr << "rfir-slam: error: " << e.what() << "\n";
            return rfir::common::kUsageExitCode;
        }
        a.rawlog = rawlog.getValue();
        a.outDir = outDir.getValue();
        if (method.isSet()) a.method = method.getValue();
        if (config.isSet()) a.config = rfir::common::resolveConfigFile(config.getValue());
        if (gtPath.isSet()) a.gtPath = gtPath.getValue();
        if (gtMap.isSet()) a.gtMap = gtMap.getValue();
        a.seed = seed.getValue();
        a.smooth = smooth.getValue();
        a.sets = sets.getValue();
        a.quiet = quiet.getValue();
        return rfir::slamapp::runSlamApp(a);
    } catch (const std::exception& e) {
        std::cerr << "rfir-slam: error: " << e.what() << "\n";
        return 1;
    }
}
