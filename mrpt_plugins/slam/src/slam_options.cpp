#include <rfir/models/ini_reader.h>
#include <rfir/slam/slam_options.h>

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cctype>
#include <vector>

namespace rfir::slam {
using PF = mrpt::bayes::CParticleFilter;
namespace {
// In TMethod's order.
const std::vector<std::string> kMethodNames = {"pf", "ps", "fastslam", "odometry"};
const std::vector<std::string> kTagPoseNames = {"posterior", "predicted"};

[[noreturn]] void badSetting(const std::string& s, const std::string& k,
                             const std::string& why) {
    throw rfir::ini::CIniError("[" + s + "] " + k + ": " + why);
}
}  // namespace

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

namespace {
/** MRPT's enum names (prSystematic, ...) or the short ones (multinomial,
 * residual, stratified, systematic). */
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
}  // namespace

namespace {
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
}  // namespace

void TSlamOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                      const std::string& s) {
    using R = rfir::ini::TRange;
    const rfir::ini::CIniSection sec(
        c, s,
        {"method", "robot_particles", "resampling", "resample_ess", "start_std_xy",
         "start_std_phi", "tag_update_pose", "map_correction", "map_correction_min_std",
         "map_correction_max_tags", "read_confirm_window"});
    method = TMethod(sec.getEnum("method", kMethodNames, size_t(method)));
    robot_particles =
        unsigned(sec.getInt("robot_particles", int64_t(robot_particles), 1, 1000000));
    const std::string r = sec.getString("resampling", resamplingName(resampling));
    try {
        resampling = parseResampling(r);
    } catch (const std::invalid_argument&) {
        sec.fail("resampling", "unknown resampling scheme '" + r + "'");
    }
    sec.declare("resampling", "enum", resamplingName(resampling),
                "multinomial, residual, stratified, systematic (also MRPT's "
                "prMultinomial, ...)");
    resample_ess = sec.getDouble("resample_ess", resample_ess, R::aboveZero(1));
    start_std_xy = sec.getDouble("start_std_xy", start_std_xy, R::closed(0, 100));
    start_std_phi = sec.getDouble("start_std_phi", start_std_phi, R::closed(0, M_PI));
    tag_update_pose = TTagUpdatePose(
        sec.getEnum("tag_update_pose", kTagPoseNames, size_t(tag_update_pose)));
    map_correction = sec.getBool("map_correction", map_correction);
    map_correction_min_std =
        sec.getDouble("map_correction_min_std", map_correction_min_std, R::aboveZero(1));
    map_correction_max_tags = unsigned(sec.getInt(
        "map_correction_max_tags", int64_t(map_correction_max_tags), 1, 10000000));
    // A minute between two reads of one tag is a revisit, not a confirmation.
    read_confirm_window =
        sec.getDouble("read_confirm_window", read_confirm_window, R::closed(0, 60));
}

void TSlamOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                    const std::string& s) const {
    c.write(s, "method", methodName(method), -1, -1, "pf | ps | fastslam | odometry");
    c.write(s, "robot_particles", int(robot_particles), -1, -1, "robot particles M");
    c.write(s, "resampling", resamplingName(resampling), -1, -1,
            "multinomial | residual | stratified | systematic");
    c.write(s, "resample_ess", resample_ess, -1, -1,
            "resample when normalised ESS < this (1: every step)");
    c.write(s, "start_std_xy", start_std_xy, -1, -1, "initial spread [m]");
    c.write(s, "start_std_phi", start_std_phi, -1, -1, "initial spread [rad]");
    c.write(s, "tag_update_pose", kTagPoseNames[size_t(tag_update_pose)], -1, -1,
            "pf/ps weigh-first: tags updated at the posterior or predicted mean");
    c.write(s, "map_correction", map_correction, -1, -1,
            "pf/ps: tags follow the robot's loop-closure corrections");
    c.write(s, "map_correction_min_std", map_correction_min_std, -1, -1,
            "[m] a tag's share of the robot error below which it stops following");
    c.write(s, "map_correction_max_tags", int(map_correction_max_tags), -1, -1,
            "at most this many tags follow the robot (the oldest leave first)");
    c.write(s, "read_confirm_window", read_confirm_window, -1, -1,
            "pf/ps [s]: a read weighs the robot only after a read of its tag this "
            "recently (0: every read)");
}

PF::TParticleFilterOptions TSlamOptions::pfOptions() const {
    PF::TParticleFilterOptions o;
    o.PF_algorithm = PF::pfStandardProposal;
    o.resamplingMethod = resampling;
    o.BETA = resample_ess;
    o.sampleSize = robot_particles;
    o.adaptiveSampleSize = false;
    return o;
}

}  // namespace rfir::slam
