/* rfir-slam: the steps of one run, separate from the command line. */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/slam/slam_config.h>
#include <rfir/slam/slam_engine.h>

#include <rfir/common/trajectory_io.h>

#include <mrpt/poses/CPose2D.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rfir::slamapp {
/** What a live view may read after each step of the run (rfir::view draws
 * it); everything const: the run's outputs do not depend on a view. */
struct TStepView {
    size_t step = 0, steps = 0;  //!< this step's index, and how many there are
    const rfir::slam::TSlamInput& input;
    const rfir::slam::CSlamEngine& engine;
    const rfir::common::TPath2D* truth = nullptr;  //!< ground-truth path, if any
    std::vector<std::string> events;  //!< relocations and loop closures of this step
    std::string method;               //!< e.g. "PF-SLAM"
};
using TStepObserver = std::function<void(const TStepView&)>;

struct TAppArgs {
    /** outDir empty: no files written (runSlam only). */
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
    /** Called after each step (--gui); empty: none. */
    TStepObserver onStep;
};

/** One run in memory: what path.tum, map.txt, stats.json and errors.json
 * hold (the files are written from these same values). */
struct TSlamAppResult {
    rfir::common::TPath2D path;
    rfir::common::TMapFile map;
    std::string statsJson;   //!< stats.json's text ("files" empty without outDir)
    std::string errorsJson;  //!< errors.json's text; empty without ground truth
    rfir::common::TPath2D smoothedPath;  //!< --smooth only
    rfir::common::TMapFile smoothedMap;
    std::string smoothedErrorsJson;
    std::string errorTable;  //!< the table rfir-slam prints (empty: no truth)
};

/** Runs SLAM, writes every output into a.outDir unless it is empty, and
 * returns the run. Throws std::exception with a message for the user on bad
 * input. */
TSlamAppResult runSlam(const TAppArgs& a);

/** Runs SLAM and writes every output (with helpKeys, only lists the keys);
 * returns the process exit code.
 * Throws std::exception with a message for the user on bad input. */
int runSlamApp(const TAppArgs& a);

}  // namespace rfir::slamapp
