/* rfir: compact storage of a tag's particle states: 32-bit integer offsets in
 * steps of 2^-20 m (0.95 um) from a per-tag anchor, and the counter-based
 * Gaussian stream the fixed-lag smoother regenerates its steps from. */
#pragma once

#include <rfir/models/particle_stats.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace rfir::models {
/** One state: offset from the anchor in quanta. */
struct TQPoint {
    int32_t x = 0, y = 0;
};

/** The quantum is a power of two, so that anchor + k * q is exact in double:
 * states given on the grid (e.g. 0, 10, 20 m) come back bit for bit, and the
 * integer running sums of the smoother stay exact over any number of steps.
 * Range: +-2048 m around the anchor (beyond: a clear error, never a wrap). */
class TAnchor {
  public:
    static constexpr double kQuantum = 1.0 / 1048576.0;  // 2^-20 m
    static constexpr double kInvQuantum = 1048576.0;

    TAnchor() = default;
    /** Anchor at p, itself rounded to the grid. */
    explicit TAnchor(const mrpt::math::TPoint2D& p)
        : m_x(std::round(p.x * kInvQuantum) * kQuantum),
          m_y(std::round(p.y * kInvQuantum) * kQuantum) {}

    double x() const { return m_x; }
    double y() const { return m_y; }
    /** Nearest grid point of p as an offset; throws std::range_error (naming
     * the point) beyond the range. */
    TQPoint quantize(const mrpt::math::TPoint2D& p) const;
    mrpt::math::TPoint2D world(const TQPoint& q) const {
        return {m_x + q.x * kQuantum, m_y + q.y * kQuantum};
    }
    /** World point of an offset given in (fractional) quanta. */
    mrpt::math::TPoint2D world(double qx, double qy) const {
        return {m_x + qx * kQuantum, m_y + qy * kQuantum};
    }

  private:
    double m_x = 0, m_y = 0;
};

/** Anchor at the mean of pts (keeps offsets small, whatever the map's size). */
TAnchor anchorAtMean(const std::vector<mrpt::math::TPoint2D>& pts);

/** Weighted mean and covariance of n offsets (fractional quanta, from xy(i))
 * with normalised weights w (nullptr: uniform); covariance as in
 * weightedEstimate (biased). */
template <class XY>
PointEstimate offsetEstimate(const TAnchor& a, size_t n, XY&& xy, const double* w) {
    PointEstimate e;
    if (n == 0) return e;
    double mx = 0, my = 0;
    for (size_t i = 0; i < n; i++) {
        const auto [px, py] = xy(i);
        const double wi = w ? w[i] : 1.0 / double(n);
        mx += wi * px;
        my += wi * py;
    }
    double cxx = 0, cxy = 0, cyy = 0;
    for (size_t i = 0; i < n; i++) {
        const auto [px, py] = xy(i);
        const double wi = w ? w[i] : 1.0 / double(n);
        const double dx = px - mx, dy = py - my;
        cxx += wi * dx * dx;
        cxy += wi * dx * dy;
        cyy += wi * dy * dy;
    }
    constexpr double q2 = TAnchor::kQuantum * TAnchor::kQuantum;
    e.mean = a.world(mx, my);
    e.cov(0, 0) = cxx * q2;
    e.cov(0, 1) = e.cov(1, 0) = cxy * q2;
    e.cov(1, 1) = cyy * q2;
    return e;
}

/** Counter-based N(0, sigma^2) pair in quanta for (stream, slot, particle):
 * splitmix64 of the counter, then Box-Muller. A draw can be made again at any
 * later time, which is what lets the smoother keep no per-state noise. */
TQPoint streamGaussian(uint64_t stream, uint64_t slot, uint64_t particle,
                       double sigmaQuanta);

/** splitmix64 finaliser (Steele, Lea, Flood 2014). */
inline uint64_t splitmix64(uint64_t z) {
    z += 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

}  // namespace rfir::models
