/* rfir-sim: the time loop: true path (with kidnapping), odometry, sensors. */
#include <rfir/common/output_set.h>
#include <rfir/common/progress.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/sim/simulator.h>

#include "odometry.h"
#include "trajectory.h"
#include "world.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace rfir::sim {
using namespace detail;
using mrpt::poses::CPose2D;

namespace {
/** Maps real time to the plan, with the kidnapping: before `ts` the plan is
 * followed; during the carry the robot moves from plan(ts) to the target; after
 * `te` it follows K (+) plan(t - te + s0). wheels(t) is the pose its wheels
 * would have integrated (they stop while carried). */
class CTimeline {
  public:
    CTimeline(const TSimConfig& cfg, const CPlan& plan) : plan_(plan) {
        const auto& k = cfg.kidnap;
        end_ = plan.duration();
        if (!k.enabled) return;
        if (k.time >= plan.duration())
            throw std::invalid_argument(
                "[kidnap] time is after the end of the trajectory (" +
                std::to_string(plan.duration()) + " s)");
        on_ = true;
        ts_ = k.time, te_ = k.time + k.carryTime;
        s0_ = k.toTime >= 0 ? k.toTime : k.time;
        const CPose2D target =
            k.toTime >= 0 ? plan.at(s0_) : CPose2D(k.toX, k.toY, k.toPhi);
        K_ = target + (CPose2D() - plan.at(s0_));
        lift_ = plan.at(ts_);
        end_ = te_ + plan.duration() - s0_;
    }
    double end() const { return end_; }
    bool carried(double t) const { return on_ && t >= ts_ && t < te_; }
    CPose2D truePose(double t) const {
        if (!on_ || t < ts_) return plan_.at(t);
        if (t >= te_) return K_ + plan_.at(t - te_ + s0_);
        const CPose2D to = K_ + plan_.at(s0_);
        const double f = te_ > ts_ ? (t - ts_) / (te_ - ts_) : 1.0;
        const double dphi = std::atan2(std::sin(to.phi() - lift_.phi()),
                                       std::cos(to.phi() - lift_.phi()));
        return {lift_.x() + f * (to.x() - lift_.x()),
                lift_.y() + f * (to.y() - lift_.y()), lift_.phi() + f * dphi};
    }
    CPose2D wheels(double t) const {
        if (!on_ || t < ts_) return plan_.at(t);
        if (t < te_) return lift_;
        return lift_ + (CPose2D() - plan_.at(s0_)) + plan_.at(t - te_ + s0_);
    }
    /** Real times at which the robot stands at plan time `s`. */
    std::vector<double> realTimes(double s) const {
        std::vector<double> v;
        if (!on_ || s < ts_) v.push_back(s);
        if (on_ && s >= s0_) v.push_back(s - s0_ + te_);
        return v;
    }

  private:
    const CPlan& plan_;
    bool on_ = false;
    double ts_ = 0, te_ = 0, s0_ = 0, end_ = 0;
    CPose2D K_, lift_;
};

/** CPose2D wraps headings into [-pi, pi); textlog angles are in (-pi, pi]:
 * a heading of exactly -pi (a start facing -x) is stored as pi, the value the
 * import of its text gives. */
CPose2D textPose(CPose2D p) {
    if (p.phi() == -M_PI) p.phi(M_PI);
    return p;
}

rfir::common::TMapFile groundTruthMap(const TWorld& w) {
    using K = rfir::common::TMapEntry::Kind;
    rfir::common::TMapFile m;
    for (const auto& t : w.tags) m.push_back({K::Tag, t.id, t.x, t.y, 0, {}, {}});
    for (const auto& e : w.emitters)
        m.push_back({K::Emitter, e.id, e.x, e.y, e.z, {}, {}});
    for (const auto& l : w.landmarks)
        m.push_back({K::Landmark, l.id, l.x, l.y, 0, {}, {}});
    return m;
}
/** Range-bearing landmark IDs in order of first observation, the header
 * naming only the landmarks observed: the numbering the import gives a text
 * log (whose `rb` records name landmarks), so that a simulated rawlog and its
 * text export are the same log. The map keeps every landmark by name. */
void numberLandmarks(const TWorld& w, TSimOutput& out) {
    std::vector<int32_t> idOf(w.landmarks.size(), -1);
    auto& names = out.header.rbLandmarkNames;
    names.clear();
    for (auto& s : out.steps)
        for (auto& o : s.obs) {
            auto rb = std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(o);
            if (!rb) continue;
            for (auto& m : rb->sensedData) {
                auto& id = idOf.at(size_t(m.landmarkID));
                if (id < 0) {
                    id = int32_t(names.size());
                    names.push_back(w.landmarks[size_t(m.landmarkID)].id);
                }
                m.landmarkID = id;
            }
        }
}
}  // namespace

