/* rfir-sim: the run parameters and their INI sections. */
#include <rfir/common/ini_file.h>
#include <rfir/common/ini_override.h>
#include <rfir/common/text_input.h>
#include <rfir/sim/simulator.h>

#include "ini_section.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rfir::sim {
using detail::CIniSection;

std::vector<rfir::obs::TRFIDReader> ringReaderLayout(double ringRadius, double halfSize) {
    std::vector<rfir::obs::TRFIDReader> rs;
    for (int k = 0; k < 8; k++) {
        const double a = mrpt::DEG2RAD(22.5 + 45.0 * k);
        rfir::obs::TRFIDReader r;
        r.id = "R" + std::to_string(k);
        // Rounded to 0.1 mm so that the INI dump reproduces it exactly.
        r.x = std::round(ringRadius * std::cos(a) * 1e4) / 1e4;
        r.y = std::round(ringRadius * std::sin(a) * 1e4) / 1e4;
        r.halfX = r.halfY = halfSize;
        rs.push_back(r);
    }
    return rs;
}

TSimConfig::TSimConfig() {
    readers = ringReaderLayout(0.15, 0.03);
    receivers = {{"IR0", 0.0, 0.15, 0.3}, {"IR1", 0.0, -0.15, 0.3}};
}

namespace {
void loadSimulation(const CIniSection& s, TSimConfig& c) {
    s.positive("dt", c.dt, 10);
    s.positive("start_time", c.startTime, 1e9);
    s.nonNegative("max_duration", c.maxDuration, 1e7);
    std::vector<std::vector<double>> a;
    if (s.numberLists("area", {4}, a)) {
        if (a.size() != 1) s.fail("area", "expected one entry 'min_x min_y max_x max_y'");
        c.areaMinX = a[0][0], c.areaMinY = a[0][1], c.areaMaxX = a[0][2],
        c.areaMaxY = a[0][3];
        if (!(c.areaMaxX > c.areaMinX && c.areaMaxY > c.areaMinY))
            s.fail("area", "max must exceed min");
    }
}

void loadRobot(const CIniSection& s, TSimConfig& c) {
    double half = 0.03, ring = 0.15;
    s.positive("reader_half_size", half, 10);
    s.positive("reader_ring_radius", ring, 100);
    std::vector<std::vector<double>> l;
    if (s.numberLists("readers", {2, 4}, l)) {
        if (l.empty()) s.fail("readers", "at least one reader is needed");
        c.readers.clear();
        for (size_t i = 0; i < l.size(); i++) {
            rfir::obs::TRFIDReader r;
            r.id = "R" + std::to_string(i);
            r.x = l[i][0], r.y = l[i][1];
            r.halfX = l[i].size() == 4 ? l[i][2] : half;
            r.halfY = l[i].size() == 4 ? l[i][3] : half;
            if (!(r.halfX > 0 && r.halfY > 0))
                s.fail("readers", "half sizes must be > 0");
            c.readers.push_back(r);
        }
    } else if (s.has("reader_half_size") || s.has("reader_ring_radius"))
        c.readers = ringReaderLayout(ring, half);
    if (s.numberLists("receivers", {3}, l)) {
        c.receivers.clear();
        for (size_t i = 0; i < l.size(); i++)
            c.receivers.push_back({"IR" + std::to_string(i), l[i][0], l[i][1], l[i][2]});
    }
}

void loadTrajectory(const CIniSection& s, TTrajectoryConfig& t) {
    using K = TTrajectoryConfig::Kind;
    using R = TTrajectoryConfig::Rotation;
    const int k = s.choice("type", {"loop", "predefined", "random", "lawnmower"});
    if (k >= 0) t.kind = K(k);
    const int r = s.choice("rotation", {"none", "follow", "spin"});
    if (r >= 0) t.rotation = R(r);
    s.integer("laps", t.laps, 1, 1000);
    s.integer("predefined", t.predefined, 1, 5);
    s.integer("waypoints", t.waypoints, 2, 100000);
    s.positive("stripe_spacing", t.stripeSpacing, 1000);
    s.nonNegative("margin", t.margin, 1000);
    s.positive("speed", t.speed, 100);
    s.positive("turn_rate", t.turnRate, 100);
    s.num("spin_rate", t.spinRate, -100, 100);
    double deg = mrpt::RAD2DEG(t.startPhi);
    s.num("start_phi_deg", deg, -3600, 3600);
    t.startPhi = mrpt::DEG2RAD(deg);
    s.integer("spots", t.spots, 0, 100000);
    s.positive("spot_pause", t.spotPause, 1e5);
}

void loadKidnap(const CIniSection& s, TKidnapConfig& k) {
    s.boolean("enabled", k.enabled);
    s.nonNegative("time", k.time, 1e7);
    s.nonNegative("carry_time", k.carryTime, 1e7);
    s.nonNegative("to_time", k.toTime, 1e7);
    std::vector<std::vector<double>> p;
    if (s.numberLists("to_pose", {3}, p)) {
        if (p.size() != 1) s.fail("to_pose", "expected one entry 'x y phi_deg'");
        if (s.has("to_time")) s.fail("to_pose", "give either to_pose or to_time");
        k.toTime = -1;
        k.toX = p[0][0], k.toY = p[0][1], k.toPhi = mrpt::DEG2RAD(p[0][2]);
    }
    const int o = s.choice("odometry", {"frozen", "stop"});
    if (o >= 0) k.odometry = TKidnapConfig::Odometry(o);
}

void loadOdometry(const CIniSection& s, TOdometryNoise& o) {
    s.nonNegative("k_xy", o.kXY, 1);
    s.nonNegative("k_phi_rot", o.kPhiRot, M_PI);
    s.nonNegative("k_phi_xy", o.kPhiXY, M_PI);
    s.nonNegative("scale_sigma", o.scaleSigma, 1);
    s.nonNegative("rot_scale_sigma", o.rotScaleSigma, 1);
    s.nonNegative("heading_drift_sigma", o.headingDriftSigma, M_PI);
}

void loadRFID(const CIniSection& s, TRFIDConfig& r) {
    s.boolean("enabled", r.enabled);
    s.positive("density", r.density, 1e6);
    s.nonNegative("placement_sigma", r.placementSigma, 100);
    s.nonNegative("miss_probability", r.missProbability, 1);
    if (r.missProbability >= 1) s.fail("miss_probability", "must be < 1");
    s.text("uid_prefix", r.uidPrefix);
    for (char ch : r.uidPrefix)
        if (!std::isxdigit(static_cast<unsigned char>(ch)))
            s.fail("uid_prefix", "must be hexadecimal digits");
    if (r.uidPrefix.size() > 56) s.fail("uid_prefix", "at most 56 digits");
}
}  // namespace

