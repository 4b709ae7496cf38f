/* rfir: the meanings of rfir-slam's INI keys (config_ini/slam_*.ini,
 * docs/slam.md). */
#include "ini_key_docs_tables.h"

namespace rfir::common::detail {
namespace {
const std::vector<TKeyRow> kSlam = {
    // [slam]
    {"slam", "method", "-",
     "the estimator: pf (PF-SLAM), ps (PS-SLAM, fixed-lag smoothers per tag), fastslam "
     "(FastSLAM 1.0) or odometry (dead reckoning); --method overrides it"},
    {"slam", "robot_particles", "particles",
     "robot particles M; more follow a drifting odometry better at a cost linear in M"},
    {"slam", "resampling", "-",
     "resampling scheme of the robot particles (systematic has the least variance)"},
    {"slam", "resample_ess", "share of M",
     "resample the robot particles when the normalised effective sample size falls "
     "below this"},
    {"slam", "start_std_xy", "m",
     "initial position spread of the robot particles about the start pose; raise it "
     "when the start pose is only roughly known"},
    {"slam", "start_std_phi", "rad",
     "initial heading spread of the robot particles about the start pose"},
    {"slam", "tag_update_pose", "-",
     "with robot_update revisit or revisit_all, the robot mean a tag is updated from: "
     "posterior (after this step's weighing) or predicted (before it)"},
    {"slam", "map_correction", "-",
     "tags mapped from an uncertain robot pose follow the robot's later corrections "
     "(a loop closure) through their cross-covariance with it; false keeps a first "
     "lap's drift in the map, as the papers' algorithm"},
    {"slam", "map_correction_min_std", "m",
     "a tag whose share of the robot's position error is below this stops following "
     "the robot's corrections"},
    {"slam", "map_correction_max_tags", "tags",
     "at most this many tags follow the robot's corrections (the oldest leave first), "
     "so that a correction's cost stays bounded on large maps"},
    {"slam", "read_confirm_window", "s",
     "a read weighs the robot only if the same tag was also read this long before it, "
     "so that one ghost read cannot pull the cloud (0: every read)"},
    // [motion]
    {"motion", "a1", "m/m",
     "odometry position noise std per metre travelled (MRPT's Gaussian model); raise "
     "it for slipping wheels"},
    {"motion", "a2", "m/rad", "odometry position noise std per radian turned"},
    {"motion", "a3", "rad/m",
     "odometry heading noise std per metre travelled; wide enough that a drifting "
     "odometry stays inside the cloud between revisits"},
    {"motion", "a4", "rad/rad", "odometry heading noise std per radian turned"},
    {"motion", "min_std_xy", "m", "position noise std added to every odometry increment"},
    {"motion", "min_std_phi", "rad",
     "heading noise std added to every odometry increment"},
    {"motion", "max_speed", "m/s",
     "the robot's top speed: a faster odometry increment is a wheel slip, believed only "
     "up to the limit with wider noise (0: no limit)"},
    {"motion", "max_turn_rate", "rad/s",
     "the robot's top turn rate, a slip limit as max_speed (0: no limit)"},
    {"motion", "interpolate_polls", "-",
     "place reader polls between odometry records at the odometry interpolated to their "
     "time; for logs whose polls and odometry are out of step"},
    {"motion", "odometry_latency", "s",
     "an odometry record stamped t is the pose at t minus this (needs "
     "interpolate_polls)"},
    {"motion", "heading_drift_std", "rad/m",
     "prior std of a per-particle odometry heading drift (a wheel-diameter mismatch) "
     "that the filter learns at revisits (0: none); for long runs with drifting "
     "odometry"},
    {"motion", "heading_drift_walk", "rad/m per sqrt(m)",
     "random walk of each particle's heading drift per square root of a metre travelled"},
    // [kidnap]
    {"kidnap", "enabled", "-",
     "detect a kidnapped robot (carried elsewhere) and redraw particles where the tags "
     "read say it is (sensor resetting)"},
    {"kidnap", "collapse_loglik", "log-likelihood per read",
     "a step disagrees with the map when its best particle's mean log-likelihood per "
     "read is below this"},
    {"kidnap", "collapse_steps", "steps",
     "disagreeing steps in a row (no agreeing one between) that trigger a reset"},
    {"kidnap", "min_tags", "tags",
     "distinct known tags or landmarks the disagreeing run must have read"},
    {"kidnap", "max_gap", "s",
     "the disagreeing steps of one run are at most this far apart; also the reads a "
     "loop-closure check must explain"},
    {"kidnap", "evidence_drop", "log-likelihood per read",
     "a reset also needs the fast average of the step evidence this far below the slow "
     "one"},
    {"kidnap", "persist_tags", "tags",
     "also reset once this many distinct known tags have disagreed in the run with no "
     "agreeing read (0: off)"},
    {"kidnap", "fast_rate", "per step", "rate of the fast average of the step evidence"},
    {"kidnap", "slow_rate", "per step", "rate of the slow average of the step evidence"},
    {"kidnap", "inject_fraction", "share of M",
     "share of the robot particles redrawn where the step's known tags were read at a "
     "reset"},
    {"kidnap", "keep_heading_share", "share",
     "share of the redrawn particles that keep the filter's heading (with heading_std)"},
    {"kidnap", "heading_std", "rad",
     "heading spread of the redrawn particles that keep the filter's heading"},
    {"kidnap", "pair_heading_share", "share",
     "share of the other redrawn particles that take the heading turning two tags of "
     "the disagreeing run onto the map (the rest: uniform heading)"},
    {"kidnap", "pair_min_distance", "m",
     "minimum distance between the two tags that give a redrawn heading"},
    {"kidnap", "map_new_tags_in_run", "-",
     "while a disagreeing run is open, tags never mapped are still mapped (known tags "
     "are not updated either way)"},
    {"kidnap", "loop_closure_smoothing", "-",
     "at a trigger, first smooth the run: if the smoothed path explains the reads it was "
     "a loop closure after drift, not a kidnapping, and nothing is reset (RFID only)"},
    {"kidnap", "rb_loglik_scale", "-",
     "range-and-bearing log-likelihoods enter the kidnap evidence times this, to match "
     "the RFID step model's scale"},
    // [fastslam]
    {"fastslam", "rfid_std_factor", "x half-size",
     "FastSLAM's RFID tag std about the reader centre, as a fraction of the reader's "
     "half side"},
    {"fastslam", "rb_std_range", "m",
     "FastSLAM's range noise std when the observation gives none"},
    {"fastslam", "rb_std_bearing", "rad",
     "FastSLAM's bearing noise std when the observation gives none"},
    // [smoother]
    {"smoother", "solver", "-",
     "offline smoother (--smooth, loop closures): ceres (robust: step reads, negative "
     "information, kidnap cuts, odometry bias) or lm (Gaussian reads, for comparison)"},
    {"smoother", "odometry_loss", "-",
     "robust loss of the odometry factors: none, huber or cauchy (against slips)"},
    {"smoother", "odometry_loss_scale", "std",
     "whitened odometry residual where the robust loss starts"},
    {"smoother", "read_loss", "-",
     "robust loss of the read factors: none, huber or cauchy (against ghost reads)"},
    {"smoother", "read_loss_scale", "std",
     "whitened read residual where the robust loss starts"},
    {"smoother", "read_tail_std_factor", "x half-size",
     "std of a read's residual outside the reader's square (zero inside it)"},
    {"smoother", "flat_min_half_size", "m",
     "readers with a smaller half-size keep the Gaussian read model and give no negative "
     "information"},
    {"smoother", "read_edge_smoothing", "x half-size",
     "width over which the flat-inside read model's edge is smoothed"},
    {"smoother", "detection_probability", "probability",
     "probability that a polled reader reads a tag in its square: a poll without it "
     "says the tag is not there (0: no negative information)"},
    {"smoother", "scale_prior_std", "share",
     "prior std of the odometry's translation scale error, estimated by the smoother "
     "(0: not estimated)"},
    {"smoother", "drift_prior_std", "rad/m",
     "prior std of the odometry's heading drift, estimated by the smoother (0: not "
     "estimated)"},
    {"smoother", "odometry_a3", "rad/m",
     "heading noise std per metre of the smoother's odometry factors (negative: [motion] "
     "a3); narrower than the filter's since the smoother estimates the drift"},
    {"smoother", "kidnap_window", "s",
     "time before a filter's kidnap reset searched for the kidnapping, which the "
     "smoother cuts"},
    {"smoother", "max_iterations", "iterations", "solver iterations at most"},
    {"smoother", "bias_min_closures", "tags",
     "the scale and drift are estimated only if at least this many tags are read again "
     "after closure_min_travel (0: always)"},
    {"smoother", "closure_min_travel", "m",
     "odometry path between two reads of a tag that makes them a closure"},
    // [tagmap]
    {"tagmap", "estimator", "-",
     "per-tag estimator, set by [slam] method (pf, fastslam: particle_filter; ps: "
     "fixed_lag_smoother); a key here must agree with it"},
    {"tagmap", "seed", "-",
     "random seed of the tag map's draws; in rfir-slam --seed sets it and a key here is "
     "refused"},
    {"tagmap", "num_particles", "particles",
     "particles per tag L; more cost memory and time per read"},
    {"tagmap", "lag", "updates",
     "fixed-lag smoother only: states kept per particle (the papers: 20-30)"},
    {"tagmap", "smoother_step_sigma", "m",
     "fixed-lag smoother only: random step of a tag particle per update"},
    {"tagmap", "roughening_sigma", "m",
     "particle filter only: jitter added to tag particles after resampling (0: none)"},
    {"tagmap", "ess_threshold", "share of L",
     "resample a tag's particles when their normalised effective sample size falls "
     "below this (1: at every read)"},
    {"tagmap", "resampling", "-", "resampling scheme of the tag particles"},
    {"tagmap", "tag_robot_pose", "-",
     "robot pose that places the reader for a tag's particles: mean, samples_init, "
     "samples or samples_visit (docs/slam.md)"},
    {"tagmap", "spread_commit_travel", "m",
     "samples_visit: robot path since a tag's first read before a new visit makes its "
     "spread permanent"},
    {"tagmap", "reseat_contradicted", "-",
     "a tag that more reads in a row contradict than agreed with it (a ghost first "
     "read, a moved tag) is placed again at the read"},
    {"tagmap", "contradict_margin", "m",
     "a read also contradicts a tag whose estimate lies more than this outside the "
     "read's reader square (negative: only the outlier floor's test)"},
    {"tagmap", "hold_outvoted", "-",
     "a contradicting read of a tag that the agreeing reads still out-vote does not "
     "move it"},
    {"tagmap", "negative_information", "probability",
     "a large polled reader that did not read a tag near its square weighs the tag's "
     "particles by 1 - this x P(read) (0: off)"},
    {"tagmap", "negative_window", "observations",
     "negative information applies to tags read in the last this many observations"},
    {"tagmap", "negative_min_half_size", "m",
     "only readers with half-sizes of at least this give negative information"},
    // [tagmap_likelihood]
    {"tagmap_likelihood", "detection_model", "-",
     "RFID read likelihood: step (flat inside the reader square, Gaussian tail; the "
     "papers) or gaussian (about the reader centre)"},
    {"tagmap_likelihood", "beta", "-",
     "step model: gain of the Gaussian tail, about 1 at the square's edge"},
    {"tagmap_likelihood", "gaussian_sigma_scale", "x half-size",
     "gaussian model: std per axis as a multiple of the reader's half-size"},
    {"tagmap_likelihood", "rb_sigma_range", "m",
     "range noise std of range-and-bearing reads"},
    {"tagmap_likelihood", "rb_sigma_bearing_deg", "deg",
     "bearing noise std of range-and-bearing reads"},
    {"tagmap_likelihood", "rb_use_landmark_cov", "-",
     "add the landmark estimate's covariance to the range-and-bearing noise when "
     "weighing the robot"},
    {"tagmap_likelihood", "robot_update", "-",
     "which reads weigh the robot: literal (every read, against the just-updated tag), "
     "revisit (the first read of a new visit) or revisit_all (every read of a new "
     "visit, against the estimate from its start)"},
    {"tagmap_likelihood", "revisit_min_gap", "observations",
     "observations without a tag's read before its next read starts a new visit"},
    {"tagmap_likelihood", "revisit_min_travel", "m",
     "robot path since a tag's last read that a new visit also needs, so that one pass "
     "under several readers is one visit"},
    {"tagmap_likelihood", "robot_likelihood", "-",
     "what a robot particle is weighed against: tag_mean or tag_particles (an uncertain "
     "tag pulls the robot less)"},
    {"tagmap_likelihood", "robot_likelihood_k", "particles",
     "tag_particles: evenly spaced tag particles averaged per weighing"},
    {"tagmap_likelihood", "robot_negative_information", "probability",
     "large readers near the one that read a tag but did not read it weigh the robot "
     "particle by 1 - this x P(read) (0: off)"},
    {"tagmap_likelihood", "outlier_weight", "share",
     "share of the reads that come from anywhere (ghost reads) in the read likelihood "
     "(0: off); for logs with ghost reads"},
    {"tagmap_likelihood", "outlier_log_floor", "log-likelihood",
     "log-likelihood of an outlier read against the model's best (0), about log(reader "
     "area / room area)"},
};
}  // namespace

const std::vector<TKeyRow>& slamKeyRows() {
    return kSlam;
}
}  // namespace rfir::common::detail
