/* rfir-bench: the floor. The least any of the methods can do per update with
 * M robot particles: draw each particle's motion noise (the same MRPT Gaussian
 * odometry sampler the engines use) and evaluate one detection likelihood
 * (SPEC section 2) per particle. Every figure is read as a multiple of it. */
#include "bench.h"

#include <rfir/models/detection_likelihood.h>
#include <rfir/slam/motion_model.h>

#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
#include <chrono>
#include <numeric>

namespace rfir::bench {
TFloorResult runFloor(const TBenchOptions& o, size_t M) {
    mrpt::random::getRandomGenerator().randomize(uint32_t(o.seed));
    rfir::slam::TMotionOptions motion;
    const auto mv = rfir::slam::makeMovement(mrpt::poses::CPose2D(0.005, 0, 0), motion);
    const rfir::models::DetectionLikelihood det;
    const rfir::models::ReaderArea reader{0.15, 0, 0.03, 0.03};
    const mrpt::math::TPoint2D tag(0.15, 0.0);
    std::vector<mrpt::poses::CPose2D> poses(M);
    std::vector<double> logW(M, 0.0);
    std::vector<double> us, wall;
    const size_t reps = o.warmupUpdates + o.timedUpdates;
    double sink = 0;
    for (size_t k = 0; k < reps; k++) {
        const double w0 = wallSeconds(), c0 = threadCpuSeconds();
        mv.prepareFastDrawSingleSamples();
        mrpt::poses::CPose2D inc;
        for (size_t i = 0; i < M; i++) {
            mv.fastDrawSingleSample(inc);
            poses[i] = poses[i] + inc;
            logW[i] += det.logLikelihood(poses[i].asTPose(), reader, tag);
        }
        const double dt = threadCpuSeconds() - c0, dw = wallSeconds() - w0;
        if (k >= o.warmupUpdates) us.push_back(1e6 * dt), wall.push_back(1e6 * dw);
        // Keep the particles near the origin so the likelihood stays in range.
        if (k % 2 == 1) std::fill(poses.begin(), poses.end(), mrpt::poses::CPose2D());
        sink += logW[k % M];
    }
    std::sort(us.begin(), us.end());
    std::sort(wall.begin(), wall.end());
    TFloorResult r;
    r.M = M;
    r.medianUs = us.empty() ? 0 : us[us.size() / 2];
    r.wallMedianUs = wall.empty() ? 0 : wall[wall.size() / 2];
    r.meanUs =
        us.empty() ? 0 : std::accumulate(us.begin(), us.end(), 0.0) / double(us.size());
    if (sink == 12345.678) r.meanUs += 0;  // keeps the loop from being optimised away
    return r;
}
}  // namespace rfir::bench
