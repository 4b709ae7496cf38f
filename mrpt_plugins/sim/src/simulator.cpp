/* rfir-sim: the time loop: true path (with kidnapping), odometry, sensors. */
#include <rfir/common/output_set.h>
#include <rfir/common/progress.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/sim/simulator.h>

#include "sim_run.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace rfir::sim {
using namespace detail;
using mrpt::poses::CPose2D;

namespace {
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

namespace {
/** One step per dt: odometry and every sensor at the same instants. */
void runSteps(TSimRun& run, TSimOutput& out) {
    const auto& cfg = run.cfg;
    const auto& tl = run.tl;
    out.steps.reserve(run.n);
    CPose2D odom = tl.truePose(0), prevWheels = tl.wheels(0);
    long lastIR = -1;
    for (size_t k = 0; k < run.n; k++) {
        TSimStep s;
        const double e = k * cfg.dt;  // elapsed; the clock reads startTime + e
        s.t = cfg.startTime + e;
        s.truePose = tl.truePose(e);
        const CPose2D wheels = tl.wheels(e);
        if (k > 0) {
            const CPose2D inc = wheels - prevWheels;
            odom = odom +
                   run.slips.apply(e, s.t, inc, run.odo.noisyIncrement(inc), out.faults);
        }
        prevWheels = wheels;
        const bool carried = tl.carried(e);
        if (!carried || cfg.kidnap.odometry == TKidnapConfig::Odometry::Frozen)
            s.odometry = textPose(odom);
        if (!carried) {
            const TFaultContext f{&run.fault, &out.faults, e, s.t};
            if (cfg.rfid.enabled)
                if (auto o = senseRFID(cfg, run.world, s.truePose, run.rfid, {}, f))
                    s.obs.push_back(o);
            const long irSlot = long(std::floor(e / cfg.ir.period + 1e-9));
            if (cfg.ir.enabled && irSlot != lastIR) {
                // nullptr: no receiver saw anything (decoded output).
                if (auto o = senseIR(cfg, run.world, s.truePose, run.ir, f))
                    s.obs.push_back(o);
                lastIR = irSlot;
            }
            if (cfg.rb.enabled)
                if (auto o = senseRB(cfg, run.world, s.truePose, run.rb))
                    s.obs.push_back(o);
        }
        out.groundTruth.push_back({s.t, s.truePose});
        out.steps.push_back(std::move(s));
    }
}

/** A position in a record, at the map files' precision (1 um). */
std::string coord(double v) {
    std::ostringstream o;
    o << std::setprecision(9) << std::round(v * 1e6) / 1e6;
    return o.str();
}

/** The faults that are not events (dead readers, emitters, biases) head the
 * ground-truth record list; the localizer's map gets the moved emitters. */
void recordStaticFaults(const TSimConfig& cfg, const TWorld& w, TSimOutput& out) {
    std::vector<std::string> head;
    head.push_back("odometry_bias " + faultNumber(out.scaleBias) + " " +
                   faultNumber(out.rotScaleBias) + " " + faultNumber(out.headingDrift));
    if (cfg.rfid.enabled)
        for (const auto& d : cfg.rfid.deadReaders)
            head.push_back("dead_reader " + cfg.readers[d.reader].id + " " +
                           faultNumber(cfg.startTime + d.from) + " " +
                           faultNumber(cfg.startTime + d.to));
    for (size_t i = 0; i < w.emitters.size(); i++)
        if (w.emitterFailed[i])
            head.push_back("failed_emitter " + w.emitters[i].id + " " +
                           coord(w.emitters[i].x) + " " + coord(w.emitters[i].y));
    if (cfg.ir.enabled && !cfg.ir.moved.empty()) {
        out.localizerMap = out.gtMap;
        for (const auto& m : cfg.ir.moved) {
            bool found = false;
            for (auto& e : out.localizerMap)
                if (e.kind == rfir::common::TMapEntry::Kind::Emitter &&
                    std::hypot(e.x - m.x, e.y - m.y) < 0.05) {
                    head.push_back("moved_emitter " + e.id + " " + coord(e.x) + " " +
                                   coord(e.y) + " " + coord(e.x + m.dx) + " " +
                                   coord(e.y + m.dy));
                    e.x += m.dx, e.y += m.dy, found = true;
                }
            if (!found)
                throw std::invalid_argument("[ir] moved: no emitter at '" + coord(m.x) +
                                            " " + coord(m.y) + "' in the lattice");
        }
    }
    out.faults.insert(out.faults.begin(), head.begin(), head.end());
}
}  // namespace

TSimOutput simulate(const TSimConfig& cfg, uint64_t seed) {
    cfg.validate();
    rfir::sim::TSimRandom rngPath(streamSeed(seed, 4)), rngOdo(streamSeed(seed, 5)),
        rngRFID(streamSeed(seed, 6)), rngIR(streamSeed(seed, 7)),
        rngRB(streamSeed(seed, 8));
    // The faults' own streams: the clean streams above draw the same numbers
    // whether faults are on or not.
    rfir::sim::TSimRandom rngFault(streamSeed(seed, 9)), rngTiming(streamSeed(seed, 10));
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
    CSlipSchedule slips(cfg.odometry, end, rngFault);
    TSimRun run{cfg,
                tl,
                world,
                odo,
                slips,
                rngRFID,
                rngIR,
                rngRB,
                rngFault,
                rngTiming,
                (n - 1) * cfg.dt,
                n};
    if (cfg.asyncTiming())
        runEvents(run, out);
    else
        runSteps(run, out);
    out.hasFaults = cfg.hasFaults();
    if (out.hasFaults) recordStaticFaults(cfg, world, out);
    if (cfg.rb.enabled) numberLandmarks(world, out);
    for (double sp : plan.spotTimes())
        for (double t : tl.realTimes(sp))
            if (t <= end) out.spots.push_back({cfg.startTime + t, tl.truePose(t)});
    std::sort(out.spots.begin(), out.spots.end(),
              [](const auto& a, const auto& b) { return a.t < b.t; });
    return out;
}

namespace {
void writeFaultRecords(const std::string& path, const TSimOutput& out,
                       const std::string& name) {
    std::ofstream f(path);
    f << "# faults injected into simulated run " << name
      << " (docs/simulator.md, \"Faults\"); times are the log's clock\n";
    for (const auto& r : out.faults) f << r << "\n";
    f.flush();
    if (!f) throw std::runtime_error(path + ": cannot write the fault records");
}
}  // namespace

void writeOutputs(const TSimOutput& out, const std::string& dir, const std::string& name,
                  std::ostream* progress) {
    const std::string base = dir + "/" + name;
    // The set is staged and renamed in whole: an earlier run's files of this
    // name (e.g. its .spots.tum) do not stay beside the new ones.
    rfir::common::COutputFiles set(
        dir, {name + ".rawlog", name + ".gt.tum", name + ".gt_map.txt",
              name + ".spots.tum", name + ".gt_faults.txt", name + ".map.txt"});
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
    if (out.hasFaults) writeFaultRecords(set.file(name + ".gt_faults.txt"), out, name);
    if (!out.localizerMap.empty())
        rfir::common::saveMapFile(set.file(name + ".map.txt"), out.localizerMap,
                                  "map given to the localizer of simulated run " + name +
                                      " (moved emitters: see " + name +
                                      ".gt_faults.txt)");
    set.commit();
}

}  // namespace rfir::sim
