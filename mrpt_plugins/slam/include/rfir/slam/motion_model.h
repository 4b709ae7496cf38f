/* rfir: the robot motion model, SPEC section 3 (eq. 7 in 003, eq. 3.6 in the
 * thesis): the pose moves by the odometry increment plus Gaussian noise. We use
 * MRPT's Gaussian odometry model (CActionRobotMovement2D, model "gaussian"),
 * whose noise grows with the distance and the turn of each increment. */
#pragma once

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose2D.h>

#include <rfir/models/odometry_noise.h>
#include <rfir/slam/CParticlePose2D.h>

#include <cmath>
#include <optional>
#include <vector>

namespace rfir::slam {
/** The odometry's heading drift as part of each robot particle's state
 * (TMotionOptions::heading_drift_std, heading_drift_walk). */
struct THeadingDrift {
    double std = 0;   //!< prior std, rad/m
    double walk = 0;  //!< random walk, rad/m per sqrt(m)
    bool on() const { return std > 0 || walk > 0; }
};

/** INI section [motion]: the std of an increment (d: its length, |phi|: its
 * turn) is a1*d + a2*|phi| + min_std_xy in x and y, a3*d + a4*|phi| +
 * min_std_phi in heading (MRPT's Gaussian model). */
struct TMotionOptions : public mrpt::config::CLoadableOptions {
    double a1 = 0.05;            //!< m of xy std per m travelled
    double a2 = 0.001;           //!< m of xy std per rad turned
    double a3 = 0.02;            //!< rad of heading std per m travelled
    double a4 = 0.02;            //!< rad of heading std per rad turned
    double min_std_xy = 0.001;   //!< m
    double min_std_phi = 0.002;  //!< rad
    /** The robot's physical limits (0: none). An odometry increment faster
     * than these over its interval is a slip, not believed (slipLimited). */
    double max_speed = 0;      //!< m/s
    double max_turn_rate = 0;  //!< rad/s
    /** Reader polls between odometry records placed at the odometry
     * interpolated to their time (interpolatedInputs). */
    bool interpolate_polls = false;
    /** s: an odometry record stamped t is the pose at t - odometry_latency
     * (only with interpolate_polls). */
    double odometry_latency = 0;
    /** The odometry's systematic heading drift (a wheel-diameter mismatch)
     * as part of each robot particle's state: rad per metre travelled, drawn
     * per particle from N(0, heading_drift_std^2) at the start and walking
     * by N(0, heading_drift_walk^2 d) over d metres. 0, 0: no drift state. */
    double heading_drift_std = 0;   //!< rad/m
    double heading_drift_walk = 0;  //!< rad/m per sqrt(m)
    THeadingDrift headingDrift() const { return {heading_drift_std, heading_drift_walk}; }

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                            const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c,
                          const std::string& s) const override;
    /** Rejects negative values, naming the key. */
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions toMRPT() const;
    /** The models layer's noise parameters (the same a1..a4 model). */
    rfir::models::OdometryNoiseParams noise() const {
        return {a1, a2, a3, a4, min_std_xy, min_std_phi};
    }
};

/** The Gaussian movement for an odometry increment, with our noise model. */
mrpt::obs::CActionRobotMovement2D makeMovement(const mrpt::poses::CPose2D& increment,
                                               const TMotionOptions& opts);

/** Share k in (0, 1] of an odometry increment over dt seconds the robot's
 * limits allow: 1 within max_speed and max_turn_rate (or dt <= 0, or no limit
 * set), else the largest k with k |(dx, dy)| <= max_speed dt and k |dphi| <=
 * max_turn_rate dt. */
double slipLimited(const mrpt::poses::CPose2D& u, double dt, const TMotionOptions& o);

/** One odometry interval a step's increment takes part of (TSlamInput). */
struct TOdometryPart {
    mrpt::poses::CPose2D interval;  //!< the interval's whole increment
    double dt = 0;                  //!< its duration (s)
    double fraction = 1;            //!< the share of it in this step
};