// IR and range-and-bearing sections live in sim_config_ir.cpp, the fault keys
// in sim_config_faults.cpp.
void loadIRSection(const CIniSection& s, TIRConfig& ir);
void loadOdometryFaults(const CIniSection& s, TOdometryNoise& o);
void loadRFIDFaults(const CIniSection& s, TRFIDConfig& r);
void loadIRFaults(const CIniSection& s, TIRConfig& ir);
void loadRBSection(const CIniSection& s, TSimConfig& c);

void TSimConfig::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                    const std::string& p) {
    loadSimulation(
        CIniSection(cfg, p + "simulation", {"dt", "start_time", "max_duration", "area"}),
        *this);
    loadRobot(
        CIniSection(cfg, p + "robot",
                    {"readers", "reader_half_size", "reader_ring_radius", "receivers"}),
        *this);
    loadTrajectory(CIniSection(cfg, p + "trajectory",
                               {"type", "rotation", "laps", "predefined", "waypoints",
                                "stripe_spacing", "margin", "speed", "turn_rate",
                                "spin_rate", "start_phi_deg", "spots", "spot_pause"}),
                   trajectory);
    loadKidnap(
        CIniSection(cfg, p + "kidnap",
                    {"enabled", "time", "carry_time", "to_time", "to_pose", "odometry"}),
        kidnap);
    const CIniSection odo(
        cfg, p + "odometry",
        {"k_xy", "k_phi_rot", "k_phi_xy", "scale_sigma", "rot_scale_sigma",
         "heading_drift_sigma", "scale_error", "rot_scale_error", "heading_drift_error",
         "rate", "latency", "slip_times", "slip_count", "slip_size", "slip_heading_deg"});
    loadOdometry(odo, odometry);
    loadOdometryFaults(odo, odometry);
    const CIniSection rf(cfg, p + "rfid",
                         {"enabled", "density", "placement_sigma", "miss_probability",
                          "uid_prefix", "ghost_rate", "ghost_distance", "dead_readers",
                          "empty_polls", "polling", "poll_rate", "poll_jitter"});
    loadRFID(rf, rfid);
    loadRFIDFaults(rf, rfid);
    const CIniSection irs(cfg, p + "ir",
                          {"enabled",
                           "pitch",
                           "ceiling_height",
                           "height_spread",
                           "reference_height",
                           "repeated_codes",
                           "unique_codes_per_id",
                           "with_repeated",
                           "with_unique",
                           "all_unique",
                           "visible_radius",
                           "volt_sigma",
                           "output",
                           "rate_hz",
                           "samples",
                           "raw_noise_sigma",
                           "raw_offset",
                           "period",
                           "failed",
                           "moved",
                           "wrong_code_rate",
                           "wrong_code_other_id",
                           "volt_outlier_rate",
                           "volt_outlier_max"});
    loadIRSection(irs, ir);
    loadIRFaults(irs, ir);
    loadRBSection(CIniSection(cfg, p + "range_bearing",
                              {"enabled", "density", "sensor_pose", "max_range",
                               "fov_deg", "sigma_range", "sigma_bearing_deg"}),
                  *this);
}

const std::vector<std::string>& simConfigSections() {
    static const std::vector<std::string> kSections = {
        "simulation", "robot", "trajectory", "kidnap",
        "odometry",   "rfid",  "ir",         "range_bearing"};
    return kSections;
}

TSimConfig loadSimConfig(const std::string& iniPath,
                         const std::vector<std::string>& overrides) {
    auto f = rfir::common::readIniFile(iniPath);
    rfir::common::applyIniOverrides(f, overrides);
    rfir::ini::checkSections(f, simConfigSections());
    TSimConfig c;
    try {
        c.loadFromConfigFile(f, "");
        c.validate();
    } catch (const rfir::ini::CIniError&) {
        throw;  // names the file already
    } catch (const std::exception& e) {
        throw rfir::ini::CIniError(iniPath + ": " + e.what());
    }
    return c;
}

}  // namespace rfir::sim
