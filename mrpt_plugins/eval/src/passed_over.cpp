/* Which ground-truth landmarks the robot's sensors could have seen along the
 * true path: the denominator of "mapped vs passed over". */
#include <rfir/eval/metrics.h>
#include <rfir/models/read_model.h>
#include <rfir/models/spatial_grid.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace rfir::eval {
using mrpt::poses::CPose2D;
using rfir::common::TMapEntry;
using rfir::common::TPath2D;

namespace {
/** Calls fn at every pose of the path and at interpolated poses in between,
 * so that a point at distance <= reach from the robot moves by at most `step`
 * between samples. Steps longer than maxGap are jumps: not interpolated. */
void forEachSample(const TPath2D& path, double step, double reach, double maxGap,
                   const std::function<void(const CPose2D&)>& fn) {
    for (size_t i = 0; i < path.size(); i++) {
        const CPose2D& b = path[i].pose;
        if (i > 0) {
            const CPose2D& a = path[i - 1].pose;
            const double d = std::hypot(b.x() - a.x(), b.y() - a.y());
            const double dphi = wrapToPi(b.phi() - a.phi());
            const int n =
                d > maxGap ? 1 : int(std::ceil((d + reach * std::abs(dphi)) / step));
            for (int k = 1; k < n; k++)
                fn(rfir::common::interpolatePose2D(a, b, double(k) / n));
        }
        fn(b);
    }
}

/** The entries on a grid of cells of side >= the query radius, so that a
 * query looks at the 3x3 cells around a point. */
using TEntryGrid = rfir::models::TSpatialGrid<const TMapEntry*>;
TEntryGrid gridOf(const std::vector<const TMapEntry*>& pts, double cell) {
    TEntryGrid g(cell);
    for (const TMapEntry* p : pts) g.insert(p->x, p->y, p);
    return g;
}

std::vector<const TMapEntry*> ofKind(const rfir::common::TMapFile& m, TMapEntry::Kind k) {
    std::vector<const TMapEntry*> out;
    for (const auto& e : m)
        if (e.kind == k) out.push_back(&e);
    return out;
}
}  // namespace

std::set<std::string> tagsPassedOver(const rfir::common::TMapFile& gt,
                                     const TPath2D& gtPath,
                                     const std::vector<rfir::obs::TRFIDReader>& readers,
                                     double maxGap) {
    if (readers.empty())
        throw std::runtime_error("passed-over tags: no RFID reader geometry is known");
    double reach = 0, minHalf = 1e9;
    for (const auto& r : readers) {
        reach =
            std::max(reach, std::hypot(std::abs(r.x) + r.halfX, std::abs(r.y) + r.halfY));
        minHalf = std::min({minHalf, r.halfX, r.halfY});
    }
    std::set<std::string> seen;
    const TEntryGrid grid = gridOf(ofKind(gt, TMapEntry::Kind::Tag), reach);
    forEachSample(gtPath, 0.25 * minHalf, reach, maxGap, [&](const CPose2D& p) {
        const mrpt::math::TPose2D pose = p.asTPose();
        const double c = std::cos(pose.phi), s = std::sin(pose.phi);
        grid.forEachAround(p.x(), p.y(), [&](const TMapEntry* t) {
            const TMapEntry& tag = *t;
            if (seen.count(tag.id)) return;
            // The SLAM read model (e = tag - reader centre, in the robot frame).
            for (const auto& r : readers) {
                const auto e =
                    rfir::models::readModel(pose, c, s, r.x, r.y, {tag.x, tag.y});
                if (std::abs(e.x) < r.halfX && std::abs(e.y) < r.halfY) {
                    seen.insert(tag.id);
                    return;
                }
            }
        });
    });
    return seen;
}

std::set<std::string> landmarksInView(const rfir::common::TMapFile& gt,
                                      const TPath2D& gtPath,
                                      const rfir::obs::TRBSensor& sensor, double maxGap) {
    if (!(sensor.maxRange > 0))
        throw std::runtime_error("landmarks in view: the sensor range must be > 0");
    const double reach = std::hypot(sensor.x, sensor.y) + sensor.maxRange;
    const CPose2D onRobot(sensor.x, sensor.y, sensor.yaw);
    std::set<std::string> seen;
    const TEntryGrid grid = gridOf(ofKind(gt, TMapEntry::Kind::Landmark), reach);
    forEachSample(gtPath, 0.125 * sensor.maxRange, reach, maxGap, [&](const CPose2D& p) {
        const CPose2D sp = p + onRobot;
        grid.forEachAround(sp.x(), sp.y(), [&](const TMapEntry* l) {
            const TMapEntry& lm = *l;
            if (seen.count(lm.id)) return;
            const double dx = lm.x - sp.x(), dy = lm.y - sp.y();
            if (std::hypot(dx, dy) > sensor.maxRange) return;
            if (std::abs(wrapToPi(std::atan2(dy, dx) - sp.phi())) <= 0.5 * sensor.fov)
                seen.insert(lm.id);
        });
    });
    return seen;
}

}  // namespace rfir::eval
