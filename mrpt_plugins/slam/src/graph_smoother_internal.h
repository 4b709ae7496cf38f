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
/** Marginal stds of the tags of `run.map` at `run`'s path and map, from the
 * Gaussian linearisation (reads as uniform squares' stds). */
void gaussianMarginalStds(const std::vector<TSlamInput>& inputs,
                          const mrpt::poses::CPose2D& start,
                          const TGraphSmootherParams& params, TSlamRun& run);
}  // namespace rfir::slam::detail
