/* rfir: fixed-lag particle smoother for one tag (Kitagawa 1996; 004 Algorithm 1,
 * thesis Algorithm 2), with the compact storage described in the header. */
#include <rfir/models/tag_fixed_lag_smoother.h>

#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace rfir::models {
namespace {
const bool kRegistered =
    registerTagEstimator(kFixedLagSmootherName, [](const TTagEstimatorParams& p) {
        return std::make_unique<TagFixedLagSmoother>(
            TagFixedLagSmootherParams{p.numParticles, p.lag, p.stepSigma, p.resampling});
    });

/** Scratch of update(), one set per thread: an update allocates nothing. The
 * resampled rows are swapped in, the old ones become the next scratch. */
struct TScratch {
    std::vector<double> logW;
    std::vector<TQPoint> cur, old, base;
    std::vector<int64_t> sum;
    std::vector<uint8_t> chain;
};
thread_local TScratch t_scratch;

TQPoint addQ(const TQPoint& a, const TQPoint& b) {
    const int64_t x = int64_t(a.x) + b.x, y = int64_t(a.y) + b.y;
    if (x != int32_t(x) || y != int32_t(y))
        throw std::range_error("TagFixedLagSmoother: state beyond 2048 m of its anchor");
    return {int32_t(x), int32_t(y)};
}
}  // namespace

