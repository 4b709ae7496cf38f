#include <rfir/slam/ini_check.h>
#include <rfir/slam/slam_options.h>

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cctype>

namespace rfir::slam {
using PF = mrpt::bayes::CParticleFilter;

TMethod parseMethod(const std::string& name) {
    if (name == "pf") return TMethod::PF;
    if (name == "ps") return TMethod::PS;
    if (name == "fastslam") return TMethod::FastSLAM;
    if (name == "odometry") return TMethod::Odometry;
    badSetting("slam", "method",
               "unknown method '" + name + "' (pf, ps, fastslam or odometry)");
}

std::string methodName(TMethod m) {
    switch (m) {
        case TMethod::PF:
            return "pf";
        case TMethod::PS:
            return "ps";
        case TMethod::FastSLAM:
            return "fastslam";
        default:
            return "odometry";
    }
}

PF::TParticleResamplingAlgorithm parseResampling(const std::string& name) {
    std::string n = name;
    std::transform(n.begin(), n.end(), n.begin(), ::tolower);
    if (n.rfind("pr", 0) == 0) n = n.substr(2);
    if (n == "multinomial") return PF::prMultinomial;
    if (n == "residual") return PF::prResidual;
    if (n == "stratified") return PF::prStratified;
    if (n == "systematic") return PF::prSystematic;
    badSetting("slam", "resampling",
               "unknown resampling scheme '" + name +
                   "' (multinomial, residual, stratified, systematic or MRPT's "
                   "prMultinomial, prResidual, prStratified, prSystematic)");
}

std::string resamplingName(PF::TParticleResamplingAlgorithm r) {
    switch (r) {
        case PF::prMultinomial:
            return "multinomial";
        case PF::prResidual:
            return "residual";
        case PF::prStratified:
            return "stratified";
        default:
            return "systematic";
    }
}

void TSlamOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                      const std::string& s) {
    method = c.read_string(s, "method", method);
    parseMethod(method);
    const int m = c.read_int(s, "robot_particles", int(robot_particles));
    if (m <= 0) badSetting(s, "robot_particles", "must be a positive count");
    robot_particles = unsigned(m);
    resampling = c.read_string(s, "resampling", resampling);
    resampling = resamplingName(parseResampling(resampling));
    resample_ess = c.read_double(s, "resample_ess", resample_ess);
    if (!(resample_ess > 0 && resample_ess <= 1))
        badSetting(s, "resample_ess", "must be in (0, 1]");
    start_std_xy = c.read_double(s, "start_std_xy", start_std_xy);
    start_std_phi = c.read_double(s, "start_std_phi", start_std_phi);
    if (!(start_std_xy >= 0)) badSetting(s, "start_std_xy", "must be >= 0");
    if (!(start_std_phi >= 0)) badSetting(s, "start_std_phi", "must be >= 0");
    tag_update_pose = c.read_string(s, "tag_update_pose", tag_update_pose);
    if (tag_update_pose != "posterior" && tag_update_pose != "predicted")
        badSetting(s, "tag_update_pose", "must be posterior or predicted");
}

void TSlamOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                    const std::string& s) const {
    c.write(s, "method", method, -1, -1, "pf | ps | fastslam | odometry");
    c.write(s, "robot_particles", int(robot_particles), -1, -1, "robot particles M");
    c.write(s, "resampling", resampling, -1, -1,
            "multinomial | residual | stratified | systematic");
    c.write(s, "resample_ess", resample_ess, -1, -1,
            "resample when normalised ESS < this (1: every step)");
    c.write(s, "start_std_xy", start_std_xy, -1, -1, "initial spread [m]");
    c.write(s, "start_std_phi", start_std_phi, -1, -1, "initial spread [rad]");
    c.write(s, "tag_update_pose", tag_update_pose, -1, -1,
            "pf/ps weigh-first: tags updated at the posterior or predicted mean");
}

PF::TParticleFilterOptions TSlamOptions::pfOptions() const {
    PF::TParticleFilterOptions o;
    o.PF_algorithm = PF::pfStandardProposal;
    o.resamplingMethod = parseResampling(resampling);
    o.BETA = resample_ess;
    o.sampleSize = robot_particles;
    o.adaptiveSampleSize = false;
    return o;
}

}  // namespace rfir::slam
