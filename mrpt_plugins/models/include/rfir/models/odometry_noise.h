/* rfir: the odometry noise model, written once (SPEC section 3; 003 eq. 7,
 * thesis eq. 3.6): an odometry increment u = (dx, dy, dphi) is the mean of a
 * Gaussian pose change. The robot filters draw from it, the graph smoother
 * weighs its residuals with it, and the IR localizer draws from it with its
 * own covariance. */
#pragma once

#include <rfir/models/random.h>
#include <rfir/models/read_model.h>

#include <cmath>

namespace rfir::models {
/** MRPT's Gaussian odometry model (CActionRobotMovement2D, mmGaussian):
 * std_xy = a1 d + a2 |dphi| + min_std_xy, std_phi = a3 d + a4 |dphi| +
 * min_std_phi, d = |(dx, dy)|. */
struct OdometryNoiseParams {
    double a1 = 0.05, a2 = 0.001, a3 = 0.02, a4 = 0.02;
    double minStdXY = 0.001, minStdPhi = 0.002;

    /** The two standard deviations of an increment (xy, heading). */
    void stds(double dx, double dy, double dphi, double& sxy, double& sphi) const {
        const double d = std::hypot(dx, dy), a = std::abs(dphi);
        sxy = a1 * d + a2 * a + minStdXY;
        sphi = a3 * d + a4 * a + minStdPhi;
    }
};

/** cos and sin of a small angle a (|a| <= 0.5 rad) by their Taylor series
 * to degree 16 (truncation below 1e-20, under the rounding of the result);
 * false, and c, s untouched, for a larger or non-finite a. */
inline bool smallAngleCosSin(double a, double& c, double& s) {
    if (!(std::abs(a) <= 0.5)) return false;
    const double a2 = a * a;
    // Horner in a^2 of sum (-1)^k a^2k / (2k)! and a * sum (-1)^k a^2k / (2k+1)!.
    double pc = 1.0 / 20922789888000.0, ps = 1.0 / 355687428096000.0;  // 1/16!, 1/17!
    constexpr double kC[8] = {
        1.0 / 87178291200.0, 1.0 / 479001600.0, 1.0 / 3628800.0, 1.0 / 40320.0,
        1.0 / 720.0,         1.0 / 24.0,        1.0 / 2.0,       1.0};  // 1/14! ... 1/0!
    constexpr double kS[8] = {1.0 / 1307674368000.0,
                              1.0 / 6227020800.0,
                              1.0 / 39916800.0,
                              1.0 / 362880.0,
                              1.0 / 5040.0,
                              1.0 / 120.0,
                              1.0 / 6.0,
                              1.0};  // 1/15! ... 1/1!
    for (int k = 0; k < 8; k++) {
        pc = kC[k] - a2 * pc;
        ps = kS[k] - a2 * ps;
    }
    c = pc;
    s = a * ps;
    return true;
}

/** A Gaussian pose change: mean (the increment) and the lower Cholesky factor
 * L of its covariance, computed once per step; a draw is mean + L n with n
 * three standard normal draws. */
class OdometryGaussian {
  public:
    /** MRPT's mmGaussian covariance (computeFromOdometry_modelGaussian):
     * J diag(sxy^2, sxy^2, sphi^2) J^T, J the rotation by dphi/2 with the
     * heading column of the arc's Jacobian. */
    static OdometryGaussian fromOdometry(double dx, double dy, double dphi,
                                         const OdometryNoiseParams& p);
    /** Any covariance C (row-major 3x3, symmetric positive semi-definite). */
    static OdometryGaussian fromCovariance(double dx, double dy, double dphi,
                                           const double C[9]);

