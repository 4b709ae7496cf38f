/* rfir: range-and-bearing sensor model (SPEC section 7; 004 section 4.2),
 * written once: h(sensor pose, landmark) = (|d|, atan2(d) - phi_s) with d the
 * landmark minus the sensor position, its Jacobians and its inverse;
 * independent zero-mean Gaussian noise on range and bearing. */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <rfir/models/random.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rfir::models {
/** A (range, bearing) prediction. The bearing is NOT wrapped (it is in
 * (-3 pi, 3 pi)): callers wrap the error z - h, which wrapping h first would
 * only round once more. */
struct TRangeBearing {
    double range, bearing;
};

/** dh/d(sensor x, y, phi) and dh/d(landmark x, y), row-major (row 0: range). */
struct TRangeBearingJacobians {
    double sensor[2][3];
    double landmark[2][2];
};

/** h(sensor pose, landmark). The Jacobians keep |d|^2 >= 1e-12 (a landmark on
 * the sensor has no bearing). Inline: it runs once per particle. */
inline TRangeBearing rangeBearingModel(const mrpt::math::TPose2D& sensor,
                                       const mrpt::math::TPoint2D& landmark,
                                       TRangeBearingJacobians* J = nullptr) {
    const double dx = landmark.x - sensor.x, dy = landmark.y - sensor.y;
    if (J) {
        const double q = std::max(dx * dx + dy * dy, 1e-12), r = std::sqrt(q);
        J->landmark[0][0] = dx / r, J->landmark[0][1] = dy / r;
        J->landmark[1][0] = -dy / q, J->landmark[1][1] = dx / q;
        J->sensor[0][0] = -dx / r, J->sensor[0][1] = -dy / r, J->sensor[0][2] = 0;
        J->sensor[1][0] = dy / q, J->sensor[1][1] = -dx / q, J->sensor[1][2] = -1;
    }
    return {std::hypot(dx, dy), std::atan2(dy, dx) - sensor.phi};
}

/** The sensor mounted at (x, y, yaw) on a robot at `robot`, in the world. */
mrpt::math::TPose2D sensorPoseInWorld(const mrpt::math::TPose2D& robot,
                                      const mrpt::math::TPose2D& mount);

/** h(robot pose, sensor mount, landmark), with dh/d(robot x, y, phi) in
 * J->sensor (the chain rule through sensorPoseInWorld). */
TRangeBearing rangeBearingModel(const mrpt::math::TPose2D& robot,
                                const mrpt::math::TPose2D& mount,
                                const mrpt::math::TPoint2D& landmark,
                                TRangeBearingJacobians* J);
struct RangeBearingParams {
    double sigmaRange = 0.010;  //!< m (the PS-SLAM paper: 10 mm)
    double sigmaBearing =
        3.0 * 3.14159265358979 / 180;  //!< rad (the PS-SLAM paper: 3 deg)
};

/** Expected (range, bearing) of a landmark seen from a sensor pose (world). */
void predictRangeBearing(const mrpt::math::TPose2D& sensor,
                         const mrpt::math::TPoint2D& landmark, double& range,
                         double& bearing);

/** Unnormalised Gaussian log-likelihood of a (range, bearing) reading of a
 * landmark at `landmark`; the bearing error is wrapped to (-pi, pi]. */
double rangeBearingLogLikelihood(const mrpt::math::TPose2D& sensor,
                                 const mrpt::math::TPoint2D& landmark, double range,
                                 double bearing, const RangeBearingParams& p);

/** Inverse model: the point a noise-free (range, bearing) reading puts in the
 * world; G, if given, receives d(point)/d(range, bearing), row-major. */
mrpt::math::TPoint2D rangeBearingToPoint(const mrpt::math::TPose2D& sensor, double range,
                                         double bearing, double (*G)[2] = nullptr);

/** Inverse model with noise: n samples of the landmark position, range and
 * bearing drawn from the sensor's Gaussians (used to initialise a landmark). */
std::vector<mrpt::math::TPoint2D> sampleRangeBearingInverse(
    const mrpt::math::TPose2D& sensor, double range, double bearing,
    const RangeBearingParams& p, size_t n, rfir::models::TRandom& rng);

}  // namespace rfir::models
