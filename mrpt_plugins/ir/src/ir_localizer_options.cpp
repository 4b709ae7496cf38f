/* rfir: INI sections [localization] and [motion] of the IR localization. */
#include <rfir/ir/ini_util.h>
#include <rfir/ir/ir_localizer.h>

#include <ostream>
#include <sstream>

namespace rfir::ir {
namespace {
const std::vector<std::string> kResampling = {"multinomial", "residual", "stratified",
                                              "systematic"};

void readArea(const mrpt::config::CConfigFileBase& c, const std::string& s,
              TLocalizerParams& p) {
    const std::string txt = ini::readString(c, s, "init_area", "");
    if (txt.empty()) return;
    std::istringstream in(txt);
    double v[4];
    for (auto& x : v)
        if (!(in >> x))
            throw std::runtime_error(
                "INI section [" + s +
                "], key 'init_area': expected \"x0 y0 x1 y1\", got '" + txt + "'");
    std::string rest;
    if ((in >> rest) || !(v[2] > v[0] && v[3] > v[1]))
        throw std::runtime_error("INI section [" + s +
                                 "], key 'init_area': expected x0 y0 x1 y1 with x1 > x0, "
                                 "y1 > y0, got '" +
                                 txt + "'");
    p.initX0 = v[0];
    p.initY0 = v[1];
    p.initX1 = v[2];
    p.initY1 = v[3];
    p.initAreaSet = true;
}
}  // namespace

void TLocalizerParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                          const std::string& prefix) {
    const std::string s = prefix + "localization";
    ini::checkKeys(c, s,
                   {"num_particles", "init_area", "init_margin", "start_from_reading",
                    "sensor_resetting", "reset_min_fraction", "reset_ratio",
                    "reset_distance_sigma", "reset_view_margin", "repeated_before_unique",
                    "association_max_std", "ess_threshold", "resampling", "decode_raw"});
    numParticles = ini::readSize(c, s, "num_particles", numParticles, 1, 10000000);
    readArea(c, s, *this);
    initMargin = ini::readDouble(c, s, "init_margin", initMargin, 0);
    startFromReading = ini::readBool(c, s, "start_from_reading", startFromReading);
    sensorResetting = ini::readBool(c, s, "sensor_resetting", sensorResetting);
    resetMinFraction =
        ini::readDouble(c, s, "reset_min_fraction", resetMinFraction, 0, 1);
    resetRatio = ini::readDouble(c, s, "reset_ratio", resetRatio, 0, 1);
    resetDistanceSigma =
        ini::readDouble(c, s, "reset_distance_sigma", resetDistanceSigma, 0);
    resetViewMargin = ini::readDouble(c, s, "reset_view_margin", resetViewMargin, 0);
    repeatedBeforeUnique =
        ini::readBool(c, s, "repeated_before_unique", repeatedBeforeUnique);
    associationMaxStd =
        ini::readDouble(c, s, "association_max_std", associationMaxStd, 0);
    essThreshold = ini::readDouble(c, s, "ess_threshold", essThreshold, 0, 1);
    resampling = mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm(
        ini::readEnum(c, s, "resampling", kResampling, size_t(resampling)));
    decodeRaw = ini::readBool(c, s, "decode_raw", decodeRaw);

    const std::string m = prefix + "motion";
    ini::checkKeys(c, m,
                   {"k_xy", "k_phi_rot", "k_phi_xy", "scale_sigma", "rot_scale_sigma",
                    "heading_drift", "min_std_xy", "min_std_phi"});
    motion.kXY = ini::readDouble(c, m, "k_xy", motion.kXY, 0);
    motion.kPhiRot = ini::readDouble(c, m, "k_phi_rot", motion.kPhiRot, 0);
    motion.kPhiXY = ini::readDouble(c, m, "k_phi_xy", motion.kPhiXY, 0);
    motion.scaleSigma = ini::readDouble(c, m, "scale_sigma", motion.scaleSigma, 0);
    motion.rotScaleSigma =
        ini::readDouble(c, m, "rot_scale_sigma", motion.rotScaleSigma, 0);
    motion.headingDrift = ini::readDouble(c, m, "heading_drift", motion.headingDrift, 0);
    motion.minStdXY = ini::readDouble(c, m, "min_std_xy", motion.minStdXY, 0);
    motion.minStdPhi = ini::readDouble(c, m, "min_std_phi", motion.minStdPhi, 0);
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
      << "sensor_resetting = " << b(sensorResetting) << "\n"
      << "reset_min_fraction = " << resetMinFraction << "\n"
      << "reset_ratio = " << resetRatio << "\n"
      << "reset_distance_sigma = " << resetDistanceSigma << "\n"
      << "reset_view_margin = " << resetViewMargin << "\n"
      << "repeated_before_unique = " << b(repeatedBeforeUnique) << "\n"
      << "association_max_std = " << associationMaxStd << "\n"
      << "ess_threshold = " << essThreshold << "\n"
      << "resampling = " << kResampling[size_t(resampling)] << "\n"
      << "decode_raw = " << b(decodeRaw) << "\n\n"
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