uint32_t TagFixedLagSmoother::chain(size_t j, size_t ring) const {
    const uint8_t* p = m_chain.data() + (j * m_p.lag + ring) * m_width;
    if (m_width == 1) return *p;
    if (m_width == 2) {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

void TagFixedLagSmoother::setChain(size_t j, size_t ring, uint32_t v) {
    uint8_t* p = m_chain.data() + (j * m_p.lag + ring) * m_width;
    if (m_width == 1)
        *p = uint8_t(v);
    else if (m_width == 2) {
        const uint16_t w = uint16_t(v);
        std::memcpy(p, &w, 2);
    } else
        std::memcpy(p, &v, 4);
}

TQPoint TagFixedLagSmoother::advance(const TQPoint& o, uint64_t u, size_t j) const {
    if (u < m_frozen) return o;  // a frozen slot: the same mean
    if (u == m_frozen) return m_base[j];
    // Line 11 of slot u, drawn again: state(u) = state(u - 1) + step(u, index).
    const double sq = m_p.stepSigma * TAnchor::kInvQuantum;
    return addQ(o, streamGaussian(m_stream, u, chain(j, u % m_p.lag), sq));
}

void TagFixedLagSmoother::seedStream() {
    uint64_t h = splitmix64(m_cur.size());
    for (const auto& q : m_cur)
        h = splitmix64(h ^ (uint64_t(uint32_t(q.x)) << 32 | uint32_t(q.y)));
    m_stream = splitmix64(h ^ uint64_t(m_anchor.x() * TAnchor::kInvQuantum)) ^
               uint64_t(m_anchor.y() * TAnchor::kInvQuantum);
}

void TagFixedLagSmoother::initFromPoints(const std::vector<mrpt::math::TPoint2D>& pts) {
    if (pts.empty()) throw std::invalid_argument("TagFixedLagSmoother: no particles");
    if (m_p.lag == 0) throw std::invalid_argument("TagFixedLagSmoother: lag = 0");
    const size_t n = pts.size();
    m_anchor = anchorAtMean(pts);
    m_cur.resize(n);
    for (size_t j = 0; j < n; j++) m_cur[j] = m_anchor.quantize(pts[j]);
    m_old = m_cur;
    m_sum.resize(2 * n);
    for (size_t j = 0; j < n; j++) {
        m_sum[2 * j] = m_cur[j].x;
        m_sum[2 * j + 1] = m_cur[j].y;
    }
    m_base.clear();
    m_width = n <= 256 ? 1 : n <= 65536 ? 2 : 4;
    m_chain.assign(n * m_p.lag * m_width, 0);
    for (size_t j = 0; j < n; j++) setChain(j, 0, uint32_t(j));
    m_count = 1;  // Alg. 2 line 8: the initial state is the first stored one
    m_frozen = 0;
    m_updates = 0;
    seedStream();
    recomputeEstimate();
}

void TagFixedLagSmoother::update(const PointLogLikelihood& logLik, TRandom& rng) {
    if (m_cur.empty()) throw std::logic_error("TagFixedLagSmoother::update before init");
    const size_t n = m_cur.size(), lag = m_p.lag;
    const uint64_t slot = m_updates + 1;
    const bool full = m_count == lag;  // the oldest state drops out (eq. 4.4)
    const uint64_t next = slot + 1 - lag;
    const double sq = m_p.stepSigma * TAnchor::kInvQuantum;
    auto& sc = t_scratch;
    sc.logW.resize(n);
    for (size_t j = 0; j < n; j++) {
        // Line 11: m_t = m_{t-1} + Gaussian random step (keeps diversity).
        const TQPoint x = addQ(m_cur[j], streamGaussian(m_stream, slot, j, sq));
        sc.logW[j] = logLik(m_anchor.world(x));  // line 12
        setChain(j, slot % lag, uint32_t(j));    // line 13: store
        if (full) {
            m_sum[2 * j] -= m_old[j].x;
            m_sum[2 * j + 1] -= m_old[j].y;
            m_old[j] = advance(m_old[j], next, j);
        }
        m_sum[2 * j] += x.x;
        m_sum[2 * j + 1] += x.y;
        m_cur[j] = x;
    }
    // Lines 16-19: resample; the histories (ancestries) travel with particles.
    resampleRows(resampleIndices(sc.logW, n, m_p.resampling, rng));
    m_updates = slot;
    m_count = std::min(m_count + 1, lag);
    if (!m_base.empty() && m_updates + 1 - m_count >= m_frozen)
        std::vector<TQPoint>().swap(m_base);  // no frozen slot left
    recomputeEstimate();                      // lines 20-24
}

void TagFixedLagSmoother::resampleRows(const std::vector<size_t>& idx) {
    const size_t n = m_cur.size(), row = m_p.lag * m_width;
    auto& sc = t_scratch;
    sc.cur.resize(n);
    sc.old.resize(n);
    sc.sum.resize(2 * n);
    sc.chain.resize(n * row);
    sc.base.resize(m_base.size());
    for (size_t k = 0; k < n; k++) {
        const size_t i = idx[k];
        sc.cur[k] = m_cur[i];
        sc.old[k] = m_old[i];
        sc.sum[2 * k] = m_sum[2 * i];
        sc.sum[2 * k + 1] = m_sum[2 * i + 1];
        std::memcpy(sc.chain.data() + k * row, m_chain.data() + i * row, row);
        if (!m_base.empty()) sc.base[k] = m_base[i];
    }
    m_cur.swap(sc.cur);
    m_old.swap(sc.old);
    m_sum.swap(sc.sum);
    m_chain.swap(sc.chain);
    if (!m_base.empty()) m_base.swap(sc.base);
}

void TagFixedLagSmoother::freeze(const std::vector<int64_t>& sums) {
    const size_t n = m_cur.size();
    const int64_t c = int64_t(m_count);
    m_frozen = m_updates;
    m_sum = sums;
    if (c == 1) {  // nothing older than the newest state
        m_old = m_cur;
        for (size_t j = 0; j < n; j++) {
            m_sum[2 * j] = m_cur[j].x;
            m_sum[2 * j + 1] = m_cur[j].y;
        }
        std::vector<TQPoint>().swap(m_base);
        return;
    }
    // Slots m_frozen - c + 1 .. m_frozen - 1 hold K = (sum - newest) / (c - 1)
    // each (floored; the sum is set to match, a change below one quantum).
    m_base = m_cur;
    for (size_t j = 0; j < n; j++) {
        const int64_t kx = (sums[2 * j] - m_cur[j].x) / (c - 1),
                      ky = (sums[2 * j + 1] - m_cur[j].y) / (c - 1);
        m_old[j] = {int32_t(kx), int32_t(ky)};
        m_sum[2 * j] = (c - 1) * kx + m_cur[j].x;
        m_sum[2 * j + 1] = (c - 1) * ky + m_cur[j].y;
    }
}

void TagFixedLagSmoother::moveStates(const TStateMove& f) {
    const size_t n = m_cur.size();
    const double c = double(m_count);
    std::vector<int64_t> sums(2 * n);
    for (size_t j = 0; j < n; j++) {
        // Sum of f over the stored states = c f(mean) for f affine.
        const auto mean = m_anchor.world(m_sum[2 * j] / c, m_sum[2 * j + 1] / c);
        const auto fm = f(j, mean);
        sums[2 * j] = std::llround(c * (fm.x - m_anchor.x()) * TAnchor::kInvQuantum);
        sums[2 * j + 1] = std::llround(c * (fm.y - m_anchor.y()) * TAnchor::kInvQuantum);
        m_cur[j] = m_anchor.quantize(f(j, m_anchor.world(m_cur[j])));
    }
    freeze(sums);
    recomputeEstimate();
}

void TagFixedLagSmoother::translate(double dx, double dy) {
    m_anchor = TAnchor(mrpt::math::TPoint2D(m_anchor.x() + dx, m_anchor.y() + dy));
    recomputeEstimate();
}

std::vector<mrpt::math::TPoint2D> TagFixedLagSmoother::particles() const {
    std::vector<mrpt::math::TPoint2D> v(m_cur.size());
    for (size_t j = 0; j < v.size(); j++) v[j] = m_anchor.world(m_cur[j]);
    return v;
}

std::vector<mrpt::math::TPoint2D> TagFixedLagSmoother::smoothedParticles() const {
    // Line 20: smoothed particle = mean of its stored states t+1-L .. t.
    std::vector<mrpt::math::TPoint2D> v(m_cur.size());
    const double c = double(std::max<size_t>(m_count, 1));
    for (size_t j = 0; j < v.size(); j++)
        v[j] = m_anchor.world(m_sum[2 * j] / c, m_sum[2 * j + 1] / c);
    return v;
}

std::vector<mrpt::math::TPoint2D> TagFixedLagSmoother::history(size_t j) const {
    if (j >= m_cur.size()) throw std::out_of_range("TagFixedLagSmoother::history");
    std::vector<mrpt::math::TPoint2D> out;
    TQPoint v = m_old[j];
    out.push_back(m_anchor.world(v));
    for (uint64_t u = m_updates + 2 - m_count; u <= m_updates; u++)
        out.push_back(m_anchor.world(v = advance(v, u, j)));
    return out;
}

void TagFixedLagSmoother::recomputeEstimate() {
    // Line 24: the estimate comes from the smoothed set (uniform weights after
    // resampling).
    const double c = double(std::max<size_t>(m_count, 1));
    m_est = offsetEstimate(
        m_anchor, m_cur.size(),
        [&](size_t j) {
            return std::pair<double, double>(m_sum[2 * j] / c, m_sum[2 * j + 1] / c);
        },
        nullptr);
}

size_t TagFixedLagSmoother::memoryBytes() const {
    return sizeof(*this) +
           (m_cur.capacity() + m_old.capacity() + m_base.capacity()) * sizeof(TQPoint) +
           m_sum.capacity() * sizeof(int64_t) + m_chain.capacity();
}
}  // namespace rfir::models
