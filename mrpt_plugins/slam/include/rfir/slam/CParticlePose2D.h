/* rfir: the pose a robot particle holds. MRPT's CPose2D caches its heading's
 * cos and sin, but every move resets the cache, so each particle paid one
 * sincos per step: the largest single cost of the robot filters (a third of
 * PS-SLAM's step at M = 5000, measured with perf on the 300 s random-path
 * log). This pose carries the cached values through the motion draw by angle
 * addition (OdometryGaussian::propagateCarryingHeading) and reads them
 * inline. */
#pragma once

#include <mrpt/poses/CPose2D.h>
#include <rfir/models/odometry_noise.h>

namespace rfir::slam {
class CParticlePose2D : public mrpt::poses::CPose2D {
  public:
    CParticlePose2D() = default;
    /** Implicit: particles are set from (and read as) MRPT poses. */
    CParticlePose2D(const mrpt::poses::CPose2D& p) : mrpt::poses::CPose2D(p) {}
    CParticlePose2D(double x, double y, double phi) : mrpt::poses::CPose2D(x, y, phi) {}

    /** @name The cached cos and sin of the heading, read inline (they hide
     * CPose2D's, which call into MRPT to check the cache; same values).
     * @{ */
    double phi_cos() const {
        if (!m_cossin_uptodate) update_cached_cos_sin();
        return m_cosphi;
    }
    double phi_sin() const {
        if (!m_cossin_uptodate) update_cached_cos_sin();
        return m_sinphi;
    }
    /** @} */

    /** Moves the pose by one draw of g (SPEC section 3). `exact`: the new
     * heading's cos and sin are recomputed from it (by the next phi_cos)
     * instead of carried; the particle sets do so every few steps, so that
     * the rounding of the carried values (a few ulp per step) cannot build
     * up. The draws are the same either way. `extra`: a turn added to the
     * draw's (a particle's heading drift over the increment). */
    void move(const rfir::models::OdometryGaussian& g, rfir::models::TRandom& rng,
              bool exact, double extra = 0) {
        double x = m_coords[0], y = m_coords[1], phi = m_phi;
        double c = phi_cos(), s = phi_sin();
        if (exact) {
            g.propagate(rng, x, y, phi, c, s, extra);
            m_coords[0] = x;
            m_coords[1] = y;
            this->phi(phi);  // resets the cache
            return;
        }
        g.propagateCarryingHeading(rng, x, y, phi, c, s, extra);
        m_coords[0] = x;
        m_coords[1] = y;
        m_phi = phi;
        m_cosphi = c;
        m_sinphi = s;
        m_cossin_uptodate = true;
    }
};
}  // namespace rfir::slam
