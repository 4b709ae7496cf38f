#include <rfir/models/ini_reader.h>
#include <rfir/slam/graph_smoother_options.h>

#include <cmath>
#include <vector>

namespace rfir::slam {
namespace {
const std::vector<std::string> kLosses = {"none", "huber", "cauchy"};
size_t indexOf(const std::vector<std::string>& v, const std::string& s) {
    for (size_t i = 0; i < v.size(); i++)
        if (v[i] == s) return i;
    return 0;
}
}  // namespace

void TGraphSmootherOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                               const std::string& s) {
    using R = rfir::ini::TRange;
    const rfir::ini::CIniSection sec(
        c, s,
        {"solver", "odometry_loss", "odometry_loss_scale", "read_loss", "read_loss_scale",
         "read_tail_std_factor", "flat_min_half_size", "read_edge_smoothing",
         "detection_probability", "scale_prior_std", "drift_prior_std", "odometry_a3",
         "kidnap_window", "max_iterations", "bias_min_closures", "closure_min_travel"});
    const std::vector<std::string> solvers = {"ceres", "lm"};
    solver = solvers[sec.getEnum("solver", solvers, indexOf(solvers, solver))];
    odometry_loss =
        kLosses[sec.getEnum("odometry_loss", kLosses, indexOf(kLosses, odometry_loss))];
    odometry_loss_scale =
        sec.getDouble("odometry_loss_scale", odometry_loss_scale, R::aboveZero(1e6));
    read_loss = kLosses[sec.getEnum("read_loss", kLosses, indexOf(kLosses, read_loss))];
    read_loss_scale =
        sec.getDouble("read_loss_scale", read_loss_scale, R::aboveZero(1e6));
    read_tail_std_factor =
        sec.getDouble("read_tail_std_factor", read_tail_std_factor, R::aboveZero(100));
    flat_min_half_size =
        sec.getDouble("flat_min_half_size", flat_min_half_size, R::closed(0, 1e3));
    read_edge_smoothing =
        sec.getDouble("read_edge_smoothing", read_edge_smoothing, R::aboveZero(1));
    // 1 would make a missed read impossible: an infinite cost.
    detection_probability = sec.getDouble("detection_probability", detection_probability,
                                          R::closed(0, 0.999));
    scale_prior_std = sec.getDouble("scale_prior_std", scale_prior_std, R::closed(0, 1));
    drift_prior_std = sec.getDouble("drift_prior_std", drift_prior_std, R::closed(0, 10));
    odometry_a3 = sec.getDouble("odometry_a3", odometry_a3, R::closed(-1, M_PI));
    kidnap_window = sec.getDouble("kidnap_window", kidnap_window, R::closed(0, 1e6));
    max_iterations = int(sec.getInt("max_iterations", max_iterations, 1, 100000));
    bias_min_closures =
        int(sec.getInt("bias_min_closures", bias_min_closures, 0, 1000000000));
    closure_min_travel =
        sec.getDouble("closure_min_travel", closure_min_travel, R::closed(0, 1e6));
}

void TGraphSmootherOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                             const std::string& s) const {
    c.write(s, "solver", solver, -1, -1, "ceres (robust) or lm (former Gauss-Newton)");
    c.write(s, "odometry_loss", odometry_loss, -1, -1, "none, huber or cauchy");
    c.write(s, "odometry_loss_scale", odometry_loss_scale, -1, -1, "in stds");
    c.write(s, "read_loss", read_loss, -1, -1, "none, huber or cauchy");
    c.write(s, "read_loss_scale", read_loss_scale, -1, -1, "in stds");
    c.write(s, "read_tail_std_factor", read_tail_std_factor, -1, -1,
            "read residual std outside the square, x half-size");
    c.write(s, "flat_min_half_size", flat_min_half_size, -1, -1,
            "readers smaller than this [m] keep the Gaussian read model");
    c.write(s, "read_edge_smoothing", read_edge_smoothing, -1, -1,
            "width of the square's smoothed edge, x half-size");
    c.write(s, "detection_probability", detection_probability, -1, -1,
            "of a tag in a polled reader's square (0: no negative information)");
    c.write(s, "scale_prior_std", scale_prior_std, -1, -1,
            "odometry translation scale error prior std (0: not estimated)");
    c.write(s, "drift_prior_std", drift_prior_std, -1, -1,
            "odometry heading drift prior std [rad/m] (0: not estimated)");
    c.write(s, "odometry_a3", odometry_a3, -1, -1,
            "odometry heading std [rad] per metre (negative: [motion] a3)");
    c.write(s, "kidnap_window", kidnap_window, -1, -1,
            "s before a kidnap reset searched for the kidnapping");
    c.write(s, "max_iterations", max_iterations, -1, -1, "solver iterations");
    c.write(
        s, "bias_min_closures", bias_min_closures, -1, -1,
        "tags read again after closure_min_travel before scale and drift are estimated");
    c.write(s, "closure_min_travel", closure_min_travel, -1, -1,
            "odometry path [m] between two reads of a tag that makes a closure");
}
}  // namespace rfir::slam
