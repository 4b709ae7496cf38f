/* rfir: fixed-lag particle smoother for one tag (Kitagawa 1996; 004 Algorithm 1,
 * thesis Algorithm 2). */
#include <rfir/models/tag_fixed_lag_smoother.h>

#include <stdexcept>

namespace rfir::models {
void TagFixedLagSmoother::initUniform(const mrpt::math::TPose2D& robot,
                                      const ReaderArea& r,
                                      mrpt::random::CRandomGenerator& rng) {
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
                                 mrpt::random::CRandomGenerator& rng) {
    if (m_pts.empty()) throw std::logic_error("TagFixedLagSmoother::update before init");
    const size_t n = m_pts.size(), lag = m_p.lag;
    std::vector<double> logW(n);
    for (size_t j = 0; j < n; j++) {
        // Line 11: m_t = m_{t-1} + Gaussian random step (keeps diversity).
        m_pts[j].x += m_p.stepSigma * rng.drawGaussian1D_normalized();
        m_pts[j].y += m_p.stepSigma * rng.drawGaussian1D_normalized();
        logW[j] = logLik(m_pts[j]);  // line 12
    }
    pushStates();  // line 13
    // Lines 16-19: resample; whole histories travel with their particles.
    const auto idx = resampleIndices(logW, n, m_p.resampling, rng);
    std::vector<mrpt::math::TPoint2D> pts(n), hist(n * lag);
    for (size_t k = 0; k < n; k++) {
        pts[k] = m_pts[idx[k]];
        std::copy_n(m_hist.begin() + idx[k] * lag, lag, hist.begin() + k * lag);
    }
    m_pts = std::move(pts);
    m_hist = std::move(hist);
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
    const size_t lag = m_p.lag;
    std::vector<mrpt::math::TPoint2D> out(m_pts.size(), {0, 0});
    if (m_count == 0) return out;
    for (size_t j = 0; j < m_pts.size(); j++) {
        double sx = 0, sy = 0;
        for (size_t k = 0; k < m_count; k++) {
            const auto& s = m_hist[j * lag + (m_head + lag - 1 - k) % lag];
            sx += s.x;
            sy += s.y;
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