TSimOutput simulate(const TSimConfig& cfg, uint64_t seed) {
    cfg.validate();
    rfir::sim::TSimRandom rngPath(streamSeed(seed, 4)), rngOdo(streamSeed(seed, 5)),
        rngRFID(streamSeed(seed, 6)), rngIR(streamSeed(seed, 7)),
        rngRB(streamSeed(seed, 8));
    const CPlan plan(cfg, rngPath);
    const CTimeline tl(cfg, plan);
    const TWorld world = buildWorld(cfg, seed);
    COdometrySimulator odo(cfg.odometry, rngOdo);

    TSimOutput out;
    out.scaleBias = odo.scaleBias(), out.rotScaleBias = odo.rotScaleBias();
    out.headingDrift = odo.headingDrift();
    out.gtMap = groundTruthMap(world);
    for (size_t i = 0; i < world.emitters.size(); i++)
        if (world.emitterFailed[i]) {
            const auto& e = world.emitters[i];
            std::ostringstream os;
            os << e.id << " " << e.x << " " << e.y;
            out.failedEmitters.push_back(os.str());
        }
    auto& h = out.header;
    h.sensorLabel = "HEADER";
    // Not "now": outputs must be reproducible.
    h.timestamp = mrpt::Clock::fromDouble(cfg.startTime);
    if (cfg.rfid.enabled) h.readers = cfg.readers;
    if (cfg.ir.enabled) h.receivers = cfg.receivers;
    if (cfg.rb.enabled) h.rbSensor = cfg.rbSensor;  // landmark names: numberLandmarks()
    h.startPose = textPose(tl.truePose(0));

    double end = tl.end();
    if (cfg.maxDuration > 0) end = std::min(end, cfg.maxDuration);
    const size_t n = size_t(std::floor(end / cfg.dt + 1e-9)) + 1;
    out.steps.reserve(n);
    CPose2D odom = tl.truePose(0), prevWheels = tl.wheels(0);
    long lastIR = -1;
    for (size_t k = 0; k < n; k++) {
        TSimStep s;
        const double e = k * cfg.dt;  // elapsed; the clock reads startTime + e
        s.t = cfg.startTime + e;
        s.truePose = tl.truePose(e);
        const CPose2D wheels = tl.wheels(e);
        if (k > 0) odom = odom + odo.noisyIncrement(wheels - prevWheels);
        prevWheels = wheels;
        const bool carried = tl.carried(e);
        if (!carried || cfg.kidnap.odometry == TKidnapConfig::Odometry::Frozen)
            s.odometry = textPose(odom);
        if (!carried) {
            if (cfg.rfid.enabled)
                s.obs.push_back(senseRFID(cfg, world, s.truePose, rngRFID));
            const long irSlot = long(std::floor(e / cfg.ir.period + 1e-9));
            if (cfg.ir.enabled && irSlot != lastIR) {
                // nullptr: no receiver saw anything (decoded output).
                if (auto o = senseIR(cfg, world, s.truePose, rngIR)) s.obs.push_back(o);
                lastIR = irSlot;
            }
            if (cfg.rb.enabled)
                if (auto o = senseRB(cfg, world, s.truePose, rngRB)) s.obs.push_back(o);
        }
        out.groundTruth.push_back({s.t, s.truePose});
        out.steps.push_back(std::move(s));
    }
    if (cfg.rb.enabled) numberLandmarks(world, out);
    for (double sp : plan.spotTimes())
        for (double t : tl.realTimes(sp))
            if (t <= end) out.spots.push_back({cfg.startTime + t, tl.truePose(t)});
    std::sort(out.spots.begin(), out.spots.end(),
              [](const auto& a, const auto& b) { return a.t < b.t; });
    return out;
}

void writeOutputs(const TSimOutput& out, const std::string& dir, const std::string& name,
                  std::ostream* progress) {
    const std::string base = dir + "/" + name;
    // The set is staged and renamed in whole: an earlier run's files of this
    // name (e.g. its .spots.tum) do not stay beside the new ones.
    rfir::common::COutputFiles set(dir, {name + ".rawlog", name + ".gt.tum",
                                         name + ".gt_map.txt", name + ".spots.tum"});
    {
        // A step with neither odometry nor observation (carried with
        // `odometry = stop`) is not written: an instant of a textlog has at
        // least one record. The header is stamped with the first instant's time,
        // as the import does.
        auto header = out.header;
        for (const auto& s : out.steps)
            if (s.odometry || !s.obs.empty()) {
                header.timestamp = mrpt::Clock::fromDouble(s.t);
                break;
            }
        rfir::common::CRawlogWriter w(set.file(name + ".rawlog"), header);
        const size_t n = out.steps.size();
        rfir::common::CProgress prog("rfir-sim: writing " + base + ".rawlog", n,
                                     n >= 1000 ? progress : nullptr);
        for (size_t k = 0; k < n; k++) {
            const auto& s = out.steps[k];
            if (s.odometry || !s.obs.empty()) w.writeStep(s.t, s.odometry, s.obs);
            prog.update(k);
        }
        prog.finish();
        w.close();
    }
    rfir::common::saveTUM(set.file(name + ".gt.tum"), out.groundTruth);
    std::string comment = "ground truth of simulated run " + name;
    if (!out.failedEmitters.empty()) {
        comment += "; failed emitters (installed, not emitting):";
        for (const auto& f : out.failedEmitters) comment += " [" + f + "]";
    }
    rfir::common::saveMapFile(set.file(name + ".gt_map.txt"), out.gtMap, comment);
    if (!out.spots.empty())
        rfir::common::saveTUM(set.file(name + ".spots.tum"), out.spots);
    set.commit();
}

}  // namespace rfir::sim
