/* rfir-sim: the fault keys of [odometry], [rfid] and [ir] (all off by
 * default, docs/simulator.md "Faults"), their validation and dump. */
#include <rfir/sim/simulator.h>

#include "ini_section.h"

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>

namespace rfir::sim {
using detail::CIniSection;

void loadOdometryFaults(const CIniSection& s, TOdometryNoise& o) {
    s.num("scale_error", o.scaleError, -0.5, 0.5);
    s.num("rot_scale_error", o.rotScaleError, -0.5, 0.5);
    s.num("heading_drift_error", o.headingDriftError, -1, 1);
    s.nonNegative("rate", o.rate, 1000);
    s.nonNegative("latency", o.latency, 10);
    std::vector<std::vector<double>> l;
    if (s.numberLists("slip_times", {1}, l)) {
        o.slipTimes.clear();
        for (const auto& e : l) {
            if (!(e[0] >= 0)) s.fail("slip_times", "times must be >= 0 s");
            o.slipTimes.push_back(e[0]);
        }
    }
    s.integer("slip_count", o.slipCount, 0, 100000);
    s.num("slip_size", o.slipSize, -10, 10);
    double deg = mrpt::RAD2DEG(o.slipHeading);
    s.num("slip_heading_deg", deg, -180, 180);
    o.slipHeading = mrpt::DEG2RAD(deg);
}

void loadRFIDFaults(const CIniSection& s, TRFIDConfig& r) {
    s.nonNegative("ghost_rate", r.ghostRate, 1);
    std::vector<std::vector<double>> l;
    if (s.numberLists("ghost_distance", {2}, l)) {
        if (l.size() != 1) s.fail("ghost_distance", "expected one entry 'min max'");
        r.ghostMinDistance = l[0][0], r.ghostMaxDistance = l[0][1];
        if (!(r.ghostMinDistance >= 0 && r.ghostMaxDistance > r.ghostMinDistance &&
              r.ghostMaxDistance <= 10))
            s.fail("ghost_distance", "need 0 <= min < max <= 10 (m)");
    }
    if (s.numberLists("dead_readers", {3}, l)) {
        r.deadReaders.clear();
        for (const auto& e : l) {
            if (!(e[0] >= 0 && e[0] == std::floor(e[0])))
                s.fail("dead_readers", "the reader is an index 0, 1, ...");
            if (!(e[1] >= 0 && e[2] > e[1]))
                s.fail("dead_readers", "need 0 <= from < to (s from the start)");
            r.deadReaders.push_back({size_t(e[0]), e[1], e[2]});
        }
    }
    const int w = s.choice("empty_polls", {"write", "omit"});
    if (w >= 0) r.writeEmptyPolls = w == 0;
    const int p = s.choice("polling", {"together", "round_robin"});
    if (p >= 0) r.polling = TRFIDConfig::Polling(p);
    s.positive("poll_rate", r.pollRate, 200);
    s.nonNegative("poll_jitter", r.pollJitter, 10);
}

void loadIRFaults(const CIniSection& s, TIRConfig& ir) {
    std::vector<std::vector<double>> l;
    if (s.numberLists("moved", {4}, l)) {
        ir.moved.clear();
        for (const auto& e : l) ir.moved.push_back({e[0], e[1], e[2], e[3]});
    }
    s.nonNegative("wrong_code_rate", ir.wrongCodeRate, 1);
    s.nonNegative("wrong_code_other_id", ir.wrongCodeOtherId, 1);
    s.nonNegative("volt_outlier_rate", ir.voltOutlierRate, 1);
    s.positive("volt_outlier_max", ir.voltOutlierMax, 1000);
}

/** The consistency checks of the fault keys (part of TSimConfig::validate). */
void validateFaults(const TSimConfig& c) {
    auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
    for (const auto& d : c.rfid.deadReaders)
        if (d.reader >= c.readers.size())
            bad("[rfid] dead_readers: reader " + std::to_string(d.reader) +
                " does not exist (" + std::to_string(c.readers.size()) + " readers)");
    if (c.rfid.polling == TRFIDConfig::Polling::RoundRobin &&
        c.rfid.pollJitter * c.rfid.pollRate * double(c.readers.size()) >= 0.5)
        bad("[rfid] poll_jitter and [rfid] poll_rate: the jitter must be under half "
            "the interval between two polls, 1 / (poll_rate * readers)");
}

bool TSimConfig::hasFaults() const {
    const auto& o = odometry;
    return o.scaleError != 0 || o.rotScaleError != 0 || o.headingDriftError != 0 ||
           !o.slipTimes.empty() || o.slipCount > 0 || asyncTiming() ||
           (rfid.enabled &&
            (rfid.ghostRate > 0 || !rfid.deadReaders.empty() || !rfid.writeEmptyPolls)) ||
           (ir.enabled &&
            (!ir.moved.empty() || ir.wrongCodeRate > 0 || ir.voltOutlierRate > 0));
}

bool TSimConfig::asyncTiming() const {
    return odometry.rate > 0 || odometry.latency > 0 ||
           (rfid.enabled && rfid.polling == TRFIDConfig::Polling::RoundRobin);
}

void dumpFaults(const TSimConfig& c, std::ostream& o) {
    if (!c.hasFaults()) return;
    const auto& n = c.odometry;
    o << "[faults] odometry: scale_error=" << n.scaleError
      << " rot_scale_error=" << n.rotScaleError
      << " heading_drift_error=" << n.headingDriftError << " rate=" << n.rate
      << " latency=" << n.latency << " slips=" << n.slipTimes.size() << "+" << n.slipCount
      << " of " << n.slipSize << " m\n";
    o << "         rfid: ghost_rate=" << c.rfid.ghostRate
      << " dead_readers=" << c.rfid.deadReaders.size()
      << " empty_polls=" << (c.rfid.writeEmptyPolls ? "write" : "omit") << " polling="
      << (c.rfid.polling == TRFIDConfig::Polling::RoundRobin ? "round_robin" : "together")
      << "\n         ir: moved=" << c.ir.moved.size()
      << " wrong_code_rate=" << c.ir.wrongCodeRate
      << " volt_outlier_rate=" << c.ir.voltOutlierRate << "\n";
}

}  // namespace rfir::sim
