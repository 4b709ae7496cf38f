/* rfir-localize: one pass over a rawlog. */
#pragma once

#include <rfir/localize/localize_config.h>

#include <rfir/common/trajectory_io.h>

#include <functional>
#include <optional>
#include <string>

namespace rfir::localize {
struct TRunResult {
    rfir::common::TPath2D path;  //!< estimate per instant (from the first unique ID)
    /** Dead reckoning from the start pose (header `start`, else the ground
     * truth's first pose, else the origin), one pose per instant. */
    rfir::common::TPath2D odometry;
    std::string odometryStart;  //!< "header", "ground truth" or "origin"
    size_t steps = 0, irObservations = 0, readings = 0, used = 0, unknownIds = 0,
           decoded = 0, resetEvents = 0, resetParticles = 0;
    std::optional<double> firstUniqueTime;
    size_t startHistoryReadings = 0;  //!< readings before it that weighed the start
    size_t gated = 0;  //!< readings inconsistent with the motion prior (not used)
    /** A lost track: when declared (and redrawn from unique ID `id`), and
     * when the particles were confident again (nullopt: not by the end). */
    struct TLost {
        double t = 0;
        std::string id;
        std::optional<double> settled;
    };
    std::vector<TLost> lost;
    /** Per emitter of the map, at the end of the run (empty: odometry only). */
    std::vector<rfir::ir::TEmitterHealth> emitterHealth;
    double seconds = 0;  //!< wall-clock time of the filter
};

/** rfir-localize's checks before a run: the INI with cfg.overrides (an edit
 * it refuses is a CUsageError naming it), `emitters` (non-empty) over its
 * emitter_file, the rawlog a file, cfg.gtPath (else <stem>.gt.tum beside the
 * rawlog when there) read. Returns the ground truth's first pose, if any. */
std::optional<mrpt::poses::CPose2D> prepareRun(TConfig& cfg, const std::string& emitters);
/** What a live view may read after each instant (rfir::view draws it);
 * everything const: the run's outputs do not depend on a view. */
struct TStepView {
    size_t step = 0;  //!< this instant's index
    double t = 0;
    const TConfig& cfg;
    const rfir::ir::CIRLocalizer* localizer;  //!< null: --odometry-only
    const rfir::ir::TLocalizerStep& info;
    const rfir::obs::CObservationIRSignals* ir;    //!< this instant's, may be null
    const mrpt::poses::CPose2D& odometry;          //!< dead reckoning
    const rfir::common::TPath2D* truth = nullptr;  //!< ground-truth path, if any
};
using TStepObserver = std::function<void(const TStepView&)>;

/** Runs the filter (or only dead reckoning) over cfg.rawlogPath. `gtStart`:
 * the ground truth's first pose, if any. Progress on stderr unless quiet.
 * `onStep` (--gui), if set, after each instant. */
TRunResult runLocalization(const TConfig& cfg,
                           const std::optional<mrpt::poses::CPose2D>& gtStart,
                           const TStepObserver& onStep = {});

}  // namespace rfir::localize
