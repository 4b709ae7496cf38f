/* rfir: fixed-lag particle smoother (Kitagawa) for one tag position (PS-SLAM:
 * 004 Algorithm 1, thesis Algorithm 2 and eq. 4.4-4.5). */
#pragma once

#include <rfir/models/anchored_points.h>
#include <rfir/models/tag_estimator.h>

#include <cstdint>
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

/** Every particle has its last `lag` states; the smoothed particle is their
 * mean, the estimate is built from the smoothed set.
 *
 * Storage without the histories (9 + lag bytes per particle at J <= 256
 * instead of 16 lag): a state is its ancestor's plus a step drawn from a
 * counter-based stream (tag stream, slot, particle), so a past step is drawn
 * again instead of stored. Per particle: the current state, the integer sum
 * of its stored states, its oldest stored state, and for every stored slot the
 * index it had in that slot (the ancestry; it travels with the particle on
 * resampling, so resampled particles share their history prefix). When the
 * window slides, the oldest state advances to the next slot by that slot's
 * step, and leaves the sum exactly (integers, no drift). */
class TagFixedLagSmoother : public CTagEstimator {
  public:
    using Params = TagFixedLagSmootherParams;

    TagFixedLagSmoother() = default;
    explicit TagFixedLagSmoother(const Params& p) : m_p(p) {}

    const char* name() const override { return kFixedLagSmootherName; }
    std::unique_ptr<CTagEstimator> clone() const override {
        return std::make_unique<TagFixedLagSmoother>(*this);
    }
    /** Alg. 2 lines 6-8: the initial states are the first stored ones. The
     * tag's step stream is seeded from them (deterministic, no generator). */
    void initFromPoints(const std::vector<mrpt::math::TPoint2D>& pts) override;
    /** Re-detection (Alg. 2 lines 10-24): random step, weigh, store, resample
     * with histories, smooth, estimate. */
    void update(const PointLogLikelihood& logLik, TRandom& rng) override;
    /** Moves particle j by f(j, .): its current state exactly, its stored
     * states through their sum (exact for f affine per j, as the map's rigid
     * samples_visit commit). The states stored before the move then leave
     * the window as their mean, one per update: the sum is exact again once
     * they are all out (lag - 1 updates later). */
    void moveStates(const TStateMove& f) override;
    /** Every state is an offset from the anchor: moving the anchor moves them
     * all (by the translation rounded to the 2^-20 m grid), O(L) for the
     * estimate instead of re-quantising the histories. */
    void translate(double dx, double dy) override;

    const PointEstimate& estimate() const override { return m_est; }
    std::vector<mrpt::math::TPoint2D> particles() const override;
    std::vector<mrpt::math::TPoint2D> smoothedParticles() const override;
    /** Stored states of particle j, oldest first (rebuilt from the stream). */
    std::vector<mrpt::math::TPoint2D> history(size_t j) const;
    size_t storedStates() const { return m_count; }
    size_t size() const override { return m_cur.size(); }
    size_t numParticles() const override { return m_p.numParticles; }
    uint64_t updateCount() const override { return m_updates; }
    size_t memoryBytes() const override;

    void writeState(mrpt::serialization::CArchive& out) const override;
    void readState(mrpt::serialization::CArchive& in) override;
    /** Restores a state stored as whole histories (the map's version 0-2
     * streams: row j = particle j's ring of `lag` slots); the stored states
     * are kept through their sums, as after moveStates. Throws on bad sizes. */
    void setLegacyState(const Params& p, const std::vector<mrpt::math::TPoint2D>& pts,
                        const std::vector<mrpt::math::TPoint2D>& hist, size_t head,
                        size_t count, uint64_t updates);

  private:
    uint32_t chain(size_t j, size_t ring) const;
    void setChain(size_t j, size_t ring, uint32_t v);
    /** The state of particle j's ancestry in slot u, given `o`, its state in
     * slot u - 1. */
    TQPoint advance(const TQPoint& o, uint64_t u, size_t j) const;
    /** Replaces particle j's stored states by states of the same sum: the
     * older ones by their mean (kept in m_old), the newest by m_cur[j]. */
    void freeze(const std::vector<int64_t>& sums);
    void resampleRows(const std::vector<size_t>& idx);
    void recomputeEstimate();
    void seedStream();

    Params m_p;
    TAnchor m_anchor;
    uint64_t m_stream = 0;         //!< the tag's step stream
    std::vector<TQPoint> m_cur;    //!< current states
    std::vector<int64_t> m_sum;    //!< per particle: sum x, sum y of stored states
    std::vector<TQPoint> m_old;    //!< per particle: oldest stored state
    std::vector<TQPoint> m_base;   //!< per particle: state in slot m_frozen (if frozen)
    std::vector<uint8_t> m_chain;  //!< J x lag ring of indices, m_width bytes each
    uint8_t m_width = 1;
    size_t m_count = 0;     //!< stored states per particle (<= lag)
    uint64_t m_frozen = 0;  //!< slots before it hold their mean (see freeze)
    PointEstimate m_est;
    uint64_t m_updates = 0;  //!< also the newest slot's number
};

}  // namespace rfir::models
