/* rfir: the [smoother] section of a SLAM INI: how `rfir-slam --smooth` refines
 * a run offline (graph_smoother.h, docs/slam.md "Offline smoothing"). */
#pragma once

#include <rfir/models/miss_model.h>

#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace rfir::slam {
struct TGraphSmootherOptions : public mrpt::config::CLoadableOptions {
    /** ceres: the robust smoother (step-shaped reads, negative information,
     * kidnap cuts, odometry bias); lm: a simpler hand-written Gauss-Newton
     * with Gaussian reads, kept for the side-by-side measurement. */
    std::string solver = "ceres";
    /** Robust losses (none, huber, cauchy) and their scales in whitened
     * residual units (standard deviations). */
    std::string odometry_loss = "cauchy";
    double odometry_loss_scale = 3.0;
    std::string read_loss = "cauchy";
    double read_loss_scale = 3.0;
    /** Outside the reader's square the read's residual grows with this std,
     * x the half-size, from the square's edge (inside it is zero). */
    double read_tail_std_factor = 0.3;
    /** Readers with a smaller half-size (m) keep the Gaussian read and give
     * no negative information: measured worse on 60 mm readers (docs/slam.md). */
    double flat_min_half_size = 0.1;
    /** Share of the half-size over which the flat-inside shape is smoothed. */
    double read_edge_smoothing = rfir::models::kMissEdgeSmoothing;
    /** Negative information: a polled reader that did not read a tag says it
     * was not in its square with this probability (0: no such factors). */
    double detection_probability = 0.95;
    /** Estimate translation scale and heading drift per metre of the odometry,
     * with these prior stds (0: not estimated). The scale is off by default:
     * it took up the read models' own biases (-5 % with Gaussian reads at
     * 60 mm, +1 to +10 % with flat ones at 300 mm; docs/slam.md). */
    double scale_prior_std = 0;
    double drift_prior_std = 0.02;  //!< rad/m
    /** The scale and the drift are estimated only if at least this many
     * distinct tags are read again after `closure_min_travel` m of odometry
     * path since their previous read: an error per metre shows only in such
     * closures. Without them (a short run across a big floor) the path and
     * its tags bend together at no cost, and freed the drift ran off
     * (docs/slam.md, "Offline smoothing"). 0: always estimated. */
    int bias_min_closures = 20;
    double closure_min_travel = 5.0;  //!< m
    /** Heading std per metre of the odometry factors (a3 of MRPT's model;
     * negative: [motion] a3). The filters' a3 may be wider, to keep a
     * drifting odometry inside the particle cloud between revisits; the
     * smoother estimates the drift itself (drift_prior_std). */
    double odometry_a3 = -1;
    /** s before a filter's kidnap reset searched for the kidnapping. */
    double kidnap_window = 8.0;
    int max_iterations = 50;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                            const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c,
                          const std::string& s) const override;
};
}  // namespace rfir::slam
