/* rfir-experiments: one simulated data set, every method of a row on it, the
 * errors against the ground truth (rfir_eval). */
#pragma once

#include <rfir/experiments/experiment.h>

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
    /** Its results.json entry (one JSON line, timings aside), as its run
     * folder's run.json holds it (loadRuns). */
    std::string entry;
};

/** A simulated data set plus what the figures need. */
struct TDataSet {
    rfir::sim::TSimConfig cfg;
    rfir::sim::TSimOutput sim;
    /** Ground-truth landmarks the robot passed over (or had in view). */
    std::optional<std::set<std::string>> passed;
};

/** Where the INIs are, and the user's --set edits: they go last, after a
 * row's own edits, into every simulation INI and every SLAM INI. */
struct TSetup {
    std::string configDir;
    std::vector<std::string> simEdits, slamEdits;
};

/** The --set edits split between the simulation INIs and the SLAM INIs (by
 * section; "sim:" or "slam:" for [kidnap], in both). Throws
 * rfir::common::CUsageError naming a malformed or unknown edit. */
TSetup makeSetup(const std::string& configDir, const std::vector<std::string>& sets);

/** Loads every INI the rows read, with their edits and the user's, so that an
 * unknown key or a bad value fails before any run. Throws
 * rfir::common::CUsageError "--set EDIT: [section] key: why" when a user's
 * edit is to blame, else the INI's own error "FILE: [section] key: why". */
void checkConfigs(const TSetup& setup, const std::vector<TRow>& rows);

/** Loads the sub-run's sim INI with the overrides of the sub-run, the point
 * and the user, and simulates it with `seed`. */
TDataSet simulateDataSet(const TSetup& setup, const TSubRun& run, const TPoint& point,
                         uint64_t seed);

/** Runs `m` (stock INI + the point's, the method's and the user's edits). */
TRunResult runMethod(const TSetup& setup, const TDataSet& data, const TMethodSpec& m,
                     const TPoint& point, uint64_t seed, bool keepOutputs);

}  // namespace rfir::experiments
