/* rfir-sim: [ir] and [range_bearing] sections, validation and dump. */
#include <rfir/obs/ir_codes.h>
#include <rfir/obs/ir_decoder.h>
#include <rfir/sim/simulator.h>

#include "ini_section.h"

#include <cmath>

#include <mrpt/core/bits_math.h>

#include <ostream>
#include <sstream>
#include <stdexcept>

namespace rfir::sim {
using detail::CIniSection;

void loadIRSection(const CIniSection& s, TIRConfig& ir) {
    s.boolean("enabled", ir.enabled);
    s.positive("pitch", ir.pitch, 1000);
    s.positive("ceiling_height", ir.ceilingHeight, 1000);
    s.nonNegative("height_spread", ir.heightSpread, 1000);
    s.positive("reference_height", ir.referenceHeight, 1000);
    std::vector<std::string> es;
    if (s.entries("repeated_codes", es)) {
        ir.repeatedCodes.clear();
        for (const auto& e : es) {
            if (e.size() != 1 || e[0] < '1' || e[0] > '9')
                s.fail("repeated_codes", "'" + e + "' is not a code 1..9");
            ir.repeatedCodes.push_back(uint8_t(e[0] - '0'));
        }
        if (ir.repeatedCodes.empty()) s.fail("repeated_codes", "at least one code");
    }
    s.integer("unique_codes_per_id", ir.uniqueCodesPerId, 2, 9);
    s.boolean("with_repeated", ir.withRepeated);
    s.boolean("with_unique", ir.withUnique);
    s.boolean("all_unique", ir.allUnique);
    s.positive("visible_radius", ir.visibleRadius, 1000);
    s.nonNegative("volt_sigma", ir.voltSigma, 100);
    const int o = s.choice("output", {"decoded", "raw"});
    if (o >= 0) ir.output = TIRConfig::Output(o);
    s.positive("rate_hz", ir.rateHz, 1e6);
    s.integer("samples", ir.samples, 16, 1 << 20);
    s.nonNegative("raw_noise_sigma", ir.rawNoiseSigma, 100);
    s.num("raw_offset", ir.rawOffset, -1000, 1000);
    s.positive("period", ir.period, 1e6);
    if (s.entries("failed", ir.failed))
        for (const auto& e : ir.failed) {
            std::vector<double> xy;
            double v = 0;
            std::string tok;
            std::istringstream is(e);
            while (is >> tok)
                if (detail::parseNumber(tok, v)) xy.push_back(v);
            const bool isId = rfir::ir::codesFromEmitterId(e).has_value();
            if (!isId && xy.size() != 2)
                s.fail("failed", "'" + e + "' is neither an emitter ID nor 'x y'");
        }
    if (ir.output == TIRConfig::Output::Raw &&
        ir.samples / ir.rateHz < rfir::ir::kMinWindowSeconds)
        s.fail("samples", "the raw window (samples / rate_hz) must last at least 0.04 s");
}

void loadRBSection(const CIniSection& s, TSimConfig& c) {
    s.boolean("enabled", c.rb.enabled);
    s.positive("density", c.rb.density, 1e6);
    std::vector<std::vector<double>> p;
    if (s.numberLists("sensor_pose", {3}, p)) {
        if (p.size() != 1) s.fail("sensor_pose", "expected one entry 'x y yaw_deg'");
        c.rbSensor.x = p[0][0], c.rbSensor.y = p[0][1];
        c.rbSensor.yaw = mrpt::DEG2RAD(p[0][2]);
    }
    s.positive("max_range", c.rbSensor.maxRange, 1e4);
    double fov = mrpt::RAD2DEG(c.rbSensor.fov);
    s.positive("fov_deg", fov, 360);
    if (fov > 360) s.fail("fov_deg", "must be <= 360");
    c.rbSensor.fov = mrpt::DEG2RAD(fov);
    s.nonNegative("sigma_range", c.rb.sigmaRange, 100);
    double sb = mrpt::RAD2DEG(c.rb.sigmaBearing);
    s.nonNegative("sigma_bearing_deg", sb, 180);
    c.rb.sigmaBearing = mrpt::DEG2RAD(sb);
}

void validateFaults(const TSimConfig& c);
void dumpFaults(const TSimConfig& c, std::ostream& o);

void TSimConfig::validate() const {
    auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
    if (!(dt > 0)) bad("[simulation] dt must be > 0");
    if (!(startTime > 0)) bad("[simulation] start_time must be > 0");
    if (!(areaMaxX > areaMinX && areaMaxY > areaMinY)) bad("[simulation] area is empty");
    const double w = areaMaxX - areaMinX, h = areaMaxY - areaMinY;
    if (2 * trajectory.margin >= w || 2 * trajectory.margin >= h)
        bad("[trajectory] margin leaves no room inside the area");
    if (readers.empty() && rfid.enabled) bad("[robot] readers: none declared");
    if ((ir.enabled) && receivers.empty()) bad("[robot] receivers: none declared");
    if (ir.enabled && !ir.withRepeated && !ir.withUnique)
        bad("[ir] with_repeated and with_unique are both false");
    if (ir.enabled && ir.ceilingHeight - ir.heightSpread <= 0)
        bad("[ir] height_spread exceeds ceiling_height");
    if (kidnap.enabled && kidnap.toTime >= 0 && kidnap.toTime >= kidnap.time)
        bad("[kidnap] time and [kidnap] to_time: to_time must be earlier than time");
    if (!rfid.enabled && !ir.enabled && !rb.enabled)
        bad("[rfid] enabled, [ir] enabled, [range_bearing] enabled: no sensor enabled");
    validateFaults(*this);
}

void TSimConfig::dumpToTextStream(std::ostream& o) const {
    o << "[simulation] dt=" << dt << " start_time=" << startTime
      << " max_duration=" << maxDuration << " area=" << areaMinX << " " << areaMinY << " "
      << areaMaxX << " " << areaMaxY << "\n";
    o << "[robot] readers=";
    for (size_t i = 0; i < readers.size(); i++)
        o << (i ? ", " : "") << readers[i].x << " " << readers[i].y << " "
          << readers[i].halfX << " " << readers[i].halfY;
    o << "\n        receivers=";
    for (size_t i = 0; i < receivers.size(); i++)
        o << (i ? ", " : "") << receivers[i].x << " " << receivers[i].y << " "
          << receivers[i].z;
    static const char* kinds[] = {"loop", "predefined", "random", "lawnmower"};
    static const char* rots[] = {"none", "follow", "spin"};
    const auto& t = trajectory;
    o << "\n[trajectory] type=" << kinds[int(t.kind)]
      << " rotation=" << rots[int(t.rotation)] << " laps=" << t.laps
      << " predefined=" << t.predefined << " waypoints=" << t.waypoints
      << " stripe_spacing=" << t.stripeSpacing << " margin=" << t.margin
      << " speed=" << t.speed << " spots=" << t.spots << "\n";
    if (kidnap.enabled)
        o << "[kidnap] time=" << kidnap.time << " carry_time=" << kidnap.carryTime
          << " to_time=" << kidnap.toTime << "\n";
    const auto& n = odometry;
    o << "[odometry] k_xy=" << n.kXY << " k_phi_rot=" << n.kPhiRot
      << " k_phi_xy=" << n.kPhiXY << " scale_sigma=" << n.scaleSigma
      << " rot_scale_sigma=" << n.rotScaleSigma
      << " heading_drift_sigma=" << n.headingDriftSigma << "\n";
    o << "[rfid] enabled=" << rfid.enabled << " density=" << rfid.density
      << " placement_sigma=" << rfid.placementSigma
      << " miss_probability=" << rfid.missProbability << "\n";
    o << "[ir] enabled=" << ir.enabled << " pitch=" << ir.pitch
      << " ceiling_height=" << ir.ceilingHeight << " height_spread=" << ir.heightSpread
      << " visible_radius=" << ir.visibleRadius << " volt_sigma=" << ir.voltSigma
      << " output=" << (ir.output == TIRConfig::Output::Raw ? "raw" : "decoded") << "\n";
    o << "[range_bearing] enabled=" << rb.enabled << " density=" << rb.density
      << " max_range=" << rbSensor.maxRange << " fov_deg=" << mrpt::RAD2DEG(rbSensor.fov)
      << "\n";
    dumpFaults(*this, o);
}

}  // namespace rfir::sim
