/* rfir-sim: rectangular loops, five predefined shapes and random waypoint
 * paths (thesis 3.4.1, 4.4.1, 4.4.2; the PS-SLAM paper's section 4), with or without
 * rotation, with optional stops at marked spots (thesis 5.4.2). */
#include "trajectory.h"

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rfir::sim::detail {
namespace {
using Shape = std::vector<std::pair<double, double>>;

/** The five predefined closed shapes, in unit coordinates of the inset area
 * (the first corner is the start; the path returns to it). */
const Shape& predefinedShape(int n) {
    static const Shape shapes[5] = {
        // 1: rectangle
        {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
        // 2: serpentine (three passes along x), back along the left side
        {{0, 0},
         {1, 0},
         {1, 1. / 3},
         {0, 1. / 3},
         {0, 2. / 3},
         {1, 2. / 3},
         {1, 1},
         {0, 1}},
        // 3: L shape
        {{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}},
        // 4: diamond (diagonal motion)
        {{0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}},
        // 5: bow tie (two crossing diagonals)
        {{0, 0}, {1, 1}, {1, 0}, {0, 1}},
    };
    return shapes[n - 1];
}

double wrapToPi(double a) {
    return std::atan2(std::sin(a), std::cos(a));
}
}  // namespace

std::vector<TPoseU> trajectoryWaypoints(const TTrajectoryConfig& t, double x0, double y0,
                                        double x1, double y1,
                                        rfir::sim::TSimRandom& rng) {
    std::vector<TPoseU> w;
    if (t.kind == TTrajectoryConfig::Kind::Random) {
        // Waypoints at least 0.3 m apart, so that no segment degenerates.
        const double minSep = std::min(0.3, 0.25 * std::min(x1 - x0, y1 - y0));
        while (int(w.size()) < t.waypoints) {
            TPoseU p;
            p.x = rng.drawUniform(x0, x1);
            p.y = rng.drawUniform(y0, y1);
            if (!w.empty() && std::hypot(p.x - w.back().x, p.y - w.back().y) < minSep)
                continue;
            w.push_back(p);
        }
        return w;
    }
    if (t.kind == TTrajectoryConfig::Kind::Lawnmower) {
        // The last stripe lies on y1 when the spacing divides the height.
        const int n = 1 + int(std::floor((y1 - y0) / t.stripeSpacing + 1e-9));
        for (int lap = 0; lap < t.laps; lap++)
            for (int k = 0; k < n; k++) {
                const double y = y0 + k * t.stripeSpacing;
                w.push_back({k % 2 ? x1 : x0, y, 0});
                w.push_back({k % 2 ? x0 : x1, y, 0});
            }
        return w;
    }
    const Shape& s = predefinedShape(
        t.kind == TTrajectoryConfig::Kind::Loop ? 1 : std::clamp(t.predefined, 1, 5));
    for (int lap = 0; lap < t.laps; lap++)
        for (const auto& [u, v] : s)
            w.push_back({x0 + u * (x1 - x0), y0 + v * (y1 - y0), 0});
    w.push_back(w.front());  // close the last lap
    return w;
}

CPlan::CPlan(const TSimConfig& cfg, rfir::sim::TSimRandom& rng) {
    const auto& tc = cfg.trajectory;
    const double m = tc.margin;
    wps_ = trajectoryWaypoints(tc, cfg.areaMinX + m, cfg.areaMinY + m, cfg.areaMaxX - m,
                               cfg.areaMaxY - m, rng);
    double length = 0;
    for (size_t i = 1; i < wps_.size(); i++)
        length += std::hypot(wps_[i].x - wps_[i - 1].x, wps_[i].y - wps_[i - 1].y);
    const double spotStep = tc.spots > 0 ? length / tc.spots : 0;
    double arcDone = 0, nextSpot = tc.spots > 0 ? 0.5 * spotStep : -1;

    cur_ = wps_.front();
    cur_.phi = tc.startPhi;
    if (tc.rotation == TTrajectoryConfig::Rotation::Follow && wps_.size() > 1)
        cur_.phi = std::atan2(wps_[1].y - cur_.y, wps_[1].x - cur_.x);
    for (size_t i = 1; i < wps_.size(); i++) {
        if (tc.rotation == TTrajectoryConfig::Rotation::Follow) {
            const double dir = std::atan2(wps_[i].y - cur_.y, wps_[i].x - cur_.x);
            if (std::abs(wrapToPi(dir - cur_.phi)) > 1e-9)
                addTurn(cur_.phi + wrapToPi(dir - cur_.phi), tc.turnRate);
        }
        addTranslation(wps_[i], cfg, spotStep, arcDone, nextSpot);
    }
    if (segs_.empty()) throw std::invalid_argument("[trajectory] the path is empty");
}

void CPlan::addTurn(double phi, double rate) {
    TSegment s{t_, t_ + std::abs(phi - cur_.phi) / rate, cur_, cur_};
    s.to.phi = phi;
    segs_.push_back(s);
    cur_ = s.to, t_ = s.t1;
}

void CPlan::addPause(double seconds) {
    segs_.push_back({t_, t_ + seconds, cur_, cur_});
    spots_.push_back(t_ + 0.5 * seconds);
    t_ += seconds;
}

void CPlan::addTranslation(const TPoseU& to, const TSimConfig& cfg, double spotStep,
                           double& arcDone, double& nextSpot) {
    const auto& tc = cfg.trajectory;
    const double spin =
        tc.rotation == TTrajectoryConfig::Rotation::Spin ? tc.spinRate : 0;
    const double len = std::hypot(to.x - cur_.x, to.y - cur_.y);
    if (len < 1e-12) return;
    const double ux = (to.x - cur_.x) / len, uy = (to.y - cur_.y) / len;
    double done = 0;  // along this segment
    while (done < len) {
        // Go to the next spot on this segment, or to its end.
        const bool spot = nextSpot >= 0 && nextSpot < arcDone + len;
        const double stop = spot ? nextSpot - arcDone : len;
        const double dl = stop - done, dt = dl / tc.speed;
        TSegment s{t_, t_ + dt, cur_, cur_};
        s.to.x = cur_.x + ux * dl;
        s.to.y = cur_.y + uy * dl;
        s.to.phi = cur_.phi + spin * dt;
        if (dt > 0) segs_.push_back(s);
        cur_ = s.to, t_ = s.t1, done = stop;
        if (spot) {
            addPause(tc.spotPause);
            nextSpot += spotStep;
        }
    }
    cur_.x = to.x, cur_.y = to.y;  // no round-off drift between corners
    arcDone += len;
}

mrpt::poses::CPose2D CPlan::at(double t) const {
    if (t <= 0) return segs_.front().from.pose();
    if (t >= duration()) return segs_.back().to.pose();
    auto it = std::upper_bound(segs_.begin(), segs_.end(), t,
                               [](double v, const TSegment& s) { return v < s.t1; });
    if (it == segs_.end()) return segs_.back().to.pose();
    const double f = it->t1 > it->t0 ? (t - it->t0) / (it->t1 - it->t0) : 1.0;
    const TPoseU& a = it->from;
    const TPoseU& b = it->to;
    return {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), a.phi + f * (b.phi - a.phi)};
}

}  // namespace rfir::sim::detail
