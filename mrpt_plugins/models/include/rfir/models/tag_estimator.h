/* rfir: the one interface of a per-tag position estimator (PF-SLAM's particle
 * filter, PS-SLAM's fixed-lag smoother, ...) and the registry that names them
 * for the INI key [tagmap] estimator. A new estimator is one file deriving
 * from CTagEstimator plus one registerTagEstimator line in it. */
#pragma once

#include <rfir/models/detection_likelihood.h>
#include <rfir/models/particle_stats.h>
#include <rfir/models/random.h>
#include <rfir/models/resampling.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mrpt::serialization {
class CArchive;
}

namespace rfir::models {
/** Every estimator's parameters (INI [tagmap]); each uses the ones it needs. */
struct TTagEstimatorParams {
    size_t numParticles = 100;  //!< num_particles (L)
    size_t lag = 25;            //!< lag (smoother)
    double stepSigma = 0.001;   //!< smoother_step_sigma (m)
    ResamplingScheme resampling = ResamplingScheme::Systematic;
    double essThreshold = 1.0;     //!< ess_threshold (PF)
    double rougheningSigma = 0.0;  //!< roughening_sigma (m, PF)
};

/** n points uniform over reader r placed by the robot pose (003 eq. 6): the
 * one initial sampler of every estimator (x then y drawn per point). */
std::vector<mrpt::math::TPoint2D> sampleReaderArea(const mrpt::math::TPose2D& robot,
                                                   const ReaderArea& r, size_t n,
                                                   TRandom& rng);
/** The same with a robot pose per point, robotPerPoint() called before the
 * point's two draws (e.g. a pose drawn from the robot's particle set). */
std::vector<mrpt::math::TPoint2D> sampleReaderArea(
    const std::function<mrpt::math::TPose2D()>& robotPerPoint, const ReaderArea& r,
    size_t n, TRandom& rng);

/** Moves state j (of any age) to f(j, state). */
using TStateMove =
    std::function<mrpt::math::TPoint2D(size_t, const mrpt::math::TPoint2D&)>;

/** Position estimate of one static 2D point from its reads. One virtual call
 * per tag operation; the per-particle loops are inside the implementations. */
class CTagEstimator {
  public:
    virtual ~CTagEstimator() = default;
    /** Registry name (the INI value). */
    virtual const char* name() const = 0;
    virtual std::unique_ptr<CTagEstimator> clone() const = 0;

    /** First detection: numParticles points over the reader (sampleReaderArea). */
    void initUniform(const mrpt::math::TPose2D& robot, const ReaderArea& reader,
                     TRandom& rng);
    /** First detection from given samples; the particle count becomes
     * pts.size(). Throws std::invalid_argument if empty. */
    virtual void initFromPoints(const std::vector<mrpt::math::TPoint2D>& pts) = 0;
    /** Re-detection: weigh by logLik, estimate, resample. */
    virtual void update(const PointLogLikelihood& logLik, TRandom& rng) = 0;
    /** Moves every stored state of particle j by f(j, .) (f rigid per j, as the
     * map's samples_visit commit), refreshes the estimate. */
    virtual void moveStates(const TStateMove& f) = 0;
    /** Moves every stored state by (dx, dy) (the map correction), refreshes
     * the estimate; an estimator may do it cheaper than moveStates. */
    virtual void translate(double dx, double dy) {
        moveStates([dx, dy](size_t, const mrpt::math::TPoint2D& p) {
            return mrpt::math::TPoint2D(p.x + dx, p.y + dy);
        });
    }

    virtual const PointEstimate& estimate() const = 0;
    /** Current (filtered) states, world frame. */
    virtual std::vector<mrpt::math::TPoint2D> particles() const = 0;
    /** The set the estimate is built from (PF: particles(); smoother: the
     * mean of each particle's stored states). */
    virtual std::vector<mrpt::math::TPoint2D> smoothedParticles() const = 0;
    virtual size_t size() const = 0;
    /** Configured particle count (L) used by initUniform. */
    virtual size_t numParticles() const = 0;
    virtual uint64_t updateCount() const = 0;
    bool empty() const { return size() == 0; }

    /** Bytes this estimator owns: the object and its containers' capacity. */
    virtual size_t memoryBytes() const = 0;

    /** Versioned state (own format byte first); readState throws on a bad or
     * inconsistent stream. */
    virtual void writeState(mrpt::serialization::CArchive& out) const = 0;
    virtual void readState(mrpt::serialization::CArchive& in) = 0;
};

/** @name Registry (name -> factory). @{ */
using TTagEstimatorFactory =
    std::function<std::unique_ptr<CTagEstimator>(const TTagEstimatorParams&)>;
/** Registers `name` (call from a static initialiser in the estimator's file);
 * returns true. Throws std::logic_error if the name is taken. */
bool registerTagEstimator(const std::string& name, TTagEstimatorFactory f);
/** Throws std::invalid_argument listing the registered names if unknown. */
std::unique_ptr<CTagEstimator> createTagEstimator(const std::string& name,
                                                  const TTagEstimatorParams& p);
/** Registered names, sorted. */
std::vector<std::string> tagEstimatorNames();
constexpr const char* kParticleFilterName = "particle_filter";
constexpr const char* kFixedLagSmootherName = "fixed_lag_smoother";
/** @} */

/** Owning handle with value semantics (copies clone), so that map entries
 * holding an estimator stay copyable. */
class CTagEstimatorPtr {
  public:
    CTagEstimatorPtr() = default;
    CTagEstimatorPtr(std::unique_ptr<CTagEstimator> p) : m_p(std::move(p)) {}
    CTagEstimatorPtr(const CTagEstimatorPtr& o) : m_p(o.m_p ? o.m_p->clone() : nullptr) {}
    CTagEstimatorPtr(CTagEstimatorPtr&&) noexcept = default;
    CTagEstimatorPtr& operator=(const CTagEstimatorPtr& o) {
        if (this != &o) m_p = o.m_p ? o.m_p->clone() : nullptr;
        return *this;
    }
    CTagEstimatorPtr& operator=(CTagEstimatorPtr&&) noexcept = default;
    CTagEstimator* operator->() const { return m_p.get(); }
    CTagEstimator& operator*() const { return *m_p; }
    explicit operator bool() const { return bool(m_p); }

  private:
    std::unique_ptr<CTagEstimator> m_p;
};

}  // namespace rfir::models
