/* rfir: particle filter for one tag (003 Algorithm 1, thesis Algorithm 1). */
#include <rfir/models/tag_particle_filter.h>

#include <stdexcept>

namespace rfir::models {
namespace {
std::vector<mrpt::math::TPoint2D> uniformOverReader(const mrpt::math::TPose2D& robot,
                                                    const ReaderArea& r, size_t n,
                                                    rfir::models::TRandom& rng) {
    // Uniform over the reader's rectangle, drawn in the robot frame and placed
    // in the world by the robot pose (003 eq. 6).
    std::vector<mrpt::math::TPoint2D> pts(n);
    for (auto& p : pts) {
        ReaderArea off = r;
        off.x = r.x + rng.drawUniform(-r.halfX, r.halfX);
        off.y = r.y + rng.drawUniform(-r.halfY, r.halfY);
        p = readerCentreInWorld(robot, off);
    }
    return pts;
}
}  // namespace

void TagParticleFilter::initUniform(const mrpt::math::TPose2D& robot,
                                    const ReaderArea& reader,
                                    rfir::models::TRandom& rng) {
    if (m_p.numParticles == 0) throw std::invalid_argument("TagParticleFilter: L = 0");
    initFromPoints(uniformOverReader(robot, reader, m_p.numParticles, rng));
}

void TagParticleFilter::initFromPoints(std::vector<mrpt::math::TPoint2D> pts) {
    if (pts.empty()) throw std::invalid_argument("TagParticleFilter: no particles");
    m_pts = std::move(pts);
    m_logW.assign(m_pts.size(), 0.0);  // weight 1 (Alg. 1 line 7)
    m_est = weightedEstimate(m_pts, m_logW);
    m_updates = 0;
}

void TagParticleFilter::moveStates(
    const std::function<mrpt::math::TPoint2D(size_t, const mrpt::math::TPoint2D&)>& f) {
    for (size_t l = 0; l < m_pts.size(); l++) m_pts[l] = f(l, m_pts[l]);
    m_est = weightedEstimate(m_pts, m_logW);
}

void TagParticleFilter::update(const PointLogLikelihood& logLik,
                               rfir::models::TRandom& rng) {
    if (m_pts.empty()) throw std::logic_error("TagParticleFilter::update before init");
    for (size_t l = 0; l < m_pts.size(); l++) m_logW[l] += logLik(m_pts[l]);  // line 10
    m_est = weightedEstimate(m_pts, m_logW);                                  // line 13
    m_updates++;
    if (effectiveSampleSize(m_logW) >= m_p.essThreshold * m_pts.size() &&
        m_p.essThreshold < 1.0)
        return;
    // Lines 14-18: particles of low weight take the state of heavy ones.
    const auto idx = resampleIndices(m_logW, m_pts.size(), m_p.resampling, rng);
    std::vector<mrpt::math::TPoint2D> next(idx.size());
    for (size_t k = 0; k < idx.size(); k++) next[k] = m_pts[idx[k]];
    if (m_p.rougheningSigma > 0)
        for (auto& p : next) {
            p.x += m_p.rougheningSigma * rng.drawGaussian1D_normalized();
            p.y += m_p.rougheningSigma * rng.drawGaussian1D_normalized();
        }
    m_pts = std::move(next);
    m_logW.assign(m_pts.size(), 0.0);
}

void TagParticleFilter::setState(const Params& p, std::vector<mrpt::math::TPoint2D> pts,
                                 std::vector<double> logW, uint64_t updates,
                                 const PointEstimate& estimate) {
    if (pts.size() != logW.size() || pts.empty())
        throw std::invalid_argument("TagParticleFilter::setState: bad sizes");
    m_p = p;
    m_pts = std::move(pts);
    m_logW = std::move(logW);
    m_updates = updates;
    m_est = estimate;
}

}  // namespace rfir::models