    /** One draw of the pose change. */
    void draw(TRandom& rng, double& x, double& y, double& phi) const {
        const double n0 = rng.drawGaussian1D_normalized();
        const double n1 = rng.drawGaussian1D_normalized();
        const double n2 = rng.drawGaussian1D_normalized();
        x = m_mean[0] + m_L[0] * n0;
        y = m_mean[1] + m_L[1] * n0 + m_L[2] * n1;
        phi = m_mean[2] + m_L[3] * n0 + m_L[4] * n1 + m_L[5] * n2;
    }
    /** Moves pose (x, y, phi) by one draw: pose (+) draw, heading wrapped to
     * (-pi, pi] as CPose2D's composition does. */
    void propagate(TRandom& rng, double& x, double& y, double& phi) const {
        propagate(rng, x, y, phi, std::cos(phi), std::sin(phi));
    }
    /** The same, given c, s = cos(phi), sin(phi). */
    void propagate(TRandom& rng, double& x, double& y, double& phi, double c, double s,
                   double extraTurn = 0) const {
        compose(rng, x, y, phi, c, s, extraTurn);
    }
    /** Length of the mean increment's translation. */
    double distance() const { return std::hypot(m_mean[0], m_mean[1]); }

    /** The same, also carrying the heading's cos and sin: c, s are
     * cos(phi), sin(phi) on entry and those of the new heading on return,
     * by angle addition (the increment's mean turn: one sincos per step in
     * the factorisation; its noise: smallAngleCosSin) instead of one sincos
     * per particle, the largest per-particle cost of the filters. Within a
     * few ulp of std::cos / std::sin per step; a caller keeping c, s over
     * many steps recomputes them now and then (CParticlePose2D). */
    void propagateCarryingHeading(TRandom& rng, double& x, double& y, double& phi,
                                  double& c, double& s, double extraTurn = 0) const {
        const double iphi = compose(rng, x, y, phi, c, s, extraTurn);
        double cn, sn;  // of the turn iphi
        if (smallAngleCosSin(iphi - m_mean[2], cn, sn)) {
            const double ct = m_cosMean * cn - m_sinMean * sn;
            sn = m_sinMean * cn + m_cosMean * sn;
            cn = ct;
        } else {
            cn = std::cos(iphi);
            sn = std::sin(iphi);
        }
        const double c2 = c * cn - s * sn;
        s = s * cn + c * sn;
        c = c2;
    }

    const double* covariance() const { return m_C; }  //!< row-major 3x3

  private:
    /** pose (+) one draw, heading wrapped to (-pi, pi] as CPose2D's
     * composition does; c, s of the heading before. Returns the drawn turn. */
    double compose(TRandom& rng, double& x, double& y, double& phi, double c, double s,
                   double extraTurn) const {
        double ix, iy, iphi;
        draw(rng, ix, iy, iphi);
        iphi += extraTurn;
        x += c * ix - s * iy;
        y += s * ix + c * iy;
        phi += iphi;
        if (phi > M_PI || phi <= -M_PI) {
            phi = std::remainder(phi, 2 * M_PI);
            if (phi <= -M_PI) phi += 2 * M_PI;
        }
        return iphi;
    }
    void factor();
    double m_mean[3] = {0, 0, 0};
    double m_cosMean = 1, m_sinMean = 0;  //!< of the mean turn m_mean[2]
    double m_C[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    double m_L[6] = {0, 0, 0, 0, 0, 0};  //!< L00, L10, L11, L20, L21, L22
};

/** The odometry model h(prev, cur), any scalar (double, ceres::Jet): the
 * increment u = prev^-1 (+) cur that two poses (x, y, phi) imply, cur's
 * position in prev's frame and the turn, not wrapped; c, s = cos, sin of
 * prev's heading. The smoothers' odometry factors compare it with the
 * measured increment. */
template <class T>
void odometryModel(const T* prev, const T* cur, const T& c, const T& s, T* u) {
    worldToRobotFrame(prev[0], prev[1], c, s, cur[0], cur[1], u[0], u[1]);
    u[2] = cur[2] - prev[2];
}

/** Residual weights of the smoother's odometry factor: 1/std of the xy and
 * heading residuals of increment u (the same stds the filters draw with). */
inline void odometryInformationSqrt(const OdometryNoiseParams& p, double dx, double dy,
                                    double dphi, double& wxy, double& wphi) {
    double sxy, sphi;
    p.stds(dx, dy, dphi, sxy, sphi);
    wxy = 1.0 / sxy;
    wphi = 1.0 / sphi;
}

}  // namespace rfir::models
