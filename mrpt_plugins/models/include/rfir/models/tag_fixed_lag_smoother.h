/* rfir: fixed-lag particle smoother (Kitagawa) for one tag position (PS-SLAM:
 * 004 Algorithm 1, thesis Algorithm 2 and eq. 4.4-4.5). */
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
struct TagFixedLagSmootherParams {
    size_t numParticles = 100;  //!< J (seeds: 100)
    size_t lag = 25;            //!< states kept per particle (seeds: 20-30)
    /** Std (m) of the Gaussian random step applied to every particle on each
     * re-detection (thesis Alg. 2 line 11); keeps the set diverse. */
    double stepSigma = 0.001;
    ResamplingScheme resampling = ResamplingScheme::Systematic;
};

/** Every particle carries its last `lag` states in a ring buffer; histories
 * travel with their particles on resampling. The smoothed particle is the mean
 * of its stored states; the estimate is built from the smoothed set. */
class TagFixedLagSmoother {
  public:
    using Params = TagFixedLagSmootherParams;

    TagFixedLagSmoother() = default;
    explicit TagFixedLagSmoother(const Params& p) : m_p(p) {}

    /** First detection: uniform over the reader's rectangle; stores the
     * initial states as the first history entry (Alg. 2 lines 6-8). */
    void initUniform(const mrpt::math::TPose2D& robot, const ReaderArea& reader,
                     rfir::models::TRandom& rng);
    void initFromPoints(std::vector<mrpt::math::TPoint2D> pts);

    /** Re-detection (Alg. 2 lines 10-24): random step, weigh, store, resample
     * with histories, smooth, estimate. */
    void update(const PointLogLikelihood& logLik, rfir::models::TRandom& rng);

    /** Moves particle j and its whole stored history by f(j, state) and
     * refreshes the estimate. */
    void moveStates(
        const std::function<mrpt::math::TPoint2D(size_t, const mrpt::math::TPoint2D&)>&
            f);

    const PointEstimate& estimate() const { return m_est; }
    /** Current (filtered) states. */
    const std::vector<mrpt::math::TPoint2D>& particles() const { return m_pts; }
    /** Smoothed particles (mean of each particle's stored states). */
    std::vector<mrpt::math::TPoint2D> smoothedParticles() const;
    /** Stored states of particle j, oldest first. */
    std::vector<mrpt::math::TPoint2D> history(size_t j) const;
    size_t storedStates() const { return m_count; }
    const Params& params() const { return m_p; }
    uint64_t updateCount() const { return m_updates; }
    bool empty() const { return m_pts.empty(); }

    /** Raw ring buffer (row j = particle j, `lag` slots) for serialization. */
    const std::vector<mrpt::math::TPoint2D>& rawHistory() const { return m_hist; }
    size_t rawHead() const { return m_head; }
    void setState(const Params& p, std::vector<mrpt::math::TPoint2D> pts,
                  std::vector<mrpt::math::TPoint2D> hist, size_t head, size_t count,
                  uint64_t updates);

  private:
    void pushStates();
    void recomputeEstimate();

    Params m_p;
    std::vector<mrpt::math::TPoint2D> m_pts;   //!< current states
    std::vector<mrpt::math::TPoint2D> m_hist;  //!< numParticles x lag ring rows
    size_t m_head = 0;                         //!< next slot to write
    size_t m_count = 0;                        //!< stored states per particle (<= lag)
    PointEstimate m_est;
    uint64_t m_updates = 0;
};

}  // namespace rfir::models
