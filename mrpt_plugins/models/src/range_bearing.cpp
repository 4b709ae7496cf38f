/* rfir: range-and-bearing sensor model (004 section 4.2). */
#include <rfir/models/range_bearing.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace rfir::models {
void predictRangeBearing(const mrpt::math::TPose2D& sensor,
                         const mrpt::math::TPoint2D& landmark, double& range,
                         double& bearing) {
    const double dx = landmark.x - sensor.x, dy = landmark.y - sensor.y;
    range = std::hypot(dx, dy);
    bearing = mrpt::math::wrapToPi(std::atan2(dy, dx) - sensor.phi);
}

double rangeBearingLogLikelihood(const mrpt::math::TPose2D& sensor,
                                 const mrpt::math::TPoint2D& landmark, double range,
                                 double bearing, const RangeBearingParams& p) {
    double r, b;
    predictRangeBearing(sensor, landmark, r, b);
    const double er = (range - r) / p.sigmaRange;
    const double eb = mrpt::math::wrapToPi(bearing - b) / p.sigmaBearing;
    return -0.5 * (er * er + eb * eb);
}

mrpt::math::TPoint2D rangeBearingToPoint(const mrpt::math::TPose2D& sensor, double range,
                                         double bearing) {
    const double a = sensor.phi + bearing;
    return {sensor.x + range * std::cos(a), sensor.y + range * std::sin(a)};
}

std::vector<mrpt::math::TPoint2D> sampleRangeBearingInverse(
    const mrpt::math::TPose2D& sensor, double range, double bearing,
    const RangeBearingParams& p, size_t n, rfir::models::TRandom& rng) {
    std::vector<mrpt::math::TPoint2D> out(n);
    for (auto& pt : out) {
        const double r =
            std::max(0.0, range + p.sigmaRange * rng.drawGaussian1D_normalized());
        const double b = bearing + p.sigmaBearing * rng.drawGaussian1D_normalized();
        pt = rangeBearingToPoint(sensor, r, b);
    }
    return out;
}

}  // namespace rfir::models
