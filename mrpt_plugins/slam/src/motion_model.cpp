#include <rfir/models/ini_reader.h>
#include <rfir/slam/motion_model.h>

#include <mrpt/config/CConfigFileBase.h>

#include <cmath>

namespace rfir::slam {
void TMotionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s) {
    using R = rfir::ini::TRange;
    const rfir::ini::CIniSection sec(
        c, s, {"a1", "a2", "a3", "a4", "min_std_xy", "min_std_phi"});
    // Upper bounds: 1 m of xy std per metre (or radian) and pi of heading std
    // are already a robot that has no odometry at all.
    a1 = sec.getDouble("a1", a1, R::closed(0, 1));
    a2 = sec.getDouble("a2", a2, R::closed(0, 1));
    a3 = sec.getDouble("a3", a3, R::closed(0, M_PI));
    a4 = sec.getDouble("a4", a4, R::closed(0, M_PI));
    min_std_xy = sec.getDouble("min_std_xy", min_std_xy, R::closed(0, 1));
    min_std_phi = sec.getDouble("min_std_phi", min_std_phi, R::closed(0, M_PI));
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

std::optional<rfir::models::OdometryGaussian> motionOf(
    const mrpt::obs::CActionCollection* action) {
    const auto mv = action ? action->getBestMovementEstimation() : nullptr;
    if (!mv) return std::nullopt;
    const auto& u = mv->rawOdometryIncrementReading;
    const auto& m = mv->motionModelConfiguration.gaussianModel;
    const rfir::models::OdometryNoiseParams p{m.a1, m.a2,       m.a3,
                                              m.a4, m.minStdXY, m.minStdPHI};
    return rfir::models::OdometryGaussian::fromOdometry(u.x(), u.y(), u.phi(), p);
}

std::optional<mrpt::poses::CPose2D> odometryIncrement(
    const mrpt::obs::CActionCollection* acts) {
    if (!acts) return std::nullopt;
    auto mv = acts->getBestMovementEstimation();
    if (!mv) return std::nullopt;
    return mv->rawOdometryIncrementReading;
}

}  // namespace rfir::slam
