#include <rfir/models/ini_reader.h>
#include <rfir/models/range_bearing.h>
#include <rfir/models/read_model.h>
#include <rfir/slam/kidnap.h>

#include <mrpt/config/CConfigFileBase.h>

#include <cmath>

namespace rfir::slam {
void TKidnapOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s) {
    using R = rfir::ini::TRange;
    const rfir::ini::CIniSection sec(
        c, s,
        {"enabled", "collapse_loglik", "collapse_steps", "min_tags", "max_gap",
         "evidence_drop", "persist_tags", "fast_rate", "slow_rate", "inject_fraction",
         "keep_heading_share", "heading_std", "pair_heading_share", "pair_min_distance",
         "map_new_tags_in_run", "rb_loglik_scale", "loop_closure_smoothing"});
    enabled = sec.getBool("enabled", enabled);
    // A mean log-likelihood per detection beyond +-1000 means nothing: a
    // density of e^1000 or a collapse on every step.
    collapse_loglik =
        sec.getDouble("collapse_loglik", collapse_loglik, R::closed(-1000, 1000));
    collapse_steps =
        unsigned(sec.getInt("collapse_steps", int64_t(collapse_steps), 1, 1000000));
    min_tags = unsigned(sec.getInt("min_tags", int64_t(min_tags), 1, 1000000));
    max_gap = sec.getDouble("max_gap", max_gap, R::aboveZero(1e6));
    evidence_drop = sec.getDouble("evidence_drop", evidence_drop, R::closed(0, 1e6));
    persist_tags =
        unsigned(sec.getInt("persist_tags", int64_t(persist_tags), 0, 1000000));
    fast_rate = sec.getDouble("fast_rate", fast_rate, R::aboveZero(1));
    slow_rate = sec.getDouble("slow_rate", slow_rate, R::aboveZero(1));
    if (slow_rate > fast_rate) sec.fail("slow_rate", "must not exceed fast_rate");
    inject_fraction = sec.getDouble("inject_fraction", inject_fraction, R::aboveZero(1));
    keep_heading_share =
        sec.getDouble("keep_heading_share", keep_heading_share, R::closed(0, 1));
    heading_std = sec.getDouble("heading_std", heading_std, R::closed(0, M_PI));
    pair_heading_share =
        sec.getDouble("pair_heading_share", pair_heading_share, R::closed(0, 1));
    pair_min_distance =
        sec.getDouble("pair_min_distance", pair_min_distance, R::closed(0, 1e3));
    map_new_tags_in_run = sec.getBool("map_new_tags_in_run", map_new_tags_in_run);
    loop_closure_smoothing =
        sec.getBool("loop_closure_smoothing", loop_closure_smoothing);
    rb_loglik_scale =
        sec.getDouble("rb_loglik_scale", rb_loglik_scale, R::aboveZero(1e6));
}

void TKidnapOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                      const std::string& s) const {
    c.write(s, "enabled", enabled, -1, -1, "sensor resetting on collapse");
    c.write(
        s, "collapse_loglik", collapse_loglik, -1, -1,
        "a step disagrees if its best particle's mean log-lik per read is below this...");
    c.write(s, "collapse_steps", int(collapse_steps), -1, -1,
            "...in this many steps of one run of disagreeing steps...");
    c.write(s, "min_tags", int(min_tags), -1, -1,
            "...over this many distinct known landmarks...");
    c.write(s, "max_gap", max_gap, -1, -1,
            "...ended by an agreeing step or this long [s] without a disagreeing one");
    c.write(s, "evidence_drop", evidence_drop, -1, -1,
            "and the fast evidence average this far below the slow one");
    c.write(s, "persist_tags", int(persist_tags), -1, -1,
            "or this many distinct landmarks contradicted in the run (0: off)");
    c.write(s, "fast_rate", fast_rate, -1, -1, "fast average rate per weighing step");
    c.write(s, "slow_rate", slow_rate, -1, -1, "slow average rate per weighing step");
    c.write(s, "inject_fraction", inject_fraction, -1, -1,
            "share of robot particles redrawn from detections");
    c.write(s, "keep_heading_share", keep_heading_share, -1, -1,
            "share of those keeping the current heading");
    c.write(s, "heading_std", heading_std, -1, -1, "their heading std [rad]");
    c.write(s, "pair_heading_share", pair_heading_share, -1, -1,
            "share of the others heading from two landmarks of the run");
    c.write(s, "pair_min_distance", pair_min_distance, -1, -1,
            "the two landmarks at least this far apart [m]");
    c.write(s, "map_new_tags_in_run", map_new_tags_in_run, -1, -1,
            "while a run is open, RFID tags never mapped are still mapped");
    c.write(s, "rb_loglik_scale", rb_loglik_scale, -1, -1,
            "range-bearing log-likelihoods enter the evidence times this");
    c.write(s, "loop_closure_smoothing", loop_closure_smoothing, -1, -1,
            "a trigger the smoothed run explains is a loop closure, not a reset");
}

