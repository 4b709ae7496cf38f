/* rfir: INI sections [localization] and [motion] of the IR localization. */
#include <rfir/ir/ir_localizer.h>
#include <rfir/models/ini_reader.h>

#include <cmath>
#include <ostream>
#include <sstream>

namespace rfir::ir {
namespace {
using R = rfir::ini::TRange;
const std::vector<std::string> kStartPose = {"unknown", "log"};
const std::vector<std::string> kResampling = {"multinomial", "residual", "stratified",
                                              "systematic"};

void readArea(const rfir::ini::CIniSection& s_sec, TLocalizerParams& p) {
    const std::string txt = s_sec.getString("init_area", "");
    s_sec.declare("init_area", "4 reals", "(the emitters' box + init_margin)",
                  "x0 y0 x1 y1, each in [-1e6, 1e6], x1 > x0, y1 > y0");
    if (txt.empty()) return;
    std::istringstream in(txt);
    double v[4];
    for (auto& x : v)
        if (!(in >> x) || !std::isfinite(x) || std::abs(x) > 1e6)
            s_sec.fail(
                "init_area",
                "expected \"x0 y0 x1 y1\" (metres, within 1e6), got '" + txt + "'");
    std::string rest;
    if ((in >> rest) || !(v[2] > v[0] && v[3] > v[1]))
        s_sec.fail("init_area",
                   "expected x0 y0 x1 y1 with x1 > x0, y1 > y0, got '" + txt + "'");
    p.initX0 = v[0];
    p.initY0 = v[1];
    p.initX1 = v[2];
    p.initY1 = v[3];
    p.initAreaSet = true;
}

void readRobust(const rfir::ini::CIniSection& s, TRobustParams& r) {
    r.gateMaxStd = s.getDouble("gate_max_std", r.gateMaxStd, R::closed(0, 1000));
    r.gateLogLik = s.getDouble("gate_loglik", r.gateLogLik, R::closed(-1e6, 0));
    r.gateMinFraction =
        s.getDouble("gate_min_fraction", r.gateMinFraction, R::closed(0, 1));
    r.lostMinReadings =
        size_t(s.getInt("lost_min_readings", int64_t(r.lostMinReadings), 1, 1000000));
    r.lostMinIds = size_t(s.getInt("lost_min_ids", int64_t(r.lostMinIds), 1, 1000));
    // The emitter lookup grid bounds the radius (TEmitterSet::kGridCell).
    r.emitterCheckRadius = s.getDouble("emitter_check_radius", r.emitterCheckRadius,
                                       R::closed(0, TEmitterSet::kGridCell));
    r.emitterMinChecks =
        size_t(s.getInt("emitter_min_checks", int64_t(r.emitterMinChecks), 1, 1000000));
    r.inconsistentWeight =
        s.getDouble("inconsistent_weight", r.inconsistentWeight, R::closed(0, 1));
}
}  // namespace

void TLocalizerParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                          const std::string& prefix) {
    const std::string s = prefix + "localization";
    const rfir::ini::CIniSection s_sec(c, s,
                                       {"num_particles",       "init_area",
                                        "init_margin",         "start_from_reading",
                                        "start_history",       "start_pose",
                                        "start_std_xy",        "start_std_phi",
                                        "sensor_resetting",    "reset_min_fraction",
                                        "reset_ratio",         "reset_distance_sigma",
                                        "reset_view_margin",   "repeated_before_unique",
                                        "association_max_std", "ess_threshold",
                                        "resampling",          "decode_raw",
                                        "gate_max_std",        "gate_loglik",
                                        "gate_min_fraction",   "lost_min_readings",
                                        "lost_min_ids",        "emitter_check_radius",
                                        "emitter_min_checks",  "inconsistent_weight"});
    numParticles =
        size_t(s_sec.getInt("num_particles", int64_t(numParticles), 1, 10000000));
    readArea(s_sec, *this);
    initMargin = s_sec.getDouble("init_margin", initMargin, R::closed(0, 1000));
    startFromReading = s_sec.getBool("start_from_reading", startFromReading);
    startHistory = s_sec.getDouble("start_history", startHistory, R::closed(0, 1000));
    startFromLog = s_sec.getEnum("start_pose", kStartPose, startFromLog ? 1 : 0) == 1;
    startStdXY = s_sec.getDouble("start_std_xy", startStdXY, R::closed(0, 1000));
    startStdPhi = s_sec.getDouble("start_std_phi", startStdPhi, R::closed(0, M_PI));
    sensorResetting = s_sec.getBool("sensor_resetting", sensorResetting);
    resetMinFraction =
        s_sec.getDouble("reset_min_fraction", resetMinFraction, R::closed(0, 1));
    resetRatio = s_sec.getDouble("reset_ratio", resetRatio, R::closed(0, 1));
    resetDistanceSigma =
        s_sec.getDouble("reset_distance_sigma", resetDistanceSigma, R::closed(0, 1000));
    resetViewMargin =
        s_sec.getDouble("reset_view_margin", resetViewMargin, R::closed(0, 1000));
    repeatedBeforeUnique = s_sec.getBool("repeated_before_unique", repeatedBeforeUnique);
    associationMaxStd =
        s_sec.getDouble("association_max_std", associationMaxStd, R::closed(0, 1000));
    essThreshold = s_sec.getDouble("ess_threshold", essThreshold, R::closed(0, 1));
    resampling = mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm(
        s_sec.getEnum("resampling", kResampling, size_t(resampling)));
    decodeRaw = s_sec.getBool("decode_raw", decodeRaw);
    readRobust(s_sec, robust);

    const std::string m = prefix + "motion";
    const rfir::ini::CIniSection m_sec(
        c, m,
        {"k_xy", "k_phi_rot", "k_phi_xy", "scale_sigma", "rot_scale_sigma",
         "heading_drift", "min_std_xy", "min_std_phi"});
    motion.kXY = m_sec.getDouble("k_xy", motion.kXY, R::closed(0, 1));
    motion.kPhiRot = m_sec.getDouble("k_phi_rot", motion.kPhiRot, R::closed(0, M_PI));
    motion.kPhiXY = m_sec.getDouble("k_phi_xy", motion.kPhiXY, R::closed(0, M_PI));
    motion.scaleSigma =
        m_sec.getDouble("scale_sigma", motion.scaleSigma, R::closed(0, 1));
    motion.rotScaleSigma =
        m_sec.getDouble("rot_scale_sigma", motion.rotScaleSigma, R::closed(0, 1));
    motion.headingDrift =
        m_sec.getDouble("heading_drift", motion.headingDrift, R::closed(0, M_PI));
    motion.minStdXY = m_sec.getDouble("min_std_xy", motion.minStdXY, R::closed(0, 1));
    motion.minStdPhi =
        m_sec.getDouble("min_std_phi", motion.minStdPhi, R::closed(0, M_PI));
}

