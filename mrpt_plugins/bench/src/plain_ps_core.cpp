/* rfir-bench: the plain reference. PS-SLAM (004 Algorithm 1) written as the
 * cheapest honest single-file loop, with the stock slam_ps.ini settings:
 * M robot particles in contiguous arrays; per step one Cholesky of MRPT's
 * Gaussian odometry covariance, then per particle three Gaussian draws and one
 * pose composition (SPEC section 3); the step detection model (thesis eq.
 * 3.7) weighs the robot on the reads the revisit_all policy uses; ESS test and
 * systematic resampling; the tags are then updated from the posterior mean by
 * per-tag fixed-lag smoothers (J particles, `lag` stored states; thesis
 * Algorithm 2 lines 10-24). Its input is plain: an increment and (reader
 * square, tag ID) reads; it keeps its state in flat arrays (no heap
 * allocation, virtual call or string lookup per particle) and links no MRPT
 * library. What it leaves out: kidnap
 * resetting (it computes the best particle's mean log-likelihood, which the
 * check needs, but never reinjects), range-bearing landmarks and the map's
 * option switches. */
#include <rfir/bench/plain_ps_core.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

namespace rfir::bench {
namespace {
using TArea = TPlainArea;

/** Thesis eq. 3.7, step model, for the tag (tx, ty) read by reader `a` of
 * the robot at (x, y) with heading cos c, sin s. */
inline double stepLogLik(double x, double y, double c, double s, const TArea& a,
                         double tx, double ty, double logBeta) {
    const double dx = tx - x, dy = ty - y;
    const double ex = c * dx + s * dy - a.x, ey = -s * dx + c * dy - a.y;
    if (std::abs(ex) < a.hx && std::abs(ey) < a.hy) return 0.0;
    return logBeta - 0.5 * (ex * ex / (a.hx * a.hx) + ey * ey / (a.hy * a.hy));
}

/** Systematic resampling of n log-weights into idx (one uniform draw). */
void systematic(const double* lw, size_t n, rfir::models::TRandom& rng,
                std::vector<double>& w, std::vector<uint32_t>& idx) {
    double mx = -1e300, sum = 0;
    for (size_t i = 0; i < n; i++) mx = std::max(mx, lw[i]);
    w.resize(n);
    for (size_t i = 0; i < n; i++) sum += (w[i] = std::exp(lw[i] - mx));
    idx.resize(n);
    const double step = sum / double(n);
    double u = rng.drawUniform01() * step, acc = w[0];
    size_t j = 0;
    for (size_t k = 0; k < n; k++, u += step) {
        while (acc < u && j + 1 < n) acc += w[++j];
        idx[k] = uint32_t(j);
    }
}

/** One tag's fixed-lag smoother, flat: J states, J x lag ring of history. */
struct TTag {
    std::vector<double> px, py;     //!< current states
    std::vector<double> hx, hy;     //!< ring rows, J x lag
    size_t head = 0, count = 0;     //!< next slot, stored states
    double mx = 0, my = 0;          //!< estimate (mean of the smoothed set)
    double startX = 0, startY = 0;  //!< estimate when the current visit began
    uint64_t visits = 0, lastStep = 0;
    double lastTravel = 0;
};
}  // namespace

struct CPlainPsCore::TImpl {
    TPlainOptions o;
    rfir::models::TRandom rng;
    std::vector<double> x, y, phi, lw;  //!< robot particles
    std::vector<double> scratchW, scratchPhi, scratchTagW, tx, ty, txh, tyh;
    std::vector<TArea> scratchAreas;
    std::vector<uint32_t> idx;
    std::vector<TTag> tags;
    std::unordered_map<std::string, uint32_t> ids;
    std::string key;  //!< the looked-up ID (its buffer is reused)
    double logBeta = 0, meanX = 0, meanY = 0, meanPhi = 0;
    uint64_t steps = 0;
    double travel = 0, lastX = 0, lastY = 0;
    bool hasLast = false;
    double bestMeanLogLik = 0;  //!< what the kidnap check reads

    /** A read of tag t, grouped by tag: the readers that read it now. */
    struct TGroup {
        uint32_t tag;
        bool isNew;
        std::vector<TArea> areas;
    };
    std::vector<TGroup> groups;
    std::unordered_map<uint32_t, size_t> groupOf;

