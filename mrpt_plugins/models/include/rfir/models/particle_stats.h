/* rfir: weighted statistics of a 2D particle set. */
#pragma once

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPoint2D.h>

#include <functional>
#include <vector>

namespace rfir::models {
/** Log-likelihood of an observation given that the tag is at a point. */
using PointLogLikelihood = std::function<double(const mrpt::math::TPoint2D&)>;

/** Mean and 2x2 covariance of a point estimate. */
struct PointEstimate {
    mrpt::math::TPoint2D mean{0, 0};
    mrpt::math::CMatrixDouble22 cov = mrpt::math::CMatrixDouble22::Zero();
};

/** Weighted mean and covariance (weights from log-weights; empty logWeights =
 * uniform). Covariance normalised by the sum of weights (biased estimator). */
PointEstimate weightedEstimate(const std::vector<mrpt::math::TPoint2D>& pts,
                               const std::vector<double>& logWeights);

}  // namespace rfir::models
