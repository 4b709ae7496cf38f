#include <rfir/eval/metrics.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace rfir::eval {
using rfir::common::TMapEntry;
using rfir::common::TPath2D;

namespace {
constexpr double kTimeTol = 1e-6;  // s: stamps written with 6 decimals in TUM
}

std::optional<mrpt::poses::CPose2D> interpolatePose(const TPath2D& gt, double t) {
    if (gt.empty() || t < gt.front().t - kTimeTol || t > gt.back().t + kTimeTol)
        return std::nullopt;
    auto it = std::lower_bound(gt.begin(), gt.end(), t,
                               [](const auto& p, double v) { return p.t < v; });
    if (it == gt.end()) return gt.back().pose;
    if (std::abs(it->t - t) <= kTimeTol || it == gt.begin()) return it->pose;
    const auto& a = *(it - 1);
    if (std::abs(a.t - t) <= kTimeTol) return a.pose;
    const auto& b = *it;
    return rfir::common::interpolatePose2D(a.pose, b.pose, (t - a.t) / (b.t - a.t));
}

void checkPath(const TPath2D& p, const std::string& what) {
    if (p.empty()) throw std::runtime_error(what + ": the path has no pose");
    for (size_t i = 1; i < p.size(); i++)
        if (p[i].t < p[i - 1].t)
            throw std::runtime_error(
                what + ": poses are not in non-decreasing time (pose " +
                std::to_string(i + 1) + " at t=" + std::to_string(p[i].t) +
                " after t=" + std::to_string(p[i - 1].t) + ")");
}

TErrorStats statsOf(const std::vector<TPoseError>& errs) {
    TErrorStats s;
    s.count = errs.size();
    for (const auto& e : errs) {
        const double ax = std::abs(e.dx), ay = std::abs(e.dy), at = std::abs(e.dtheta);
        s.mean_dx += ax;
        s.mean_dy += ay;
        s.mean_dtheta += at;
        s.mean_dist += e.dist;
        s.max_dx = std::max(s.max_dx, ax);
        s.max_dy = std::max(s.max_dy, ay);
        s.max_dtheta = std::max(s.max_dtheta, at);
        s.max_dist = std::max(s.max_dist, e.dist);
        s.rmse_dist += e.dist * e.dist;
        s.rmse_dtheta += e.dtheta * e.dtheta;
    }
    if (s.count) {
        const double n = double(s.count);
        s.rmse_dist = std::sqrt(s.rmse_dist / n);
        s.rmse_dtheta = std::sqrt(s.rmse_dtheta / n);
        s.mean_dx /= n;
        s.mean_dy /= n;
        s.mean_dtheta /= n;
        s.mean_dist /= n;
    }
    return s;
}

std::vector<TErrorStats> segmentStats(const std::vector<TPoseError>& errs, double t0,
                                      double t1, size_t n) {
    if (n == 0) throw std::invalid_argument("segmentStats: no segment asked for");
    if (!(t1 > t0)) throw std::invalid_argument("segmentStats: the time span is empty");
    std::vector<std::vector<TPoseError>> bins(n);
    for (const auto& e : errs) {
        const double f = std::floor(double(n) * (e.t - t0) / (t1 - t0));
        bins[size_t(std::clamp(f, 0.0, double(n - 1)))].push_back(e);
    }
    std::vector<TErrorStats> out;
    for (const auto& b : bins) out.push_back(statsOf(b));
    return out;
}

namespace {
TPoseError poseError(double t, const mrpt::poses::CPose2D& e,
                     const mrpt::poses::CPose2D& g) {
    TPoseError pe;
    pe.t = t;
    pe.dx = e.x() - g.x();
    pe.dy = e.y() - g.y();
    pe.dtheta = wrapToPi(e.phi() - g.phi());
    pe.dist = std::hypot(pe.dx, pe.dy);
    return pe;
}
}  // namespace

namespace {
/** The evo-like figures of a run from its compared pose pairs. */
void addTrajectoryMetrics(TRobotErrors& r) {
    r.alignment = alignPositions(r.pairs);
    std::vector<TPoseError> aligned;
    aligned.reserve(r.pairs.size());
    for (const auto& p : r.pairs)
        aligned.push_back(poseError(p.t, r.alignment.apply(p.est), p.gt));
    r.aligned = statsOf(aligned);
    r.rpePerMetre = relativePoseError(r.pairs, 1.0, RpeUnit::Metres);
    r.rpePerSecond = relativePoseError(r.pairs, 1.0, RpeUnit::Seconds);
}
}  // namespace

