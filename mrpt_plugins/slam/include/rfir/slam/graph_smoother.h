/* rfir: offline smoothing of a SLAM run (beyond the papers). A filter's estimate
 * at time t uses only the data up to t, so the first pass over new ground
 * keeps its odometry drift, and independent per-tag filters keep it in the map
 * (docs/slam.md, "Known gaps"). Offline, the whole log is known: this smoother
 * refines the filter's path and map jointly on the factor graph of odometry
 * increments (the [motion] noise model, robust loss, with the odometry's
 * translation scale and heading drift per metre as variables) and RFID reads
 * (flat inside the reader's square, robust loss), plus the negative
 * information of polled readers that read nothing, solved with Ceres. The
 * odometry factor across a kidnapping the filter reported is cut. The former
 * Gauss-Newton with Gaussian reads stays as [smoother] solver = lm. */
#pragma once

#include <rfir/slam/graph_smoother_options.h>
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
    double tolerance = 1e-9;        //!< stop when the largest update is below it (m, rad)
    TGraphSmootherOptions options;  //!< the INI's [smoother]
};

struct TSlamConfig;
/** The smoother's parameters of a SLAM configuration ([motion], [smoother]). */
TGraphSmootherParams smootherParams(const TSlamConfig& cfg);

struct TGraphSmootherResult {
    /** The filter's run with the smoothed poses (same times) and the smoothed
     * tags (marginal stds); its timings are the filter's. */
    TSlamRun run;
    double initialCost = 0, finalCost = 0;  //!< sum of squared whitened residuals
    int iterations = 0;
    size_t reads = 0;      //!< RFID read factors used
    size_t negatives = 0;  //!< negative-information factors (polls without the tag)
    double seconds = 0;    //!< wall time of the solve
    /** Estimated odometry systematic error: true translation = (1 + scale) x
     * odometry's, true heading change = odometry's + drift x distance. */
    double odometryScale = 0, headingDriftPerMetre = 0;
    /** Tags read again after closure_min_travel; the bias is estimated only
     * if there are at least bias_min_closures of them (biasEstimated). */
    size_t closures = 0;
    bool biasEstimated = false;
    /** A bias prior was set but too few closures: the bias was held (ceres). */
    bool biasHeld = false;
    /** Times (s) of the odometry increments cut as kidnappings. */
    std::vector<double> cutTimes;
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