/** The movement a filter draws for a step's increment `u` (dt: the seconds
 * it covers, 0 unknown). Without `parts`, MRPT's model of u, except that a
 * slip (slipLimited < 1) is not believed: the increment becomes `rate` * dt
 * (limited) if a rate is given, else k u, and its noise std grows by
 * k |(dx, dy)| and k |dphi| (the robot's limit over dt). With `parts`
 * (interpolated polls) the step draws, of each interval, `fraction` of its
 * noise variance: the draws over an interval then add up to one draw of that
 * interval's noise, however many polls fall in it (docs/slam.md). */
mrpt::obs::CActionRobotMovement2D makeMovement(
    const mrpt::poses::CPose2D& u, double dt, const std::vector<TOdometryPart>& parts,
    const TMotionOptions& opts, const mrpt::poses::CPose2D* rate = nullptr);

/** makeMovement with a memory, one per filter run: a slip's believed
 * increment is the last believed increment's rate (per second, `rate` above)
 * over dt, within the limits: the robot keeps its speed while its wheels
 * slip; the noise is the slip rule's. Without a rate yet, the increment
 * scaled to the limits. */
class CSlipAwareMotion {
  public:
    void reset() { m_rate.reset(); }
    mrpt::obs::CActionRobotMovement2D movement(const mrpt::poses::CPose2D& u, double dt,
                                               const std::vector<TOdometryPart>& parts,
                                               const TMotionOptions& opts);

  private:
    std::optional<mrpt::poses::CPose2D> m_rate;  //!< m/s, m/s, rad/s (robot frame)
};

/** The Gaussian pose change of the action's odometry increment, with the
 * noise options the action was built with (its MRPT Gaussian-model options);
 * nullopt without a movement. One Cholesky per step. */
std::optional<rfir::models::OdometryGaussian> motionOf(
    const mrpt::obs::CActionCollection* action);

/** The prediction every robot filter shares: each particle's pose moves by
 * its own draw of the odometry Gaussian (SPEC section 3), a plain loop of three
 * normal draws and one composition per particle, the heading's cos and sin
 * carried (CParticlePose2D::move). `poseOf(p)` returns a reference to
 * particle p's CParticlePose2D; `moves` counts the calls of a particle set,
 * which recomputes the carried values every kExactHeadingEvery moves. */
constexpr unsigned kExactHeadingEvery = 64;
template <class Particles, class PoseOf>
void drawMotion(const rfir::models::OdometryGaussian& g, Particles& particles,
                PoseOf&& poseOf, rfir::models::TRandom& rng, unsigned& moves) {
    const bool exact = ++moves % kExactHeadingEvery == 0;
    for (auto& p : particles) poseOf(p).move(g, rng, exact);
}

/** The same with a heading drift in each particle (TMotionOptions::
 * heading_drift_std): `driftOf(p, i)` returns a reference to particle p's
 * (index i) drift in rad/m, which first walks by N(0, walk^2 d) and then
 * turns the particle by drift * d on top of its draw (d: the increment's
 * length). Kept apart from CParticlePose2D: a robot particle and its weight
 * fill one 64-byte cache line, and a drift member cost 4-6 % per step. */
template <class Particles, class PoseOf, class DriftOf>
void drawMotion(const rfir::models::OdometryGaussian& g, Particles& particles,
                PoseOf&& poseOf, DriftOf&& driftOf, double walk,
                rfir::models::TRandom& rng, unsigned& moves) {
    const bool exact = ++moves % kExactHeadingEvery == 0;
    const double d = g.distance(), sd = walk * std::sqrt(d);
    size_t i = 0;
    for (auto& p : particles) {
        double& b = driftOf(p, i++);
        if (sd > 0) b += rng.drawGaussian1D(0, sd);
        poseOf(p).move(g, rng, exact, b * d);
    }
}

/** Each particle's heading drift drawn from N(0, std^2) (0 if std is 0):
 * the prior of TMotionOptions::heading_drift_std. */
template <class Particles, class DriftOf>
void drawDriftPrior(Particles& particles, DriftOf&& driftOf, double std,
                    rfir::models::TRandom& rng) {
    size_t i = 0;
    for (auto& p : particles) driftOf(p, i++) = std > 0 ? rng.drawGaussian1D(0, std) : 0;
}

}  // namespace rfir::slam
