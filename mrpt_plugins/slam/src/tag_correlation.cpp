#include <rfir/slam/tag_correlation.h>

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace rfir::slam {
namespace {
double positionVariance(const Eigen::Matrix<double, 2, 3>& C) {
    return 0.5 * std::abs(C(0, 0) + C(1, 1));
}
}  // namespace

TPoseMoments CPoseMomentSums::moments() const {
    TPoseMoments m;
    if (!(m_w > 0)) return m;
    const Eigen::Vector3d mean(m_x / m_w, m_y / m_w, m_p / m_w);
    Eigen::Matrix3d second;
    second << m_xx, m_xy, m_xp, m_xy, m_yy, m_yp, m_xp, m_yp, m_pp;
    m.x = m_rx + mean.x();
    m.y = m_ry + mean.y();
    m.phi = mrpt::math::wrapToPi(m_rp + mean.z());
    m.cov = second / m_w - mean * mean.transpose();
    return m;
}

void CTagRobotCorrelation::add(const std::string& id, bool landmark, double tx, double ty,
                               const TPoseMoments& r) {
    Eigen::Matrix<double, 2, 3> J;
    J << 1, 0, -(ty - r.y), 0, 1, tx - r.x;
    TEntry e{id, landmark, J * r.cov, J * r.cov * J.transpose(), r.x, r.y};
    if (positionVariance(e.C) < m_minVar) return;
    m_active.push_back(e);
    if (m_active.size() > m_maxTags) m_active.pop_front();
}

size_t CTagRobotCorrelation::correct(const TPoseMoments& before,
                                     const TPoseMoments& after, const TShift& shift) {
    if (m_active.empty()) return 0;
    const Eigen::Matrix3d& P = before.cov;
    // A weighing that did not narrow the cloud (a split, a flat weighing) is
    // no Gaussian update; a collapsed cloud has no usable inverse.
    if (!(after.cov.determinant() < P.determinant()) || P.determinant() <= 1e-30)
        return 0;
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(P);
    const Eigen::Vector3d d(after.x - before.x, after.y - before.y,
                            mrpt::math::wrapToPi(after.phi - before.phi));
    const Eigen::Vector3d g = ldlt.solve(d);
    const Eigen::Matrix3d shrink = ldlt.solve(after.cov);
    size_t moved = 0;
    for (auto& e : m_active) {
        // C carried along the mean path since its reference: the product of
        // the motion Jacobians is the shear of the displacement.
        Eigen::Matrix3d Ft = Eigen::Matrix3d::Identity();
        Ft(2, 0) = -(before.y - e.refY);
        Ft(2, 1) = before.x - e.refX;
        Eigen::Matrix<double, 2, 3> Ct = e.C * Ft;
        const double explained = (Ct * ldlt.solve(Ct.transpose())).trace();
        if (explained > e.T.trace()) Ct *= std::sqrt(e.T.trace() / explained);
        const Eigen::Vector2d s = Ct * g;
        shift(e.id, e.landmark, s.x(), s.y());
        // The tag's variance drops by what the correction explained.
        e.T -= Ct * ldlt.solve((P - after.cov) * ldlt.solve(Ct.transpose()));
        e.T = 0.5 * (e.T + e.T.transpose());
        e.C = Ct * shrink;
        e.refX = after.x;
        e.refY = after.y;
        moved++;
    }
    m_active.erase(std::remove_if(m_active.begin(), m_active.end(),
                                  [&](const TEntry& e) {
                                      return positionVariance(e.C) < m_minVar ||
                                             0.5 * e.T.trace() < m_minVar;
                                  }),
                   m_active.end());
    return moved;
}

void CTagRobotCorrelation::drop(const std::vector<std::string>& ids) {
    if (ids.empty() || m_active.empty()) return;
    m_active.erase(std::remove_if(m_active.begin(), m_active.end(),
                                  [&](const TEntry& e) {
                                      return std::find(ids.begin(), ids.end(), e.id) !=
                                             ids.end();
                                  }),
                   m_active.end());
}

void CMapCorrection::clear() {
    m_corr.clear();
    m_pending.clear();
    m_pendingIds.clear();
}

void CMapCorrection::weighed(const TPoseMoments& before, const TPoseMoments& after,
                             const std::vector<std::string>& ids) {
    m_pending.emplace_back(before, after);
    m_pendingIds.insert(m_pendingIds.end(), ids.begin(), ids.end());
}

size_t CMapCorrection::settle(bool reset, bool mapping,
                              const CTagRobotCorrelation::TShift& shift) {
    if (reset) {
        clear();
        return 0;
    }
    if (m_pending.empty() || !mapping) return 0;
    m_corr.drop(m_pendingIds);
    size_t moved = 0;
    for (const auto& [b, a] : m_pending) moved += m_corr.correct(b, a, shift);
    m_pending.clear();
    m_pendingIds.clear();
    return moved;
}

}  // namespace rfir::slam