    void motion(const double* u);
    void group(const TPlainRead* reads, size_t n);
    void weigh();
    void resampleRobot();
    void meanPose();
    void insert();
    void initTag(TTag& t, const TArea& a);
    void updateTag(TTag& t, const std::vector<TArea>& areas, size_t first);
    void smooth(TTag& t);
};

CPlainPsCore::CPlainPsCore(const TPlainOptions& o) : m_(std::make_unique<TImpl>()) {
    m_->o = o;
    m_->logBeta = std::log(o.beta);
}
CPlainPsCore::~CPlainPsCore() = default;

void CPlainPsCore::reset(double x0, double y0, double phi0) {
    auto& m = *m_;
    m.rng.randomize(m.o.seed);
    m.x.assign(m.o.M, x0);
    m.y.assign(m.o.M, y0);
    m.phi.assign(m.o.M, phi0);
    m.lw.assign(m.o.M, 0.0);
    m.tags.clear();
    m.ids.clear();
    m.steps = 0;
    m.travel = 0;
    m.hasLast = false;
    m.meanX = x0, m.meanY = y0, m.meanPhi = phi0;
}

void CPlainPsCore::TImpl::motion(const double* u) {
    const auto g =
        rfir::models::OdometryGaussian::fromOdometry(u[0], u[1], u[2], o.motion);
    const size_t M = x.size();
    for (size_t i = 0; i < M; i++) g.propagate(rng, x[i], y[i], phi[i]);
}

void CPlainPsCore::TImpl::group(const TPlainRead* reads, size_t n) {
    groups.clear();
    groupOf.clear();
    for (size_t r = 0; r < n; r++) {
        const TPlainRead& rd = reads[r];
        key.assign(rd.tag.data(), rd.tag.size());
        auto [it, isNew] = ids.try_emplace(key, uint32_t(tags.size()));
        if (isNew) tags.emplace_back();
        auto [g, gNew] = groupOf.try_emplace(it->second, groups.size());
        if (gNew) groups.push_back({it->second, isNew, {}});
        groups[g->second].areas.push_back(rd.area);
    }
}

void CPlainPsCore::TImpl::weigh() {
    // revisit_all: a known tag weighs the robot with its current estimate on
    // a new visit, with the estimate at the visit's start on later re-reads of
    // a revisit, and not at all while first mapped.
    tx.clear(), ty.clear();
    std::vector<TArea>& used = scratchAreas;
    used.clear();
    for (const auto& g : groups) {
        if (g.isNew) continue;
        const TTag& t = tags[g.tag];
        const bool newVisit =
            t.visits == 0 ||
            (steps - t.lastStep >= 1 && travel - t.lastTravel >= o.revisitMinTravel);
        if (!newVisit && t.visits < 2) continue;
        for (const auto& a : g.areas) {
            used.push_back(a);
            tx.push_back(newVisit ? t.mx : t.startX);
            ty.push_back(newVisit ? t.my : t.startY);
        }
    }
    if (used.empty()) return;
    const size_t M = x.size(), K = used.size();
    double best = -1e300;
    for (size_t i = 0; i < M; i++) {
        const double c = std::cos(phi[i]), s = std::sin(phi[i]);
        double ll = 0;
        for (size_t k = 0; k < K; k++)
            ll += stepLogLik(x[i], y[i], c, s, used[k], tx[k], ty[k], logBeta);
        lw[i] += ll;
        best = std::max(best, ll);
    }
    bestMeanLogLik = best / double(K);
}

void CPlainPsCore::TImpl::resampleRobot() {
    const size_t M = x.size();
    double mx = -1e300;
    for (double v : lw) mx = std::max(mx, v);
    double s1 = 0, s2 = 0;
    for (size_t i = 0; i < M; i++) {
        lw[i] -= mx;
        const double w = std::exp(lw[i]);
        s1 += w, s2 += w * w;
    }
    if (s1 * s1 / s2 >= o.resampleEss * double(M)) return;
    systematic(lw.data(), M, rng, scratchW, idx);
    // In place: idx is sorted, so a gather through copies is enough.
    txh.assign(x.begin(), x.end()), tyh.assign(y.begin(), y.end());
    std::vector<double>& ph = scratchPhi;
    ph.assign(phi.begin(), phi.end());
    for (size_t k = 0; k < M; k++)
        x[k] = txh[idx[k]], y[k] = tyh[idx[k]], phi[k] = ph[idx[k]];
    std::fill(lw.begin(), lw.end(), 0.0);
}

void CPlainPsCore::TImpl::meanPose() {
    double sw = 0, sx = 0, sy = 0, sc = 0, ss = 0;
    for (size_t i = 0; i < x.size(); i++) {
        const double w = std::exp(lw[i]);
        sw += w, sx += w * x[i], sy += w * y[i];
        sc += w * std::cos(phi[i]), ss += w * std::sin(phi[i]);
    }
    meanX = sx / sw, meanY = sy / sw, meanPhi = std::atan2(ss, sc);
}

void CPlainPsCore::TImpl::initTag(TTag& t, const TArea& a) {
    // Alg. 2 lines 6-8: uniform over the reader's rectangle, first history.
    const size_t J = o.J;
    t.px.resize(J), t.py.resize(J);
    t.hx.assign(J * o.lag, 0.0), t.hy.assign(J * o.lag, 0.0);
    const double c = std::cos(meanPhi), s = std::sin(meanPhi);
    for (size_t j = 0; j < J; j++) {
        const double ox = a.x + rng.drawUniform(-a.hx, a.hx);
        const double oy = a.y + rng.drawUniform(-a.hy, a.hy);
        t.px[j] = meanX + c * ox - s * oy;
        t.py[j] = meanY + s * ox + c * oy;
        t.hx[j * o.lag] = t.px[j], t.hy[j * o.lag] = t.py[j];
    }
    t.head = 1 % o.lag, t.count = 1;
    smooth(t);
}

void CPlainPsCore::TImpl::updateTag(TTag& t, const std::vector<TArea>& areas,
                                    size_t first) {
    // Alg. 2 lines 11-19: random step, weigh, store, resample with histories.
    const size_t J = o.J, L = o.lag;
    const double c = std::cos(meanPhi), s = std::sin(meanPhi);
    scratchW.resize(J);
    std::vector<double>& lwT = scratchTagW;
    lwT.resize(J);
    for (size_t j = 0; j < J; j++) {
        t.px[j] += o.stepSigma * rng.drawGaussian1D_normalized();
        t.py[j] += o.stepSigma * rng.drawGaussian1D_normalized();
        double ll = 0;
        for (size_t k = first; k < areas.size(); k++)
            ll += stepLogLik(meanX, meanY, c, s, areas[k], t.px[j], t.py[j], logBeta);
        lwT[j] = ll;
        t.hx[j * L + t.head] = t.px[j], t.hy[j * L + t.head] = t.py[j];
    }
    t.head = (t.head + 1) % L;
    t.count = std::min(t.count + 1, L);
    systematic(lwT.data(), J, rng, scratchW, idx);
    txh.resize(J * L), tyh.resize(J * L), tx.resize(J), ty.resize(J);
    for (size_t k = 0; k < J; k++) {
        tx[k] = t.px[idx[k]], ty[k] = t.py[idx[k]];
        std::copy_n(t.hx.begin() + idx[k] * L, L, txh.begin() + k * L);
        std::copy_n(t.hy.begin() + idx[k] * L, L, tyh.begin() + k * L);
    }
    t.px.swap(tx), t.py.swap(ty), t.hx.swap(txh), t.hy.swap(tyh);
    smooth(t);
}

void CPlainPsCore::TImpl::smooth(TTag& t) {
    // Line 20: each smoothed particle is the mean of its stored states; the
    // estimate is their mean (lines 21-24; the covariance costs one more pass,
    // which map.txt needs only at the end).
    const size_t L = o.lag;
    double sx = 0, sy = 0;
    for (size_t j = 0; j < t.px.size(); j++)
        for (size_t k = 0; k < t.count; k++) {
            const size_t slot = (t.head + L - 1 - k) % L;
            sx += t.hx[j * L + slot], sy += t.hy[j * L + slot];
        }
    const double n = double(t.px.size() * t.count);
    t.mx = sx / n, t.my = sy / n;
}

void CPlainPsCore::TImpl::insert() {
    // The visit test reads the track as it was before this observation.
    const double travelBefore = travel;
    if (hasLast) travel += std::hypot(meanX - lastX, meanY - lastY);
    hasLast = true, lastX = meanX, lastY = meanY;
    const uint64_t before = steps++;
    for (const auto& g : groups) {
        TTag& t = tags[g.tag];
        if (g.isNew) initTag(t, g.areas[0]);
        const bool newVisit =
            t.visits == 0 || (before - t.lastStep >= 1 &&
                              travelBefore - t.lastTravel >= o.revisitMinTravel);
        if (newVisit) t.visits++, t.startX = t.mx, t.startY = t.my;
        t.lastStep = steps, t.lastTravel = travel;
        const size_t first = g.isNew ? 1 : 0;
        if (first < g.areas.size()) updateTag(t, g.areas, first);
    }
}

void CPlainPsCore::step(const double* u, const TPlainRead* reads, size_t n) {
    auto& m = *m_;
    if (u) m.motion(u);
    m.group(reads, n);
    m.weigh();
    m.resampleRobot();
    m.meanPose();
    m.insert();
}

size_t CPlainPsCore::tagsMapped() const {
    return m_->tags.size();
}

void CPlainPsCore::meanPose(double& x, double& y, double& phi) const {
    x = m_->meanX, y = m_->meanY, phi = m_->meanPhi;
}

}  // namespace rfir::bench
