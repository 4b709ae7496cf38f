/* rfir: offline smoothing of a SLAM run (beyond the seeds). A filter's estimate
 * at time t uses only the data up to t, so the first pass over new ground
 * keeps its odometry drift, and independent per-tag filters keep it in the map
 * (docs/slam.md, "Known gaps"). Offline, the whole log is known: this smoother
 * refines the filter's path and map jointly, by Gauss-Newton on the factor
 * graph of odometry increments (MRPT's Gaussian odometry model, the [motion]
 * section) and RFID reads (the seeds' step likelihood approximated by a
 * Gaussian with the std of a uniform square: half-size / sqrt(3)). Started
 * from the filter's output, it moves the past poses and the tags with the
 * robot-tag correlations the per-tag filters drop. */
#pragma once

#include <rfir/slam/motion_model.h>
#include <rfir/slam/slam_engine.h>

#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace rfir::slam {
struct TGraphSmootherParams {
    TMotionOptions motion;         //!< odometry noise (the SLAM INI's [motion])
    double readStdFactor = 0.577;  //!< read std = factor x half-size (uniform: 1/sqrt 3)
    int maxIterations = 30;
    double tolerance = 1e-9;  //!< stop when the largest update is below it (m, rad)
};

struct TGraphSmootherResult {
    /** The filter's run with the smoothed poses (same times) and the smoothed
     * tags (marginal stds); its timings are the filter's. */
    TSlamRun run;
    double initialCost = 0, finalCost = 0;  //!< sum of squared whitened residuals
    int iterations = 0;
    size_t reads = 0;  //!< RFID read factors used
};

/** Smooths a filter's run (one pose per input, and its map) over the inputs;
 * `start` is held fixed (the known start pose).
 * Tags read but absent from `initialMap` start from their first read. Range-
 * bearing detections are not used (RFID only). Throws std::invalid_argument
 * on size mismatches. */
TGraphSmootherResult smoothRun(const std::vector<TSlamInput>& inputs,
                               const mrpt::poses::CPose2D& start,
                               const TSlamRun& filtered,
                               const TGraphSmootherParams& params);

}  // namespace rfir::slam
