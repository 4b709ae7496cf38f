/* rfir-slam: the steps of one run, separate from the command line. */
#pragma once

#include <rfir/slam/slam_config.h>

#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>
#include <vector>

namespace rfir::slamapp {
struct TAppArgs {
    std::string rawlog, outDir;
    std::optional<std::string> method, config, gtPath, gtMap;
    uint64_t seed = 1;
    std::optional<mrpt::poses::CPose2D> start;
    /** Also refine the run offline (rfir::slam::smoothRun): *_smoothed outputs. */
    bool smooth = false;
    /** --set "section.key=value" edits over the INI, in order. */
    std::vector<std::string> sets;
    /** --quiet: no progress or summary on stderr. */
    bool quiet = false;
    /** --help-keys: list the configuration's INI keys on stdout, run nothing. */
    bool helpKeys = false;
};

/** Runs SLAM and writes every output (with helpKeys, only lists the keys);
 * returns the process exit code.
 * Throws std::exception with a message for the user on bad input. */
int runSlamApp(const TAppArgs& a);

}  // namespace rfir::slamapp
