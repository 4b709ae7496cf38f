/* rfir: the two solvers of smoothRun (graph_smoother.h), apart. */
#pragma once

#include <rfir/slam/graph_smoother.h>

namespace rfir::slam::detail {
/** [smoother] solver = lm: Gauss-Newton with Gaussian reads, no robust loss. */
TGraphSmootherResult smoothRunLM(const std::vector<TSlamInput>& inputs,
                                 const mrpt::poses::CPose2D& start,
                                 const TSlamRun& filtered,
                                 const TGraphSmootherParams& params);
/** [smoother] solver = ceres: the robust smoother. */
TGraphSmootherResult smoothRunCeres(const std::vector<TSlamInput>& inputs,
                                    const mrpt::poses::CPose2D& start,
                                    const TSlamRun& filtered,
                                    const TGraphSmootherParams& params);
/** 1 / std (m, rad) of step `s`'s odometry factor under the noise model `n`:
 * of its increment, or, for an interpolated poll ([motion]
 * interpolate_polls), the sum of its parts' shares of their intervals'
 * variances, as the filters draw it (the factors over one interval then add
 * up to that interval's noise, however many polls fall in it). */
void stepOdometryInformationSqrt(const TSlamInput& s,
                                 const rfir::models::OdometryNoiseParams& n, double& wxy,
                                 double& wphi);
/** Marginal stds of the tags of `run.map` at `run`'s path and map, from the
 * Gaussian linearisation (reads as uniform squares' stds). */
void gaussianMarginalStds(const std::vector<TSlamInput>& inputs,
                          const mrpt::poses::CPose2D& start,
                          const TGraphSmootherParams& params, TSlamRun& run);
}  // namespace rfir::slam::detail
