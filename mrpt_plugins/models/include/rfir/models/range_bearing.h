/* rfir: range-and-bearing sensor model (SPEC section 7; 004 section 4.2):
 * independent zero-mean Gaussian noise on range and bearing. */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <rfir/models/random.h>

#include <vector>

namespace rfir::models {
struct RangeBearingParams {
    double sigmaRange = 0.010;                           //!< m (seed: 10 mm)
    double sigmaBearing = 3.0 * 3.14159265358979 / 180;  //!< rad (seed: 3 deg)
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
 * world. */
mrpt::math::TPoint2D rangeBearingToPoint(const mrpt::math::TPose2D& sensor, double range,
                                         double bearing);

/** Inverse model with noise: n samples of the landmark position, range and
 * bearing drawn from the sensor's Gaussians (used to initialise a landmark). */
std::vector<mrpt::math::TPoint2D> sampleRangeBearingInverse(
    const mrpt::math::TPose2D& sensor, double range, double bearing,
    const RangeBearingParams& p, size_t n, rfir::models::TRandom& rng);

}  // namespace rfir::models
