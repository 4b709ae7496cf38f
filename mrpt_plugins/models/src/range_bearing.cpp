/* rfir: range-and-bearing sensor model (004 section 4.2). */
#include <rfir/models/range_bearing.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace rfir::models {
void predictRangeBearing(const mrpt::math::TPose2D& sensor,
                         const mrpt::math::TPoint2D& landmark, double& range,
                         double& bearing) {
    const TRangeBearing h = rangeBearingModel(sensor, landmark);
    range = h.range;
    bearing = mrpt::math::wrapToPi(h.bearing);
}

mrpt::math::TPose2D sensorPoseInWorld(const mrpt::math::TPose2D& robot,
                                      const mrpt::math::TPose2D& mount) {
    const double c = std::cos(robot.phi), s = std::sin(robot.phi);
    return {robot.x + c * mount.x - s * mount.y, robot.y + s * mount.x + c * mount.y,
            mrpt::math::wrapToPi(robot.phi + mount.phi)};
}

TRangeBearing rangeBearingModel(const mrpt::math::TPose2D& robot,
                                const mrpt::math::TPose2D& mount,
                                const mrpt::math::TPoint2D& landmark,
                                TRangeBearingJacobians* J) {
    const TRangeBearing h =
        rangeBearingModel(sensorPoseInWorld(robot, mount), landmark, J);
    if (J) {
        // d(sensor)/d(robot phi) = (-(R m)_y, (R m)_x, 1); x and y pass through.
        const double c = std::cos(robot.phi), s = std::sin(robot.phi);
        const double mx = c * mount.x - s * mount.y, my = s * mount.x + c * mount.y;
        for (auto& row : J->sensor) row[2] += -row[0] * my + row[1] * mx;
    }
    return h;
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
                                         double bearing, double (*G)[2]) {
    const double a = sensor.phi + bearing, c = std::cos(a), s = std::sin(a);
    if (G) G[0][0] = c, G[0][1] = -range * s, G[1][0] = s, G[1][1] = range * c;
    return {sensor.x + range * c, sensor.y + range * s};
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