TRobotErrors computeRobotErrors(const TPath2D& est, const TPath2D& gt,
                                Association assoc) {
    const bool atTruth = assoc == Association::AtTruthTimes;
    if (est.empty()) throw std::runtime_error("estimated path: the path has no pose");
    checkPath(gt, "ground-truth path");
    if (atTruth) checkPath(est, "estimated path");
    // `samples` are paired with `other` interpolated at their times.
    const TPath2D& samples = atTruth ? gt : est;
    const TPath2D& other = atTruth ? est : gt;
    TRobotErrors r;
    r.perPose.reserve(samples.size());
    r.pairs.reserve(samples.size());
    for (const auto& p : samples) {
        const auto q = interpolatePose(other, p.t);
        if (!q) {
            r.skipped++;
            continue;
        }
        const mrpt::poses::CPose2D& e = atTruth ? *q : p.pose;
        const mrpt::poses::CPose2D& g = atTruth ? p.pose : *q;
        r.perPose.push_back(poseError(p.t, e, g));
        r.pairs.push_back({p.t, e, g});
    }
    if (r.perPose.empty())
        throw std::runtime_error(
            std::string(atTruth ? "no ground-truth pose lies within the estimate's"
                                : "no estimated pose lies within the ground truth's") +
            " time span (ground truth [" + std::to_string(gt.front().t) + ", " +
            std::to_string(gt.back().t) + "] s, estimate [" +
            std::to_string(est.front().t) + ", " + std::to_string(est.back().t) + "] s)");
    r.stats = statsOf(r.perPose);
    addTrajectoryMetrics(r);
    return r;
}

namespace {
TMapEntry::Kind inferKind(const rfir::common::TMapFile& est) {
    bool tag = false, lm = false;
    for (const auto& e : est) {
        tag |= e.kind == TMapEntry::Kind::Tag;
        lm |= e.kind == TMapEntry::Kind::Landmark;
    }
    if (tag && lm)
        throw std::runtime_error(
            "the estimated map holds both tag and landmark records: say which to "
            "evaluate");
    return lm ? TMapEntry::Kind::Landmark : TMapEntry::Kind::Tag;
}
}  // namespace

TMapErrors computeMapErrors(const rfir::common::TMapFile& est,
                            const rfir::common::TMapFile& gt,
                            std::optional<TMapEntry::Kind> kind) {
    TMapErrors m;
    m.kind = kind ? *kind : inferKind(est);
    std::map<std::string, const TMapEntry*> truth;
    for (const auto& g : gt)
        if (g.kind == m.kind) truth[g.id] = &g;
    m.total = truth.size();
    std::vector<TPoseError> errs;
    for (const auto& e : est) {
        if (e.kind != m.kind) continue;
        const auto it = truth.find(e.id);
        if (it == truth.end()) {
            m.unknownIds.push_back(e.id);
            continue;
        }
        TLandmarkError le;
        le.id = e.id;
        le.dx = e.x - it->second->x;
        le.dy = e.y - it->second->y;
        le.dist = std::hypot(le.dx, le.dy);
        m.perLandmark.push_back(le);
        TPoseError pe;
        pe.dx = le.dx;
        pe.dy = le.dy;
        pe.dist = le.dist;
        errs.push_back(pe);
    }
    m.mapped = m.perLandmark.size();
    m.stats = statsOf(errs);
    return m;
}

void setPassedOver(TMapErrors& m, const std::set<std::string>& passedIds,
                   const rfir::common::TMapFile& est) {
    m.passedOver = passedIds.size();
    size_t n = 0;
    for (const auto& e : est)
        if (e.kind == m.kind && passedIds.count(e.id)) n++;
    m.mappedOfPassedOver = n;
}

TPath2D alignOdometryAtStart(const TPath2D& odometry, const TPath2D& gt) {
    checkPath(gt, "ground-truth path");
    size_t k = 0;
    std::optional<mrpt::poses::CPose2D> g0;
    for (; k < odometry.size() && !g0; k++) g0 = interpolatePose(gt, odometry[k].t);
    if (!g0)
        throw std::runtime_error(
            "no odometry pose lies within the ground truth's time span");
    k--;  // the first odometry pose with a ground-truth pose
    TPath2D out;
    const auto& o0 = odometry[k].pose;
    for (size_t i = k; i < odometry.size(); i++)
        out.push_back({odometry[i].t, *g0 + (odometry[i].pose - o0)});
    return out;
}

TPath2D alignOdometryAt(const TPath2D& odometry, const mrpt::poses::CPose2D& start) {
    TPath2D out;
    for (const auto& o : odometry)
        out.push_back({o.t, start + (o.pose - odometry.front().pose)});
    return out;
}

TPath2D deadReckoning(const TPath2D& odometry,
                      const std::optional<mrpt::poses::CPose2D>& start,
                      const TPath2D& gt) {
    return start ? alignOdometryAt(odometry, *start) : alignOdometryAtStart(odometry, gt);
}

}  // namespace rfir::eval
