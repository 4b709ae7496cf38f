/* rfir-bench: the floor, the cheapest honest loop one robot-filter update
 * needs with M particles: per particle one fast Gaussian
 * draw of the odometry noise (three normals from the run's generator through
 * one Cholesky factor computed per step), one pose composition and one
 * detection likelihood (the PF-SLAM paper's step model, eq. 5;
 * docs/bibliography.md [2]), over contiguous arrays. No MRPT
 * sampler: MRPT's fastDrawSingleSample costs about 5 x this whole loop and
 * would hide the gap. Every figure is read as a multiple of it. */
#include <rfir/bench/bench.h>

#include <rfir/models/detection_likelihood.h>
#include <rfir/models/odometry_noise.h>
#include <rfir/slam/motion_model.h>

#include <algorithm>
#include <numeric>

namespace rfir::bench {
TFloorResult runFloor(const TBenchOptions& o, size_t M) {
    rfir::models::TRandom rng(o.seed);
    const rfir::slam::TMotionOptions motion;
    const rfir::models::OdometryNoiseParams noise{motion.a1,         motion.a2,
                                                  motion.a3,         motion.a4,
                                                  motion.min_std_xy, motion.min_std_phi};
    const rfir::models::DetectionLikelihood det;
    const rfir::models::ReaderArea reader{0.15, 0, 0.03, 0.03};
    const mrpt::math::TPoint2D tag(0.15, 0.0);
    std::vector<double> x(M, 0.0), y(M, 0.0), phi(M, 0.0), logW(M, 0.0);
    std::vector<double> us, wall;
    const size_t reps = o.warmupUpdates + o.timedUpdates;
    double sink = 0;
    for (size_t k = 0; k < reps; k++) {
        const double w0 = wallSeconds(), c0 = threadCpuSeconds();
        const auto g = rfir::models::OdometryGaussian::fromOdometry(0.005, 0, 0, noise);
        for (size_t i = 0; i < M; i++) {
            g.propagate(rng, x[i], y[i], phi[i]);
            logW[i] += det.logLikelihood({x[i], y[i], phi[i]}, reader, tag);
        }
        const double dt = threadCpuSeconds() - c0, dw = wallSeconds() - w0;
        if (k >= o.warmupUpdates) us.push_back(1e6 * dt), wall.push_back(1e6 * dw);
        // Keep the particles near the origin so the likelihood stays in range.
        if (k % 2 == 1) {
            std::fill(x.begin(), x.end(), 0.0);
            std::fill(y.begin(), y.end(), 0.0);
            std::fill(phi.begin(), phi.end(), 0.0);
        }
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
