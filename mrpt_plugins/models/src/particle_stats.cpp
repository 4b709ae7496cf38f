/* rfir: weighted statistics of a 2D particle set. */
#include <rfir/models/particle_stats.h>
#include <rfir/models/resampling.h>

#include <stdexcept>

namespace rfir::models {
PointEstimate weightedEstimate(const std::vector<mrpt::math::TPoint2D>& pts,
                               const std::vector<double>& logWeights) {
    PointEstimate e;
    if (pts.empty()) return e;
    std::vector<double> w;
    if (logWeights.empty())
        w.assign(pts.size(), 1.0 / pts.size());
    else {
        if (logWeights.size() != pts.size())
            throw std::invalid_argument("weightedEstimate: size mismatch");
        w = normalisedWeights(logWeights);
    }
    double mx = 0, my = 0;
    for (size_t i = 0; i < pts.size(); i++) {
        mx += w[i] * pts[i].x;
        my += w[i] * pts[i].y;
    }
    double cxx = 0, cxy = 0, cyy = 0;
    for (size_t i = 0; i < pts.size(); i++) {
        const double dx = pts[i].x - mx, dy = pts[i].y - my;
        cxx += w[i] * dx * dx;
        cxy += w[i] * dx * dy;
        cyy += w[i] * dy * dy;
    }
    e.mean = {mx, my};
    e.cov(0, 0) = cxx;
    e.cov(0, 1) = e.cov(1, 0) = cxy;
    e.cov(1, 1) = cyy;
    return e;
}

}  // namespace rfir::models
