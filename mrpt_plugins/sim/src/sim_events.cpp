/* rfir-sim: the event-driven time loop (docs/simulator.md, "Faults"): odometry
 * records at their own rate and with a latency, RFID polls round robin with
 * jitter, IR and range-bearing on the dt grid. Event times are whole 0.1 ms
 * ticks, so that events falling on one tick form one instant (MRPT timestamps
 * cannot tell apart times closer than 100 ns). */
#include "sim_run.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace rfir::sim::detail {
namespace {
constexpr double kTick = 1e-4;  // s

struct TEvent {
    bool grid = false;  //!< a dt step: IR, range-bearing, RFID polled together
    bool odometry = false;
    std::vector<size_t> polls;  //!< readers polled (round robin)
};

int64_t ticks(double e) {
    return int64_t(std::llround(e / kTick));
}

std::map<int64_t, TEvent> schedule(const TSimRun& run) {
    const auto& cfg = run.cfg;
    std::map<int64_t, TEvent> ev;
    for (size_t k = 0; k < run.n; k++) ev[ticks(k * cfg.dt)].grid = true;
    if (cfg.odometry.rate > 0) {
        for (int64_t j = 0; j / cfg.odometry.rate <= run.end + 1e-9; j++)
            ev[ticks(j / cfg.odometry.rate)].odometry = true;
    } else
        for (auto& [t, e] : ev) e.odometry = true;
    if (cfg.rfid.enabled && cfg.rfid.polling == TRFIDConfig::Polling::RoundRobin) {
        const size_t nr = cfg.readers.size();
        const double rate = cfg.rfid.pollRate * double(nr);
        for (int64_t p = 0; p / rate <= run.end + 1e-9; p++) {
            double e = p / rate;
            if (cfg.rfid.pollJitter > 0)
                e += run.timing.drawUniform(-cfg.rfid.pollJitter, cfg.rfid.pollJitter);
            e = std::clamp(e, 0.0, run.end);
            ev[ticks(e)].polls.push_back(size_t(p) % nr);
        }
    }
    return ev;
}
}  // namespace

void runEvents(TSimRun& run, TSimOutput& out) {
    const auto& cfg = run.cfg;
    const auto& tl = run.tl;
    const bool together = cfg.rfid.polling == TRFIDConfig::Polling::Together;
    CPose2D odom = tl.truePose(0), prevWheels = tl.wheels(0);
    long lastIR = -1;
    bool firstOdo = true;
    for (const auto& [tk, ev] : schedule(run)) {
        TSimStep s;
        const double e = double(tk) * kTick;
        s.t = cfg.startTime + e;
        s.truePose = tl.truePose(e);
        if (ev.odometry) {
            // Latency: the record at t reports the wheels at t - latency.
            const double ew = std::max(0.0, e - cfg.odometry.latency);
            const CPose2D wheels = tl.wheels(ew);
            if (!firstOdo) {
                const CPose2D inc = wheels - prevWheels;
                odom = odom + run.slips.apply(ew, s.t, inc, run.odo.noisyIncrement(inc),
                                              out.faults);
            }
            prevWheels = wheels, firstOdo = false;
            if (!tl.carried(ew) || cfg.kidnap.odometry == TKidnapConfig::Odometry::Frozen)
                s.odometry = textPose(odom);
        }
        if (!tl.carried(e)) {
            const TFaultContext f{&run.fault, &out.faults, e, s.t};
            if (cfg.rfid.enabled && ((together && ev.grid) || !ev.polls.empty()))
                if (auto o = senseRFID(cfg, run.world, s.truePose, run.rfid, ev.polls, f))
                    s.obs.push_back(o);
            const long irSlot = long(std::floor(e / cfg.ir.period + 1e-9));
            if (ev.grid && cfg.ir.enabled && irSlot != lastIR) {
                if (auto o = senseIR(cfg, run.world, s.truePose, run.ir, f))
                    s.obs.push_back(o);
                lastIR = irSlot;
            }
            if (ev.grid && cfg.rb.enabled)
                if (auto o = senseRB(cfg, run.world, s.truePose, run.rb))
                    s.obs.push_back(o);
        }
        out.groundTruth.push_back({s.t, s.truePose});
        out.steps.push_back(std::move(s));
    }
}
}  // namespace rfir::sim::detail
