/* rfir-slam: offline SLAM (PF-SLAM, PS-SLAM, FastSLAM 1.0) on a rawlog. */
#include "slam_app.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <cstring>
#include <iostream>
#include <sstream>
#include <vector>

namespace {
/** TCLAP takes one token per value: fold "--start X Y PHI" into one token
 * (negative numbers would otherwise look like flags). */
std::vector<std::string> foldStart(int argc, char** argv) {
    std::vector<std::string> args(argv, argv + argc);
    for (size_t i = 1; i < args.size(); i++)
        if (args[i] == "--start") {
            if (i + 3 >= args.size())
                throw std::invalid_argument("--start needs three numbers: X Y PHI");
            args[i + 1] = args[i + 1] + " " + args[i + 2] + " " + args[i + 3];
            args.erase(args.begin() + i + 2, args.begin() + i + 4);
        }
    return args;
}

mrpt::poses::CPose2D parseStart(const std::string& s) {
    std::istringstream is(s);
    double x, y, phi;
    std::string extra;
    if (!(is >> x >> y >> phi) || (is >> extra))
        throw std::invalid_argument("--start needs three numbers: X Y PHI (got '" + s +
                                    "')");
    return {x, y, phi};
}
}  // namespace

int main(int argc, char** argv) {
    try {
        TCLAP::CmdLine cmd(
            "rfir-slam: PF-SLAM, PS-SLAM or FastSLAM on a project rawlog. Writes "
            "path.tum, map.txt, settings.ini, stats.json, path_map.png, scene.3Dscene "
            "(and errors.json, error_time.png with ground truth) into --out-dir.",
            ' ', "0.1");
        TCLAP::ValueArg<std::string> rawlog("", "rawlog", "input rawlog", true, "",
                                            "FILE", cmd);
        TCLAP::ValueArg<std::string> outDir("", "out-dir", "output folder", true, "",
                                            "DIR", cmd);
        TCLAP::ValueArg<std::string> method("", "method",
                                            "pf | ps | fastslam | odometry "
                                            "(default: the INI's [slam] method, or pf)",
                                            false, "", "NAME", cmd);
        TCLAP::ValueArg<std::string> config("", "config",
                                            "INI file (default: the method's stock INI)",
                                            false, "", "INI", cmd);
        TCLAP::ValueArg<uint64_t> seed("", "seed", "random seed", false, 1, "N", cmd);
        TCLAP::ValueArg<std::string> start("", "start",
                                           "start pose X Y PHI (default: the rawlog's)",
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
        const auto args = foldStart(argc, argv);
        std::vector<const char*> av;
        for (const auto& s : args) av.push_back(s.c_str());
        // MRPT's TCLAP returns false after printing --help or --version.
        if (!cmd.parse(int(av.size()), av.data())) return 0;

        rfir::slamapp::TAppArgs a;
        a.rawlog = rawlog.getValue();
        a.outDir = outDir.getValue();
        if (method.isSet()) a.method = method.getValue();
        if (config.isSet()) a.config = config.getValue();
        if (gtPath.isSet()) a.gtPath = gtPath.getValue();
        if (gtMap.isSet()) a.gtMap = gtMap.getValue();
        a.seed = seed.getValue();
        a.smooth = smooth.getValue();
        if (start.isSet()) a.start = parseStart(start.getValue());
        return rfir::slamapp::runSlamApp(a);
    } catch (const TCLAP::ArgException& e) {
        std::cerr << "rfir-slam: " << e.error() << " (" << e.argId() << ")\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "rfir-slam: error: " << e.what() << "\n";
        return 1;
    }
}
