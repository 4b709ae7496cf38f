/* rfir-sim: wheel odometry noise. Variances proportional to the distance
 * travelled and to the rotation (a random walk per metre, so the drift does not
 * depend on the step length), plus per-run scale and heading biases: the
 * systematic errors of real wheels (radius, wheel base). The seeds give no
 * odometry model; their motion model (SPEC 3) is V dt + eps dt. */
#include "odometry.h"

#include <cmath>

namespace rfir::sim::detail {
COdometrySimulator::COdometrySimulator(const TOdometryNoise& n,
                                       rfir::sim::TSimRandom& rng)
    : n_(n), rng_(rng) {
    s_ = rng_.drawGaussian1D(0, n_.scaleSigma);
    r_ = rng_.drawGaussian1D(0, n_.rotScaleSigma);
    h_ = rng_.drawGaussian1D(0, n_.headingDriftSigma);
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
}  // namespace rfir::sim::detail
