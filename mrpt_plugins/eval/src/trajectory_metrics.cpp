#include <rfir/common/trajectory_io.h>
#include <rfir/eval/trajectory_metrics.h>

#include <algorithm>
#include <cmath>

namespace rfir::eval {

mrpt::poses::CPose2D TAlignment::apply(const mrpt::poses::CPose2D& p) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {scale * (c * p.x() - s * p.y()) + tx, scale * (s * p.x() + c * p.y()) + ty,
            rfir::common::wrapToPi(p.phi() + theta)};
}

TAlignment alignPositions(const std::vector<TPosePair>& pairs, bool withScale) {
    TAlignment a;
    if (pairs.empty()) return a;
    double mex = 0, mey = 0, mgx = 0, mgy = 0;
    for (const auto& p : pairs) {
        mex += p.est.x(), mey += p.est.y(), mgx += p.gt.x(), mgy += p.gt.y();
    }
    const double n = double(pairs.size());
    mex /= n, mey /= n, mgx /= n, mgy /= n;
    // In 2D the SVD of Umeyama's cross-covariance reduces to one angle:
    // theta = atan2(sum e x g, sum e . g) over the centred points.
    double dot = 0, cross = 0, varE = 0;
    for (const auto& p : pairs) {
        const double ex = p.est.x() - mex, ey = p.est.y() - mey;
        const double gx = p.gt.x() - mgx, gy = p.gt.y() - mgy;
        dot += ex * gx + ey * gy;
        cross += ex * gy - ey * gx;
        varE += ex * ex + ey * ey;
    }
    if (varE > 1e-18) {
        a.theta = std::atan2(cross, dot);
        if (withScale) a.scale = std::hypot(dot, cross) / varE;
    }
    const double c = std::cos(a.theta), s = std::sin(a.theta);
    a.tx = mgx - a.scale * (c * mex - s * mey);
    a.ty = mgy - a.scale * (s * mex + c * mey);
    return a;
}

TRpeStats relativePoseError(const std::vector<TPosePair>& pairs, double delta,
                            RpeUnit unit) {
    TRpeStats r;
    r.delta = delta;
    if (pairs.size() < 2 || !(delta > 0)) return r;
    // Step coordinate of each pose: true travelled distance, or time.
    std::vector<double> u(pairs.size(), 0.0);
    for (size_t k = 1; k < pairs.size(); k++)
        u[k] = unit == RpeUnit::Seconds
                   ? pairs[k].t - pairs[0].t
                   : u[k - 1] + std::hypot(pairs[k].gt.x() - pairs[k - 1].gt.x(),
                                           pairs[k].gt.y() - pairs[k - 1].gt.y());
    double sumT = 0, sumT2 = 0, sumR = 0, sumR2 = 0;
    size_t j = 1;
    for (size_t i = 0; i + 1 < pairs.size(); i++) {
        j = std::max(j, i + 1);
        while (j < pairs.size() && u[j] - u[i] < delta * (1 - 1e-9)) j++;
        if (j == pairs.size()) break;  // u is non-decreasing: no later start fits
        const auto dG = pairs[j].gt - pairs[i].gt;
        const auto dP = pairs[j].est - pairs[i].est;
        const auto e = dP - dG;  // (G_i^-1 G_j)^-1 (P_i^-1 P_j)
        const double tr = std::hypot(e.x(), e.y());
        const double rot = std::abs(rfir::common::wrapToPi(e.phi()));
        r.pairs++;
        sumT += tr, sumT2 += tr * tr, sumR += rot, sumR2 += rot * rot;
        r.max_trans = std::max(r.max_trans, tr);
        r.max_rot = std::max(r.max_rot, rot);
    }
    if (r.pairs) {
        const double n = double(r.pairs);
        r.mean_trans = sumT / n, r.rmse_trans = std::sqrt(sumT2 / n);
        r.mean_rot = sumR / n, r.rmse_rot = std::sqrt(sumR2 / n);
    }
    return r;
}

}  // namespace rfir::eval
