#include <rfir/slam/ini_check.h>
#include <rfir/slam/motion_model.h>

#include <mrpt/config/CConfigFileBase.h>

namespace rfir::slam {
void TMotionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s) {
    a1 = c.read_double(s, "a1", a1);
    a2 = c.read_double(s, "a2", a2);
    a3 = c.read_double(s, "a3", a3);
    a4 = c.read_double(s, "a4", a4);
    min_std_xy = c.read_double(s, "min_std_xy", min_std_xy);
    min_std_phi = c.read_double(s, "min_std_phi", min_std_phi);
    validate(s);
}

void TMotionOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                      const std::string& s) const {
    c.write(s, "a1", a1, -1, -1, "xy std [m] per metre travelled");
    c.write(s, "a2", a2, -1, -1, "xy std [m] per radian turned");
    c.write(s, "a3", a3, -1, -1, "heading std [rad] per metre travelled");
    c.write(s, "a4", a4, -1, -1, "heading std [rad] per radian turned");
    c.write(s, "min_std_xy", min_std_xy, -1, -1, "xy std floor per step [m]");
    c.write(s, "min_std_phi", min_std_phi, -1, -1, "heading std floor per step [rad]");
}

void TMotionOptions::validate(const std::string& s) const {
    const std::pair<const char*, double> vals[] = {{"a1", a1},
                                                   {"a2", a2},
                                                   {"a3", a3},
                                                   {"a4", a4},
                                                   {"min_std_xy", min_std_xy},
                                                   {"min_std_phi", min_std_phi}};
    for (const auto& [k, v] : vals)
        if (!(v >= 0)) badSetting(s, k, "must be >= 0");
}

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions TMotionOptions::toMRPT() const {
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m;
    m.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
    m.gaussianModel = {a1, a2, a3, a4, min_std_xy, min_std_phi};
    return m;
}

mrpt::obs::CActionRobotMovement2D makeMovement(const mrpt::poses::CPose2D& increment,
                                               const TMotionOptions& opts) {
    mrpt::obs::CActionRobotMovement2D act;
    act.computeFromOdometry(increment, opts.toMRPT());
    return act;
}

std::optional<mrpt::poses::CPose2D> odometryIncrement(
    const mrpt::obs::CActionCollection* acts) {
    if (!acts) return std::nullopt;
    auto mv = acts->getBestMovementEstimation();
    if (!mv) return std::nullopt;
    return mv->rawOdometryIncrementReading;
}

}  // namespace rfir::slam
