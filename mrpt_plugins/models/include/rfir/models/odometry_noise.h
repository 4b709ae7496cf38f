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
    void propagate(TRandom& rng, double& x, double& y, double& phi, double c,
                   double s) const {
        double ix, iy, iphi;
        draw(rng, ix, iy, iphi);
        x += c * ix - s * iy;
        y += s * ix + c * iy;
        phi += iphi;
        // CPose2D's composition wraps into (-pi, pi].
        if (phi > M_PI || phi <= -M_PI) {
            phi = std::remainder(phi, 2 * M_PI);
            if (phi <= -M_PI) phi += 2 * M_PI;
        }
    }

    const double* covariance() const { return m_C; }  //!< row-major 3x3

  private:
    void factor();
    double m_mean[3] = {0, 0, 0};
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
