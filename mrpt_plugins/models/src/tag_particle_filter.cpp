/* rfir: particle filter for one tag (003 Algorithm 1, thesis Algorithm 1). */
#include <rfir/models/tag_particle_filter.h>

#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

namespace rfir::models {
namespace {
const bool kRegistered =
    registerTagEstimator(kParticleFilterName, [](const TTagEstimatorParams& p) {
        return std::make_unique<TagParticleFilter>(TagParticleFilterParams{
            p.numParticles, p.resampling, p.essThreshold, p.rougheningSigma});
    });

/** Scratch of update(), one per thread: an update allocates nothing. */
struct TScratch {
    std::vector<double> logW;
    std::vector<TQPoint> pts;
};
thread_local TScratch t_scratch;

// Bounds of a stream read (a corrupt count must not allocate gigabytes).
constexpr uint64_t kMaxParticles = 10000000;
}  // namespace

void TagParticleFilter::initFromPoints(const std::vector<mrpt::math::TPoint2D>& pts) {
    if (pts.empty()) throw std::invalid_argument("TagParticleFilter: no particles");
    m_anchor = anchorAtMean(pts);
    m_pts.resize(pts.size());
    for (size_t l = 0; l < pts.size(); l++) m_pts[l] = m_anchor.quantize(pts[l]);
    m_logW.clear();  // weight 1 (Alg. 1 line 7)
    m_est = computeEstimate();
    m_updates = 0;
}

PointEstimate TagParticleFilter::computeEstimate() const {
    const auto xy = [&](size_t i) {
        return std::pair<double, double>(m_pts[i].x, m_pts[i].y);
    };
    if (m_logW.empty()) return offsetEstimate(m_anchor, m_pts.size(), xy, nullptr);
    const auto w = normalisedWeights(logWeights());
    return offsetEstimate(m_anchor, m_pts.size(), xy, w.data());
}

std::vector<mrpt::math::TPoint2D> TagParticleFilter::particles() const {
    std::vector<mrpt::math::TPoint2D> v(m_pts.size());
    for (size_t l = 0; l < v.size(); l++) v[l] = m_anchor.world(m_pts[l]);
    return v;
}

std::vector<double> TagParticleFilter::logWeights() const {
    if (m_logW.empty()) return std::vector<double>(m_pts.size(), 0.0);
    return std::vector<double>(m_logW.begin(), m_logW.end());
}

void TagParticleFilter::moveStates(const TStateMove& f) {
    for (size_t l = 0; l < m_pts.size(); l++)
        m_pts[l] = m_anchor.quantize(f(l, m_anchor.world(m_pts[l])));
    m_est = computeEstimate();
}

void TagParticleFilter::update(const PointLogLikelihood& logLik, TRandom& rng) {
    if (m_pts.empty()) throw std::logic_error("TagParticleFilter::update before init");
    const size_t n = m_pts.size();
    auto& sc = t_scratch;
    sc.logW.resize(n);
    for (size_t l = 0; l < n; l++)  // line 10
        sc.logW[l] =
            (m_logW.empty() ? 0.0 : m_logW[l]) + logLik(m_anchor.world(m_pts[l]));
    {  // line 13: the weighted mean, before resampling
        const auto w = normalisedWeights(sc.logW);
        m_est = offsetEstimate(
            m_anchor, n,
            [&](size_t i) { return std::pair<double, double>(m_pts[i].x, m_pts[i].y); },
            w.data());
    }
    m_updates++;
    if (m_p.essThreshold < 1.0 && effectiveSampleSize(sc.logW) >= m_p.essThreshold * n) {
        m_logW.assign(sc.logW.begin(), sc.logW.end());
        return;
    }
    // Lines 14-18: particles of low weight take the state of heavy ones.
    const auto idx = resampleIndices(sc.logW, n, m_p.resampling, rng);
    sc.pts.resize(idx.size());
    for (size_t k = 0; k < idx.size(); k++) sc.pts[k] = m_pts[idx[k]];
    if (m_p.rougheningSigma > 0)
        for (auto& q : sc.pts) {
            auto p = m_anchor.world(q);
            p.x += m_p.rougheningSigma * rng.drawGaussian1D_normalized();
            p.y += m_p.rougheningSigma * rng.drawGaussian1D_normalized();
            q = m_anchor.quantize(p);
        }
    m_pts.swap(sc.pts);
    m_logW.clear();
}

size_t TagParticleFilter::memoryBytes() const {
    return sizeof(*this) + m_pts.capacity() * sizeof(TQPoint) +
           m_logW.capacity() * sizeof(float);
}

void TagParticleFilter::setState(const Params& p,
                                 const std::vector<mrpt::math::TPoint2D>& pts,
                                 const std::vector<double>& logW, uint64_t updates,
                                 const PointEstimate& estimate) {
    if (pts.size() != logW.size() || pts.empty())
        throw std::invalid_argument("TagParticleFilter::setState: bad sizes");
    m_p = p;
    initFromPoints(pts);
    bool uniform = true;
    for (double w : logW) uniform = uniform && w == logW[0];
    if (!uniform) m_logW.assign(logW.begin(), logW.end());
    m_updates = updates;
    m_est = estimate;
}

void TagParticleFilter::writeState(mrpt::serialization::CArchive& a) const {
    a.WriteAs<uint8_t>(0);  // format of this estimator's state
    a.WriteAs<uint64_t>(m_p.numParticles);
    a.WriteAs<uint8_t>(static_cast<uint8_t>(m_p.resampling));
    a << m_p.essThreshold << m_p.rougheningSigma << m_anchor.x() << m_anchor.y();
    a.WriteAs<uint64_t>(m_pts.size());
    for (const auto& q : m_pts) a << q.x << q.y;
    a.WriteAs<uint64_t>(m_logW.size());
    for (float w : m_logW) a << w;
    a.WriteAs<uint64_t>(m_updates);
    a << m_est.mean.x << m_est.mean.y << m_est.cov(0, 0) << m_est.cov(0, 1)
      << m_est.cov(1, 1);
}

void TagParticleFilter::readState(mrpt::serialization::CArchive& a) {
    if (a.ReadAs<uint8_t>() != 0)
        throw std::runtime_error("TagParticleFilter: unknown state format");
    m_p.numParticles = a.ReadAs<uint64_t>();
    m_p.resampling = static_cast<ResamplingScheme>(a.ReadAs<uint8_t>());
    double ax, ay;
    a >> m_p.essThreshold >> m_p.rougheningSigma >> ax >> ay;
    m_anchor = TAnchor({ax, ay});
    const auto n = a.ReadAs<uint64_t>();
    if (n == 0 || n > kMaxParticles)
        throw std::runtime_error("TagParticleFilter: particle count out of range");
    m_pts.resize(n);
    for (auto& q : m_pts) a >> q.x >> q.y;
    const auto nw = a.ReadAs<uint64_t>();
    if (nw != 0 && nw != n)
        throw std::runtime_error("TagParticleFilter: weight count mismatch");
    m_logW.resize(nw);
    for (float& w : m_logW) a >> w;
    m_updates = a.ReadAs<uint64_t>();
    double c01;
    a >> m_est.mean.x >> m_est.mean.y >> m_est.cov(0, 0) >> c01 >> m_est.cov(1, 1);
    m_est.cov(0, 1) = m_est.cov(1, 0) = c01;
}

}  // namespace rfir::models