void TLocalizerParams::dumpToTextStream(std::ostream& o) const {
    auto b = [](bool v) { return v ? "true" : "false"; };
    o << "[localization]\n"
      << "num_particles = " << numParticles << "\n";
    if (initAreaSet)
        o << "init_area = " << initX0 << " " << initY0 << " " << initX1 << " " << initY1
          << "\n";
    o << "init_margin = " << initMargin << "\n"
      << "start_from_reading = " << b(startFromReading) << "\n"
      << "start_history = " << startHistory << "\n"
      << "start_pose = " << kStartPose[startFromLog ? 1 : 0] << "\n"
      << "start_std_xy = " << startStdXY << "\n"
      << "start_std_phi = " << startStdPhi << "\n"
      << "sensor_resetting = " << b(sensorResetting) << "\n"
      << "reset_min_fraction = " << resetMinFraction << "\n"
      << "reset_ratio = " << resetRatio << "\n"
      << "reset_distance_sigma = " << resetDistanceSigma << "\n"
      << "reset_view_margin = " << resetViewMargin << "\n"
      << "repeated_before_unique = " << b(repeatedBeforeUnique) << "\n"
      << "association_max_std = " << associationMaxStd << "\n"
      << "ess_threshold = " << essThreshold << "\n"
      << "resampling = " << kResampling[size_t(resampling)] << "\n"
      << "decode_raw = " << b(decodeRaw) << "\n"
      << "gate_max_std = " << robust.gateMaxStd << "\n"
      << "gate_loglik = " << robust.gateLogLik << "\n"
      << "gate_min_fraction = " << robust.gateMinFraction << "\n"
      << "lost_min_readings = " << robust.lostMinReadings << "\n"
      << "lost_min_ids = " << robust.lostMinIds << "\n"
      << "emitter_check_radius = " << robust.emitterCheckRadius << "\n"
      << "emitter_min_checks = " << robust.emitterMinChecks << "\n"
      << "inconsistent_weight = " << robust.inconsistentWeight << "\n\n"
      << "[motion]\n"
      << "k_xy = " << motion.kXY << "\n"
      << "k_phi_rot = " << motion.kPhiRot << "\n"
      << "k_phi_xy = " << motion.kPhiXY << "\n"
      << "scale_sigma = " << motion.scaleSigma << "\n"
      << "rot_scale_sigma = " << motion.rotScaleSigma << "\n"
      << "heading_drift = " << motion.headingDrift << "\n"
      << "min_std_xy = " << motion.minStdXY << "\n"
      << "min_std_phi = " << motion.minStdPhi << "\n";
}

}  // namespace rfir::ir