bool CKidnapMonitor::update(const TStepEvidence& e) {
    if (!o_.enabled || e.reads == 0) return false;
    // Augmented MCL's two averages of the step evidence (in log units, so
    // that a read far outside its reader does not underflow).
    const bool first = !fast_;
    fast_ =
        first ? e.meanLogEvidence : *fast_ + o_.fast_rate * (e.meanLogEvidence - *fast_);
    const double slowBefore = first ? e.meanLogEvidence : *slow_;
    slow_ = slowBefore + o_.slow_rate * (e.meanLogEvidence - slowBefore);
    if (bad_ > 0 && e.t - lastBad_ > o_.max_gap) endRun();
    if (e.bestMeanLogLik >= o_.collapse_loglik || e.agreeing > 0) {
        endRun();  // some particle explains the reads: not lost
        return false;
    }
    if (bad_++ == 0) slowAtRunStart_ = slowBefore;
    lastBad_ = e.t;
    ids_.insert(e.disagreeing.begin(), e.disagreeing.end());
    // The drop is measured against the slow average from before this run
    // took it down, so a long run cannot hide itself.
    if (bad_ < o_.collapse_steps || ids_.size() < o_.min_tags) return false;
    const bool dropped = *fast_ <= slowAtRunStart_ - o_.evidence_drop;
    const bool persistent = o_.persist_tags > 0 && ids_.size() >= o_.persist_tags;
    if (!dropped && !persistent) return false;
    endRun();
    ++resets_;
    return true;
}

void CRunAnchors::add(const std::vector<TAnchor>& anchors,
                      const mrpt::poses::CPose2D& odo) {
    // A run lasts a few seconds; the cap only bounds a pathological one.
    constexpr size_t kMax = 256;
    for (const auto& a : anchors) v_.push_back({a, odo});
    if (v_.size() > kMax) v_.erase(v_.begin(), v_.end() - kMax);
}

namespace {
/** Where the detection puts its landmark, robot frame: a point drawn in the
 * reader's square (the step model's support), or the range-bearing read
 * with its noise. */
mrpt::math::TPoint2D sensedPoint(const TDetection& d, rfir::models::TRandom& rng) {
    if (d.kind == TDetection::Kind::RFID)
        return {d.a + rng.drawUniform(-d.halfX, d.halfX),
                d.b + rng.drawUniform(-d.halfY, d.halfY)};
    const double r = d.a + rng.drawGaussian1D(0, std::max(d.stdRange, 1e-3));
    const double b = d.b + rng.drawGaussian1D(0, std::max(d.stdBearing, 1e-3));
    // The range-bearing inverse model, in the robot frame.
    return rfir::models::rangeBearingToPoint({d.sensor.x(), d.sensor.y(), d.sensor.phi()},
                                             r, b);
}

mrpt::poses::CPose2D poseFromSensed(const TAnchor& a, const mrpt::math::TPoint2D& s,
                                    double phi) {
    const auto t = rfir::models::robotPositionFromRead({a.x, a.y}, std::cos(phi),
                                                       std::sin(phi), s.x, s.y);
    return {t.x, t.y, phi};
}

/** A pose from anchor `b` of this step with the heading that turns the
 * vector from `a` (an earlier step's, moved into this step's frame by the
 * odometry between them) to `b` onto the map's vector between the two. */
mrpt::poses::CPose2D poseFromPair(const TRunAnchor& a, const TAnchor& b,
                                  const mrpt::poses::CPose2D& odo,
                                  rfir::models::TRandom& rng) {
    const auto sa = sensedPoint(a.a.det, rng);
    const auto sb = sensedPoint(b.det, rng);
    const mrpt::poses::CPose2D rel = a.odo - odo;  // a's step in this step's frame
    double ax, ay;
    rel.composePoint(sa.x, sa.y, ax, ay);
    const double phi =
        std::atan2(b.y - a.a.y, b.x - a.a.x) - std::atan2(sb.y - ay, sb.x - ax);
    return poseFromSensed(b, sb, mrpt::math::wrapToPi(phi));
}

/** The run's anchors that pair with `b`: another landmark, far enough. */
std::vector<const TRunAnchor*> partners(const std::vector<TRunAnchor>& run,
                                        const TAnchor& b, double minDist) {
    std::vector<const TRunAnchor*> out;
    for (const auto& r : run)
        if (r.a.det.id != b.det.id && std::hypot(r.a.x - b.x, r.a.y - b.y) >= minDist)
            out.push_back(&r);
    return out;
}
}  // namespace

mrpt::poses::CPose2D poseFromAnchor(const TAnchor& a, double phi,
                                    rfir::models::TRandom& rng) {
    return poseFromSensed(a, sensedPoint(a.det, rng), phi);
}

std::vector<mrpt::poses::CPose2D> resettingPoses(const std::vector<TAnchor>& now,
                                                 const mrpt::poses::CPose2D& odo,
                                                 const std::vector<TRunAnchor>& run,
                                                 size_t n, double currentPhi,
                                                 const TKidnapOptions& o,
                                                 rfir::models::TRandom& rng) {
    std::vector<mrpt::poses::CPose2D> out;
    if (now.empty()) return out;
    // This step's anchors pair with each other too (no odometry between).
    std::vector<TRunAnchor> all = run;
    for (const auto& a : now) all.push_back({a, odo});
    std::vector<std::vector<const TRunAnchor*>> pairsOf;  // per anchor of `now`
    for (const auto& b : now) pairsOf.push_back(partners(all, b, o.pair_min_distance));
    for (size_t i = 0; i < n; i++) {
        const size_t k = rng.drawUniform32bit() % now.size();
        const TAnchor& b = now[k];
        if (rng.drawUniform(0, 1) < o.keep_heading_share) {
            const double phi = currentPhi + rng.drawGaussian1D(0, o.heading_std);
            out.push_back(poseFromAnchor(b, mrpt::math::wrapToPi(phi), rng));
            continue;
        }
        const auto& ps = pairsOf[k];
        if (!ps.empty() && rng.drawUniform(0, 1) < o.pair_heading_share)
            out.push_back(
                poseFromPair(*ps[rng.drawUniform32bit() % ps.size()], b, odo, rng));
        else
            out.push_back(poseFromAnchor(b, rng.drawUniform(-M_PI, M_PI), rng));
    }
    return out;
}

}  // namespace rfir::slam
