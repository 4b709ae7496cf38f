/* rfir: particle filter for one tag position (PF-SLAM: 003 Algorithm 1 lines
 * 6-18, thesis Algorithm 1). */
#pragma once

#include <rfir/models/detection_likelihood.h>
#include <rfir/models/particle_stats.h>
#include <rfir/models/resampling.h>

#include <mrpt/random/RandomGenerators.h>
#include <rfir/models/random.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace rfir::models {
struct TagParticleFilterParams {
    size_t numParticles = 100;  //!< L (seeds: 100 in 004, 150 in 003)
    ResamplingScheme resampling = ResamplingScheme::Systematic;
    /** Resample when ESS / L falls below this; 1 = every update (the seed). */
    double essThreshold = 1.0;
    /** Std (m) of a Gaussian jitter added after each resampling to fight the
     * collapse of a step likelihood; 0 = the seed's literal algorithm. */
    double rougheningSigma = 0.0;
};

/** Independent particle set for one static 2D point (a tag or landmark). */
class TagParticleFilter {
  public:
    using Params = TagParticleFilterParams;

    TagParticleFilter() = default;
    explicit TagParticleFilter(const Params& p) : m_p(p) {}

    /** First detection: L particles uniform over the reader's rectangle placed
     * by the robot pose (weight 1). */
    void initUniform(const mrpt::math::TPose2D& robot, const ReaderArea& reader,
                     rfir::models::TRandom& rng);
    /** First detection from given samples (e.g. a range-bearing inverse model);
     * the particle count becomes pts.size(). */
    void initFromPoints(std::vector<mrpt::math::TPoint2D> pts);

    /** Re-detection: weigh every particle by logLik, take the weighted mean as
     * the estimate (line 13), then resample (lines 14-18). */
    void update(const PointLogLikelihood& logLik, rfir::models::TRandom& rng);

    /** Moves particle j to f(j, particle j) (keeps the weights) and refreshes
     * the estimate: e.g. a tag mapped relative to the robot placed by a robot
     * pose drawn per particle. */
    void moveStates(
        const std::function<mrpt::math::TPoint2D(size_t, const mrpt::math::TPoint2D&)>&
            f);

    const PointEstimate& estimate() const { return m_est; }
    const std::vector<mrpt::math::TPoint2D>& particles() const { return m_pts; }
    const std::vector<double>& logWeights() const { return m_logW; }
    const Params& params() const { return m_p; }
    uint64_t updateCount() const { return m_updates; }
    bool empty() const { return m_pts.empty(); }

    /** Restores a serialized state; throws if sizes disagree. The estimate is
     * given because it was taken before the last resampling (line 13). */
    void setState(const Params& p, std::vector<mrpt::math::TPoint2D> pts,
                  std::vector<double> logW, uint64_t updates,
                  const PointEstimate& estimate);

  private:
    Params m_p;
    std::vector<mrpt::math::TPoint2D> m_pts;
    std::vector<double> m_logW;
    PointEstimate m_est;
    uint64_t m_updates = 0;
};

}  // namespace rfir::models
