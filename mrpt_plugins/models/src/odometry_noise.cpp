/* rfir: the odometry noise model (SPEC section 3). */
#include <rfir/models/odometry_noise.h>

#include <algorithm>

namespace rfir::models {
OdometryGaussian OdometryGaussian::fromOdometry(double dx, double dy, double dphi,
                                                const OdometryNoiseParams& p) {
    double sxy, sphi;
    p.stds(dx, dy, dphi, sxy, sphi);
    const double vxy = sxy * sxy, vphi = sphi * sphi;
    // J = [c -s j02; s c j12; 0 0 1] with c, s of dphi/2 (MRPT's H and its
    // heading column); C = J diag(vxy, vxy, vphi) J^T.
    const double c = std::cos(0.5 * dphi), s = std::sin(0.5 * dphi);
    const double j02 = -s * dx - c * dy, j12 = c * dx - s * dy;
    const double C[9] = {vxy + j02 * j02 * vphi,
                         j02 * j12 * vphi,
                         j02 * vphi,
                         j02 * j12 * vphi,
                         vxy + j12 * j12 * vphi,
                         j12 * vphi,
                         j02 * vphi,
                         j12 * vphi,
                         vphi};
    return fromCovariance(dx, dy, dphi, C);
}

OdometryGaussian OdometryGaussian::fromCovariance(double dx, double dy, double dphi,
                                                  const double C[9]) {
    OdometryGaussian g;
    g.m_mean[0] = dx;
    g.m_mean[1] = dy;
    g.m_mean[2] = dphi;
    std::copy(C, C + 9, g.m_C);
    g.factor();
    return g;
}

void OdometryGaussian::factor() {
    // 3x3 Cholesky; a zero pivot (a zero variance) gives a zero column, so a
    // degenerate covariance draws along the directions it has.
    const double* C = m_C;
    const auto root = [](double v) { return v > 0 ? std::sqrt(v) : 0.0; };
    const double l00 = root(C[0]);
    const double l10 = l00 > 0 ? C[3] / l00 : 0;
    const double l20 = l00 > 0 ? C[6] / l00 : 0;
    const double l11 = root(C[4] - l10 * l10);
    const double l21 = l11 > 0 ? (C[7] - l20 * l10) / l11 : 0;
    const double l22 = root(C[8] - l20 * l20 - l21 * l21);
    const double L[6] = {l00, l10, l11, l20, l21, l22};
    std::copy(L, L + 6, m_L);
    m_cosMean = std::cos(m_mean[2]);
    m_sinMean = std::sin(m_mean[2]);
}

}  // namespace rfir::models
