/* rfir: particle filter for one tag position (PF-SLAM: 003 Algorithm 1 lines
 * 6-18, thesis Algorithm 1). */
#pragma once

#include <rfir/models/anchored_points.h>
#include <rfir/models/tag_estimator.h>

#include <cstdint>
#include <vector>

namespace rfir::models {
struct TagParticleFilterParams {
    size_t numParticles =
        100;  //!< L (the papers: 100 in the PS-SLAM paper, 150 in the PF-SLAM paper)
    ResamplingScheme resampling = ResamplingScheme::Systematic;
    /** Resample when ESS / L falls below this; 1 = every update (the papers). */
    double essThreshold = 1.0;
    /** Std (m) of a Gaussian jitter added after each resampling to fight the
     * collapse of a step likelihood; 0 = the papers' literal algorithm. */
    double rougheningSigma = 0.0;
};

/** Independent particle set for one static 2D point (a tag or landmark).
 * Storage: 8 bytes per particle (anchored offsets) plus 4 per log-weight only
 * while the weights are not uniform (ess_threshold < 1). */
class TagParticleFilter : public CTagEstimator {
  public:
    using Params = TagParticleFilterParams;

    TagParticleFilter() = default;
    explicit TagParticleFilter(const Params& p) : m_p(p) {}

    const char* name() const override { return kParticleFilterName; }
    std::unique_ptr<CTagEstimator> clone() const override {
        return std::make_unique<TagParticleFilter>(*this);
    }
    void initFromPoints(const std::vector<mrpt::math::TPoint2D>& pts) override;
    /** Re-detection: weigh every particle by logLik, take the weighted mean as
     * the estimate (line 13), then resample (lines 14-18). */
    void update(const PointLogLikelihood& logLik, TRandom& rng) override;
    /** Moves particle j to f(j, particle j) (keeps the weights). */
    void moveStates(const TStateMove& f) override;

    const PointEstimate& estimate() const override { return m_est; }
    std::vector<mrpt::math::TPoint2D> particles() const override;
    std::vector<mrpt::math::TPoint2D> smoothedParticles() const override {
        return particles();
    }
    /** Log-weights (all 0 after a resampling). */
    std::vector<double> logWeights() const;
    size_t size() const override { return m_pts.size(); }
    size_t numParticles() const override { return m_p.numParticles; }
    uint64_t updateCount() const override { return m_updates; }
    size_t memoryBytes() const override;

    void writeState(mrpt::serialization::CArchive& out) const override;
    void readState(mrpt::serialization::CArchive& in) override;
    /** Restores a state (also the map's version 0-2 streams); throws if sizes
     * disagree. The estimate is given because it was taken before the last
     * resampling (line 13). */
    void setState(const Params& p, const std::vector<mrpt::math::TPoint2D>& pts,
                  const std::vector<double>& logW, uint64_t updates,
                  const PointEstimate& estimate);

  private:
    PointEstimate computeEstimate() const;

    Params m_p;
    TAnchor m_anchor;
    std::vector<TQPoint> m_pts;
    std::vector<float> m_logW;  //!< empty = uniform (the common case)
    PointEstimate m_est;
    uint64_t m_updates = 0;
};

}  // namespace rfir::models
