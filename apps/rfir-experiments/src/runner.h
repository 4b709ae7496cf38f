/* rfir-experiments: one simulated data set, every method of a row on it, the
 * errors against the ground truth (rfir_eval). */
#pragma once

#include "experiment.h"

#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/eval/report.h>
#include <rfir/sim/simulator.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rfir::experiments {
/** Kidnap rows: the "after" error is measured from this many seconds after
 * the robot is put down. */
constexpr double kRecoveryWindow = 15.0;

/** One method on one data set. */
struct TRunResult {
    std::string method;  //!< TMethodSpec::label
    size_t point = 0, run = 0;
    uint64_t seed = 0;
    rfir::eval::TEvalResult eval;  //!< robot and map errors (m, rad)
    double msPerStep = 0, maxStepMs = 0, totalSeconds = 0;
    size_t steps = 0, resets = 0;
    /** Kidnap rows: mean distance error before the kidnapping and from
     * kRecoveryWindow seconds after the robot is put down to the end (m). */
    double beforeKidnap = kNaN, afterKidnap = kNaN;
    /** Recovered (the error after is at most twice the error before): seconds
     * from the put-down to the first error below twice the error before;
     * NaN: not recovered. */
    double recoveryTime = kNaN;
    // For figures (kept for the first seed only).
    rfir::common::TPath2D estPath;
    rfir::common::TMapFile estMap;
};

/** A simulated data set plus what the figures need. */
struct TDataSet {
    rfir::sim::TSimConfig cfg;
    rfir::sim::TSimOutput sim;
    /** Ground-truth landmarks the robot passed over (or had in view). */
    std::optional<std::set<std::string>> passed;
};

/** Loads the sub-run's sim INI from `configDir` with the overrides of the
 * sub-run and the point, and simulates it with `seed`. */
TDataSet simulateDataSet(const std::string& configDir, const TSubRun& run,
                         const TPoint& point, uint64_t seed);

/** Runs `m` (stock INI from `configDir` + the point's and method's edits). */
TRunResult runMethod(const std::string& configDir, const TDataSet& data,
                     const TMethodSpec& m, const TPoint& point, uint64_t seed,
                     bool keepOutputs);

}  // namespace rfir::experiments
