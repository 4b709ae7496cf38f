#include <rfir/models/ini_reader.h>
#include <rfir/slam/motion_model.h>

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cmath>

namespace rfir::slam {
void TMotionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s) {
    using R = rfir::ini::TRange;
    const rfir::ini::CIniSection sec(
        c, s,
        {"a1", "a2", "a3", "a4", "min_std_xy", "min_std_phi", "max_speed",
         "max_turn_rate", "interpolate_polls", "odometry_latency", "heading_drift_std",
         "heading_drift_walk"});
    // Upper bounds: 1 m of xy std per metre (or radian) and pi of heading std
    // are already a robot that has no odometry at all.
    a1 = sec.getDouble("a1", a1, R::closed(0, 1));
    a2 = sec.getDouble("a2", a2, R::closed(0, 1));
    a3 = sec.getDouble("a3", a3, R::closed(0, M_PI));
    a4 = sec.getDouble("a4", a4, R::closed(0, M_PI));
    min_std_xy = sec.getDouble("min_std_xy", min_std_xy, R::closed(0, 1));
    min_std_phi = sec.getDouble("min_std_phi", min_std_phi, R::closed(0, M_PI));
    // 100 m/s and 100 rad/s are beyond any indoor robot: larger means "off".
    max_speed = sec.getDouble("max_speed", max_speed, R::closed(0, 100));
    max_turn_rate = sec.getDouble("max_turn_rate", max_turn_rate, R::closed(0, 100));
    interpolate_polls = sec.getBool("interpolate_polls", interpolate_polls);
    // A latency of seconds would be a clock error, not a lag.
    odometry_latency =
        sec.getDouble("odometry_latency", odometry_latency, R::closed(-1, 1));
    // 0.1 rad per metre is a robot whose odometry has no heading at all.
    heading_drift_std =
        sec.getDouble("heading_drift_std", heading_drift_std, R::closed(0, 0.1));
    heading_drift_walk =
        sec.getDouble("heading_drift_walk", heading_drift_walk, R::closed(0, 0.1));
    if (odometry_latency != 0 && !interpolate_polls)
        sec.fail("odometry_latency",
                 "a latency moves the polls between odometry records: it needs "
                 "interpolate_polls = true");
}

void TMotionOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                      const std::string& s) const {
    c.write(s, "a1", a1, -1, -1, "xy std [m] per metre travelled");
    c.write(s, "a2", a2, -1, -1, "xy std [m] per radian turned");
    c.write(s, "a3", a3, -1, -1, "heading std [rad] per metre travelled");
    c.write(s, "a4", a4, -1, -1, "heading std [rad] per radian turned");
    c.write(s, "min_std_xy", min_std_xy, -1, -1, "xy std floor per step [m]");
    c.write(s, "min_std_phi", min_std_phi, -1, -1, "heading std floor per step [rad]");
    c.write(s, "max_speed", max_speed, -1, -1, "slip above this speed [m/s], 0 off");
    c.write(s, "max_turn_rate", max_turn_rate, -1, -1,
            "slip above this turn rate [rad/s], 0 off");
    c.write(s, "interpolate_polls", interpolate_polls, -1, -1,
            "polls at the odometry interpolated to their time");
    c.write(s, "odometry_latency", odometry_latency, -1, -1,
            "odometry record stamped t = pose at t - latency [s]");
    c.write(s, "heading_drift_std", heading_drift_std, -1, -1,
            "prior std of the per-particle heading drift [rad/m], 0 off");
    c.write(s, "heading_drift_walk", heading_drift_walk, -1, -1,
            "its random walk [rad/m per sqrt(m)], 0 off");
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

double slipLimited(const mrpt::poses::CPose2D& u, double dt, const TMotionOptions& o) {
    if (!(dt > 0)) return 1;
    double k = 1;
    const double d = std::hypot(u.x(), u.y()), a = std::abs(u.phi());
    if (o.max_speed > 0 && d > o.max_speed * dt) k = std::min(k, o.max_speed * dt / d);
    if (o.max_turn_rate > 0 && a > o.max_turn_rate * dt)
        k = std::min(k, o.max_turn_rate * dt / a);
    return k;
}

namespace {
/** Stds of an increment under the slip rule of makeMovement. */
void slipStds(const mrpt::poses::CPose2D& u, double k, const TMotionOptions& o,
              double& sxy, double& sphi) {
    o.noise().stds(k * u.x(), k * u.y(), k * u.phi(), sxy, sphi);
    if (k < 1) {
        sxy += k * std::hypot(u.x(), u.y());
        sphi += k * std::abs(u.phi());
    }
}
}  // namespace

mrpt::obs::CActionRobotMovement2D makeMovement(const mrpt::poses::CPose2D& u, double dt,
                                               const std::vector<TOdometryPart>& parts,
                                               const TMotionOptions& o,
                                               const mrpt::poses::CPose2D* rate) {
    // A slip's believed increment: the last believed rate over dt (limited),
    // else the increment scaled to the limits.
    const auto believed = [&](double k) -> mrpt::poses::CPose2D {
        if (!rate || !(dt > 0)) return {k * u.x(), k * u.y(), k * u.phi()};
        const mrpt::poses::CPose2D r(rate->x() * dt, rate->y() * dt, rate->phi() * dt);
        const double kr = slipLimited(r, dt, o);
        return {kr * r.x(), kr * r.y(), kr * r.phi()};
    };
    if (parts.empty()) {
        const double k = slipLimited(u, dt, o);
        if (k >= 1) return makeMovement(u, o);  // the plain model, bit for bit
        TMotionOptions w = o;
        double sxy, sphi;
        slipStds(u, k, o, sxy, sphi);
        w.a1 = w.a2 = w.a3 = w.a4 = 0;
        w.min_std_xy = sxy;
        w.min_std_phi = sphi;
        return makeMovement(believed(k), w);
    }
    // Variances add over independent draws: `fraction` of each interval's.
    double vxy = 0, vphi = 0, kmin = 1;
    for (const auto& p : parts) {
        const double k = slipLimited(p.interval, p.dt, o);
        double sxy, sphi;
        slipStds(p.interval, k, o, sxy, sphi);
        vxy += p.fraction * sxy * sxy;
        vphi += p.fraction * sphi * sphi;
        kmin = std::min(kmin, k);
    }
    TMotionOptions w = o;
    w.a1 = w.a2 = w.a3 = w.a4 = 0;
    w.min_std_xy = std::sqrt(vxy);
    w.min_std_phi = std::sqrt(vphi);
    return makeMovement(kmin < 1 ? believed(kmin) : u, w);
}

mrpt::obs::CActionRobotMovement2D CSlipAwareMotion::movement(
    const mrpt::poses::CPose2D& u, double dt, const std::vector<TOdometryPart>& parts,
    const TMotionOptions& o) {
    const bool slip = parts.empty()
                          ? slipLimited(u, dt, o) < 1
                          : std::any_of(parts.begin(), parts.end(), [&](auto& p) {
                                return slipLimited(p.interval, p.dt, o) < 1;
                            });
    auto mv = makeMovement(u, dt, parts, o, m_rate ? &*m_rate : nullptr);
    if (!slip && dt > 0)
        m_rate = mrpt::poses::CPose2D(u.x() / dt, u.y() / dt, u.phi() / dt);
    return mv;
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

}  // namespace rfir::slam
