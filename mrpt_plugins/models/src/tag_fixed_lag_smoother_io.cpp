/* rfir: the fixed-lag smoother's state on a stream, and the conversion of the
 * whole-history states of the map's version 0-2 streams. */
#include <rfir/models/tag_fixed_lag_smoother.h>

#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

namespace rfir::models {
namespace {
constexpr uint64_t kMaxParticles = 10000000, kMaxLag = 100000;

void writeQ(mrpt::serialization::CArchive& a, const std::vector<TQPoint>& v) {
    a.WriteAs<uint64_t>(v.size());
    for (const auto& q : v) a << q.x << q.y;
}
void readQ(mrpt::serialization::CArchive& a, std::vector<TQPoint>& v, uint64_t n) {
    if (a.ReadAs<uint64_t>() != n)
        throw std::runtime_error("TagFixedLagSmoother: state size mismatch");
    v.resize(n);
    for (auto& q : v) a >> q.x >> q.y;
}
}  // namespace

void TagFixedLagSmoother::writeState(mrpt::serialization::CArchive& a) const {
    a.WriteAs<uint8_t>(0);  // format of this estimator's state
    a.WriteAs<uint64_t>(m_p.numParticles);
    a.WriteAs<uint64_t>(m_p.lag);
    a << m_p.stepSigma;
    a.WriteAs<uint8_t>(static_cast<uint8_t>(m_p.resampling));
    a << m_anchor.x() << m_anchor.y() << m_stream;
    a.WriteAs<uint64_t>(m_updates);
    a.WriteAs<uint64_t>(m_count);
    a << m_frozen << m_width;
    writeQ(a, m_cur);
    writeQ(a, m_old);
    writeQ(a, m_base);
    for (int64_t s : m_sum) a << s;
    a.WriteBuffer(m_chain.data(), m_chain.size());
}

void TagFixedLagSmoother::readState(mrpt::serialization::CArchive& a) {
    if (a.ReadAs<uint8_t>() != 0)
        throw std::runtime_error("TagFixedLagSmoother: unknown state format");
    m_p.numParticles = a.ReadAs<uint64_t>();
    m_p.lag = a.ReadAs<uint64_t>();
    a >> m_p.stepSigma;
    m_p.resampling = static_cast<ResamplingScheme>(a.ReadAs<uint8_t>());
    double ax, ay;
    a >> ax >> ay >> m_stream;
    m_anchor = TAnchor({ax, ay});
    m_updates = a.ReadAs<uint64_t>();
    m_count = a.ReadAs<uint64_t>();
    a >> m_frozen >> m_width;
    if (m_p.lag == 0 || m_p.lag > kMaxLag || m_count == 0 || m_count > m_p.lag ||
        m_count > m_updates + 1 || (m_width != 1 && m_width != 2 && m_width != 4))
        throw std::runtime_error("TagFixedLagSmoother: inconsistent state header");
    // The particle count is the one of the current states (bounded first).
    const auto n = a.ReadAs<uint64_t>();
    if (n == 0 || n > kMaxParticles || n * m_p.lag > 4 * kMaxParticles)
        throw std::runtime_error("TagFixedLagSmoother: particle count out of range");
    m_cur.resize(n);
    for (auto& q : m_cur) a >> q.x >> q.y;
    readQ(a, m_old, n);
    const auto nb = a.ReadAs<uint64_t>();
    if (nb != 0 && nb != n)
        throw std::runtime_error("TagFixedLagSmoother: state size mismatch");
    m_base.resize(nb);
    for (auto& q : m_base) a >> q.x >> q.y;
    if (m_base.empty() && m_updates + 1 - m_count < m_frozen)
        throw std::runtime_error("TagFixedLagSmoother: frozen slots without base states");
    m_sum.resize(2 * n);
    for (auto& s : m_sum) a >> s;
    m_chain.resize(n * m_p.lag * m_width);
    a.ReadBufferFixEndianness(m_chain.data(), m_chain.size());
    recomputeEstimate();
}

void TagFixedLagSmoother::setLegacyState(const Params& p,
                                         const std::vector<mrpt::math::TPoint2D>& pts,
                                         const std::vector<mrpt::math::TPoint2D>& hist,
                                         size_t head, size_t count, uint64_t updates) {
    if (pts.empty() || p.lag == 0 || hist.size() != pts.size() * p.lag || head >= p.lag ||
        count > p.lag || count == 0 || count > updates + 1)
        throw std::invalid_argument("TagFixedLagSmoother::setState: bad sizes");
    m_p = p;
    initFromPoints(pts);
    const size_t n = pts.size(), lag = p.lag;
    m_updates = updates;
    m_count = count;
    // Row j's stored states are the `count` slots before `head` (a ring).
    std::vector<int64_t> sums(2 * n, 0);
    for (size_t j = 0; j < n; j++)
        for (size_t k = 0; k < count; k++) {
            const auto q = m_anchor.quantize(hist[j * lag + (head + lag - 1 - k) % lag]);
            sums[2 * j] += q.x;
            sums[2 * j + 1] += q.y;
        }
    freeze(sums);
    recomputeEstimate();
}

}  // namespace rfir::models
