/* rfir: fixed-lag particle smoother for one tag (Kitagawa 1996; 004 Algorithm 1,
 * thesis Algorithm 2). */
#include <rfir/models/tag_fixed_lag_smoother.h>

#include <algorithm>
#include <stdexcept>

namespace rfir::models {
namespace {
/** Scratch of update(), one set per thread: an update allocates nothing, and a
 * tag does not keep a second copy of its histories (memory stays O(L N)). The
 * resampled buffers are swapped in, the old ones become the next scratch. */
struct TScratch {
    std::vector<double> logW;
    std::vector<mrpt::math::TPoint2D> pts, hist;
};
thread_local TScratch t_scratch;
}  // namespace

void TagFixedLagSmoother::initUniform(const mrpt::math::TPose2D& robot,
                                      const ReaderArea& r,
                                      rfir::models::TRandom& rng) {
    if (m_p.numParticles == 0) throw std::invalid_argument("TagFixedLagSmoother: J = 0");
    std::vector<mrpt::math::TPoint2D> pts(m_p.numParticles);
    for (auto& p : pts) {
        ReaderArea off = r;
        off.x = r.x + rng.drawUniform(-r.halfX, r.halfX);
        off.y = r.y + rng.drawUniform(-r.halfY, r.halfY);
        p = readerCentreInWorld(robot, off);
    }
    initFromPoints(std::move(pts));
}

void TagFixedLagSmoother::initFromPoints(std::vector<mrpt::math::TPoint2D> pts) {
    if (pts.empty()) throw std::invalid_argument("TagFixedLagSmoother: no particles");
    if (m_p.lag == 0) throw std::invalid_argument("TagFixedLagSmoother: lag = 0");
    m_pts = std::move(pts);
    m_hist.assign(m_pts.size() * m_p.lag, {0, 0});
    m_head = 0;
    m_count = 0;
    m_updates = 0;
    pushStates();  // Alg. 2 line 8: the initial state is the first stored one
    recomputeEstimate();
}

void TagFixedLagSmoother::pushStates() {
    const size_t lag = m_p.lag;
    for (size_t j = 0; j < m_pts.size(); j++) m_hist[j * lag + m_head] = m_pts[j];
    m_head = (m_head + 1) % lag;
    if (m_count < lag) m_count++;  // the oldest state drops out (eq. 4.4)
}

void TagFixedLagSmoother::update(const PointLogLikelihood& logLik,
                                 rfir::models::TRandom& rng) {
    if (m_pts.empty()) throw std::logic_error("TagFixedLagSmoother::update before init");
    const size_t n = m_pts.size(), lag = m_p.lag;
    auto& sc = t_scratch;
    sc.logW.resize(n);
    for (size_t j = 0; j < n; j++) {
        // Line 11: m_t = m_{t-1} + Gaussian random step (keeps diversity).
        m_pts[j].x += m_p.stepSigma * rng.drawGaussian1D_normalized();
        m_pts[j].y += m_p.stepSigma * rng.drawGaussian1D_normalized();
        sc.logW[j] = logLik(m_pts[j]);  // line 12
    }
    pushStates();  // line 13
    // Lines 16-19: resample; whole histories travel with their particles.
    const auto idx = resampleIndices(sc.logW, n, m_p.resampling, rng);
    sc.pts.resize(n);
    sc.hist.resize(n * lag);
    for (size_t k = 0; k < n; k++) {
        sc.pts[k] = m_pts[idx[k]];
        std::copy_n(m_hist.begin() + idx[k] * lag, lag, sc.hist.begin() + k * lag);
    }
    m_pts.swap(sc.pts);
    m_hist.swap(sc.hist);
    m_updates++;
    recomputeEstimate();  // lines 20-24
}

void TagFixedLagSmoother::moveStates(
    const std::function<mrpt::math::TPoint2D(size_t, const mrpt::math::TPoint2D&)>& f) {
    const size_t lag = m_p.lag;
    for (size_t j = 0; j < m_pts.size(); j++) {
        m_pts[j] = f(j, m_pts[j]);
        for (size_t k = 0; k < lag; k++) m_hist[j * lag + k] = f(j, m_hist[j * lag + k]);
    }
    recomputeEstimate();
}

std::vector<mrpt::math::TPoint2D> TagFixedLagSmoother::smoothedParticles() const {
    // Line 20: smoothed particle = mean of its stored states t+1-L .. t.
    // Summed newest first: slots head-1 .. 0, then lag-1 down (the ring's
    // wrap), without a modulo per term (this runs on every update).
    const size_t lag = m_p.lag;
    std::vector<mrpt::math::TPoint2D> out(m_pts.size(), {0, 0});
    if (m_count == 0) return out;
    const size_t first = std::min(m_count, m_head), wrapped = m_count - first;
    for (size_t j = 0; j < m_pts.size(); j++) {
        const mrpt::math::TPoint2D* row = m_hist.data() + j * lag;
        double sx = 0, sy = 0;
        for (size_t k = 0; k < first; k++) {
            sx += row[m_head - 1 - k].x;
            sy += row[m_head - 1 - k].y;
        }
        for (size_t k = 0; k < wrapped; k++) {
            sx += row[lag - 1 - k].x;
            sy += row[lag - 1 - k].y;
        }
        out[j] = {sx / m_count, sy / m_count};
    }
    return out;
}

std::vector<mrpt::math::TPoint2D> TagFixedLagSmoother::history(size_t j) const {
    const size_t lag = m_p.lag;
    std::vector<mrpt::math::TPoint2D> out;
    for (size_t k = m_count; k-- > 0;)
        out.push_back(m_hist.at(j * lag + (m_head + lag - 1 - k) % lag));
    return out;
}

void TagFixedLagSmoother::recomputeEstimate() {
    // Line 24: the estimate comes from the smoothed set (uniform weights after
    // resampling).
    m_est = weightedEstimate(smoothedParticles(), {});
}

void TagFixedLagSmoother::setState(const Params& p, std::vector<mrpt::math::TPoint2D> pts,
                                   std::vector<mrpt::math::TPoint2D> hist, size_t head,
                                   size_t count, uint64_t updates) {
    if (pts.empty() || p.lag == 0 || hist.size() != pts.size() * p.lag || head >= p.lag ||
        count > p.lag || count == 0)
        throw std::invalid_argument("TagFixedLagSmoother::setState: bad sizes");
    m_p = p;
    m_pts = std::move(pts);
    m_hist = std::move(hist);
    m_head = head;
    m_count = count;
    m_updates = updates;
    recomputeEstimate();
}

}  // namespace rfir::models
