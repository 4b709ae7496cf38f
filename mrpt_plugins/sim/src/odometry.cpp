/* rfir-sim: wheel odometry noise. Variances proportional to the distance
 * travelled and to the rotation (a random walk per metre, so the drift does not
 * depend on the step length), plus per-run scale and heading biases: the
 * systematic errors of real wheels (radius, wheel base). The papers give no
 * odometry model; their motion model (the PF-SLAM paper's eq. 7) is
 * V dt + eps dt. */
#include "odometry.h"
#include "world.h"

#include <algorithm>

#include <cmath>

namespace rfir::sim::detail {
COdometrySimulator::COdometrySimulator(const TOdometryNoise& n,
                                       rfir::sim::TSimRandom& rng)
    : n_(n), rng_(rng) {
    // The fixed errors (0 unless configured) shift the drawn biases; the
    // draws themselves stay the same.
    s_ = rng_.drawGaussian1D(0, n_.scaleSigma) + n_.scaleError;
    r_ = rng_.drawGaussian1D(0, n_.rotScaleSigma) + n_.rotScaleError;
    h_ = rng_.drawGaussian1D(0, n_.headingDriftSigma) + n_.headingDriftError;
}

mrpt::poses::CPose2D slipIncrement(const mrpt::poses::CPose2D& inc, double size,
                                   double heading) {
    // The wheels spin on: the odometry counts extra travel along the motion
    // (forward when standing still).
    const double d = std::hypot(inc.x(), inc.y());
    const double ux = d > 1e-9 ? inc.x() / d : 1.0, uy = d > 1e-9 ? inc.y() / d : 0.0;
    return {size * ux, size * uy, heading};
}

mrpt::poses::CPose2D COdometrySimulator::noisyIncrement(const mrpt::poses::CPose2D& inc) {
    const double dx = inc.x(), dy = inc.y(), dphi = inc.phi();
    const double d = std::hypot(dx, dy), a = std::abs(dphi);
    if (d == 0 && a == 0) return inc;
    const double sxy = n_.kXY * std::sqrt(d);
    const double sphi =
        std::sqrt(n_.kPhiRot * n_.kPhiRot * a + n_.kPhiXY * n_.kPhiXY * d);
    const double nx = rng_.drawGaussian1D(0, sxy), ny = rng_.drawGaussian1D(0, sxy);
    const double np = rng_.drawGaussian1D(0, sphi);
    return {(1 + s_) * dx + nx, (1 + s_) * dy + ny, (1 + r_) * dphi + h_ * d + np};
}

CSlipSchedule::CSlipSchedule(const TOdometryNoise& n, double end,
                             rfir::sim::TSimRandom& rng)
    : times_(n.slipTimes), size_(n.slipSize), heading_(n.slipHeading) {
    for (int i = 0; i < n.slipCount; i++) times_.push_back(rng.drawUniform(0.0, end));
    std::sort(times_.begin(), times_.end());
}

mrpt::poses::CPose2D CSlipSchedule::apply(double e, double t,
                                          const mrpt::poses::CPose2D& trueInc,
                                          mrpt::poses::CPose2D inc,
                                          std::vector<std::string>& log) {
    for (; next_ < times_.size() && times_[next_] <= e; next_++) {
        const auto sl = slipIncrement(trueInc, size_, heading_);
        inc = mrpt::poses::CPose2D(inc.x() + sl.x(), inc.y() + sl.y(),
                                   inc.phi() + sl.phi());
        log.push_back("slip " + faultNumber(t) + " " + faultNumber(sl.x()) + " " +
                      faultNumber(sl.y()) + " " + faultNumber(sl.phi()));
    }
    return inc;
}
}  // namespace rfir::sim::detail
