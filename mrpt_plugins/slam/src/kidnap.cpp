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
         "keep_heading_share", "heading_std", "map_new_tags_in_run", "rb_loglik_scale"});
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
    map_new_tags_in_run = sec.getBool("map_new_tags_in_run", map_new_tags_in_run);
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
    c.write(s, "map_new_tags_in_run", map_new_tags_in_run, -1, -1,
            "while a run is open, RFID tags never mapped are still mapped");
    c.write(s, "rb_loglik_scale", rb_loglik_scale, -1, -1,
            "range-bearing log-likelihoods enter the evidence times this");
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

mrpt::poses::CPose2D poseFromAnchor(const TAnchor& a, double phi,
                                    rfir::models::TRandom& rng) {
    const TDetection& d = a.det;
    double sx, sy;  // the landmark seen from the pose, robot frame
    if (d.kind == TDetection::Kind::RFID) {
        sx = d.a + rng.drawUniform(-d.halfX, d.halfX);
        sy = d.b + rng.drawUniform(-d.halfY, d.halfY);
    } else {
        const double r = d.a + rng.drawGaussian1D(0, std::max(d.stdRange, 1e-3));
        const double b = d.b + rng.drawGaussian1D(0, std::max(d.stdBearing, 1e-3));
        // The range-bearing inverse model, in the robot frame.
        const auto p = rfir::models::rangeBearingToPoint(
            {d.sensor.x(), d.sensor.y(), d.sensor.phi()}, r, b);
        sx = p.x;
        sy = p.y;
    }
    const auto t = rfir::models::robotPositionFromRead({a.x, a.y}, std::cos(phi),
                                                       std::sin(phi), sx, sy);
    return {t.x, t.y, phi};
}

std::vector<mrpt::poses::CPose2D> resettingPoses(const std::vector<TAnchor>& anchors,
                                                 size_t n, double currentPhi,
                                                 const TKidnapOptions& o,
                                                 rfir::models::TRandom& rng) {
    std::vector<mrpt::poses::CPose2D> out;
    if (anchors.empty()) return out;
    for (size_t i = 0; i < n; i++) {
        const TAnchor& a = anchors[rng.drawUniform32bit() % anchors.size()];
        const double phi = rng.drawUniform(0, 1) < o.keep_heading_share
                               ? currentPhi + rng.drawGaussian1D(0, o.heading_std)
                               : rng.drawUniform(-M_PI, M_PI);
        out.push_back(poseFromAnchor(a, mrpt::math::wrapToPi(phi), rng));
    }
    return out;
}

}  // namespace rfir::slam
