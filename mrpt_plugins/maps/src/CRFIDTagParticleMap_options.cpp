/* rfir: INI options and map definition of CRFIDTagParticleMap. */
#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/models/ini_check.h>

#include <mrpt/core/bits_math.h>

#include <ostream>

using namespace rfir::maps;

MAP_DEFINITION_REGISTER("rfir::maps::CRFIDTagParticleMap,rfidTagMap",
                        rfir::maps::CRFIDTagParticleMap)

namespace {
const std::vector<std::string> kEstimatorNames = {"particle_filter",
                                                  "fixed_lag_smoother"};
const std::vector<std::string> kResamplingNames = {"systematic", "stratified",
                                                   "multinomial"};
const std::vector<std::string> kModelNames = {"step", "gaussian"};
const std::vector<std::string> kPolicyNames = {"literal", "revisit", "revisit_all"};
const std::vector<std::string> kRobotPoseNames = {"mean", "samples_init", "samples",
                                                  "samples_visit"};
const std::vector<std::string> kRobotLikNames = {"tag_mean", "tag_particles"};
}  // namespace

const std::vector<std::string>& CRFIDTagParticleMap::TInsertionOptions::allowedKeys() {
    static const std::vector<std::string> k = {
        "estimator",        "num_particles",       "lag",        "smoother_step_sigma",
        "roughening_sigma", "ess_threshold",       "resampling", "seed",
        "tag_robot_pose",   "spread_commit_travel"};
    return k;
}

void CRFIDTagParticleMap::TInsertionOptions::loadFromConfigFile(
    const mrpt::config::CConfigFileBase& c, const std::string& s) {
    rfir::checkIniKeys(c, s, allowedKeys());
    estimator = static_cast<TTagEstimatorKind>(rfir::readIniEnum(
        c, s, "estimator", kEstimatorNames, static_cast<size_t>(estimator)));
    numParticles = rfir::readIniPositiveInt(c, s, "num_particles", numParticles);
    lag = rfir::readIniPositiveInt(c, s, "lag", lag);
    smootherStepSigma =
        rfir::readIniDouble(c, s, "smoother_step_sigma", smootherStepSigma, 0.0, false);
    rougheningSigma =
        rfir::readIniDouble(c, s, "roughening_sigma", rougheningSigma, 0.0, false);
    essThreshold = rfir::readIniDouble(c, s, "ess_threshold", essThreshold, 0.0, true);
    if (essThreshold > 1.0)
        throw std::runtime_error("[" + s + "] ess_threshold: must be <= 1");
    resampling = static_cast<rfir::models::ResamplingScheme>(rfir::readIniEnum(
        c, s, "resampling", kResamplingNames, static_cast<size_t>(resampling)));
    const double sd =
        rfir::readIniDouble(c, s, "seed", static_cast<double>(seed), 0.0, false);
    if (sd != static_cast<double>(static_cast<uint64_t>(sd)))
        throw std::runtime_error("[" + s + "] seed: must be a non-negative integer");
    seed = static_cast<uint64_t>(sd);
    tagRobotPose = static_cast<TTagRobotPose>(rfir::readIniEnum(
        c, s, "tag_robot_pose", kRobotPoseNames, static_cast<size_t>(tagRobotPose)));
    spreadCommitTravel =
        rfir::readIniDouble(c, s, "spread_commit_travel", spreadCommitTravel, 0.0, false);
}

void CRFIDTagParticleMap::TInsertionOptions::dumpToTextStream(std::ostream& o) const {
    o << "estimator           = " << kEstimatorNames[static_cast<size_t>(estimator)]
      << "\n"
      << "num_particles       = " << numParticles << "\n"
      << "lag                 = " << lag << "\n"
      << "smoother_step_sigma = " << smootherStepSigma << "\n"
      << "roughening_sigma    = " << rougheningSigma << "\n"
      << "ess_threshold       = " << essThreshold << "\n"
      << "resampling          = " << rfir::models::toString(resampling) << "\n"
      << "seed                = " << seed << "\n"
      << "tag_robot_pose      = " << kRobotPoseNames[static_cast<size_t>(tagRobotPose)]
      << "\n"
      << "spread_commit_travel = " << spreadCommitTravel << "\n";
}

const std::vector<std::string>& CRFIDTagParticleMap::TLikelihoodOptions::allowedKeys() {
    static const std::vector<std::string> k = {
        "detection_model",      "beta",
        "gaussian_sigma_scale", "rb_sigma_range",
        "rb_sigma_bearing_deg", "robot_update",
        "revisit_min_gap",      "revisit_min_travel",
        "rb_use_landmark_cov",  "robot_likelihood",
        "robot_likelihood_k"};
    return k;
}

void CRFIDTagParticleMap::TLikelihoodOptions::loadFromConfigFile(
    const mrpt::config::CConfigFileBase& c, const std::string& s) {
    rfir::checkIniKeys(c, s, allowedKeys());
    detection.model = static_cast<rfir::models::DetectionModel>(rfir::readIniEnum(
        c, s, "detection_model", kModelNames, static_cast<size_t>(detection.model)));
    detection.beta = rfir::readIniDouble(c, s, "beta", detection.beta, 0.0, true);
    detection.gaussianSigmaScale = rfir::readIniDouble(
        c, s, "gaussian_sigma_scale", detection.gaussianSigmaScale, 0.0, true);
    rangeBearing.sigmaRange =
        rfir::readIniDouble(c, s, "rb_sigma_range", rangeBearing.sigmaRange, 0.0, true);
    rangeBearing.sigmaBearing = mrpt::DEG2RAD(
        rfir::readIniDouble(c, s, "rb_sigma_bearing_deg",
                            mrpt::RAD2DEG(rangeBearing.sigmaBearing), 0.0, true));
    robotUpdate = static_cast<TRobotUpdatePolicy>(rfir::readIniEnum(
        c, s, "robot_update", kPolicyNames, static_cast<size_t>(robotUpdate)));
    revisitMinGap = rfir::readIniPositiveInt(c, s, "revisit_min_gap", revisitMinGap);
    revisitMinTravel =
        rfir::readIniDouble(c, s, "revisit_min_travel", revisitMinTravel, 0.0, false);
    rbUseLandmarkCov = rfir::readIniEnum(c, s, "rb_use_landmark_cov", {"false", "true"},
                                         rbUseLandmarkCov ? 1 : 0) == 1;
    robotLikelihood = static_cast<TRobotLikelihood>(rfir::readIniEnum(
        c, s, "robot_likelihood", kRobotLikNames, static_cast<size_t>(robotLikelihood)));
    robotLikelihoodK = rfir::readIniPositiveInt(c, s, "robot_likelihood_k",
                                                robotLikelihoodK, kMaxRobotLikelihoodK);
}

void CRFIDTagParticleMap::TLikelihoodOptions::dumpToTextStream(std::ostream& o) const {
    o << "detection_model      = " << kModelNames[static_cast<size_t>(detection.model)]
      << "\n"
      << "beta                 = " << detection.beta << "\n"
      << "gaussian_sigma_scale = " << detection.gaussianSigmaScale << "\n"
      << "rb_sigma_range       = " << rangeBearing.sigmaRange << "\n"
      << "rb_sigma_bearing_deg = " << mrpt::RAD2DEG(rangeBearing.sigmaBearing) << "\n"
      << "robot_update         = " << kPolicyNames[static_cast<size_t>(robotUpdate)]
      << "\n"
      << "revisit_min_gap      = " << revisitMinGap << "\n"
      << "revisit_min_travel   = " << revisitMinTravel << "\n"
      << "rb_use_landmark_cov  = " << (rbUseLandmarkCov ? "true" : "false") << "\n"
      << "robot_likelihood     = " << kRobotLikNames[static_cast<size_t>(robotLikelihood)]
      << "\n"
      << "robot_likelihood_k   = " << robotLikelihoodK << "\n";
}

CRFIDTagParticleMap::TMapDefinition::TMapDefinition() = default;

void CRFIDTagParticleMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) {
    const std::string creation = prefix + "_creationOpts";
    if (source.sectionExists(creation)) {
        // MRPT reads its generic map options from the same section.
        rfir::checkIniKeys(source, creation,
                           {"prior_map_file", "enableSaveAs3DObject",
                            "enableObservationLikelihood", "enableObservationInsertion"});
        priorMapFile = source.read_string(creation, "prior_map_file", "");
    }
    insertionOpts.loadFromConfigFile(source, prefix + "_insertOpts");
    likelihoodOpts.loadFromConfigFile(source, prefix + "_likelihoodOpts");
}

void CRFIDTagParticleMap::TMapDefinition::dumpToTextStream_map_specific(
    std::ostream& out) const {
    out << "prior_map_file      = " << priorMapFile << "\n";
    insertionOpts.dumpToTextStream(out);
    likelihoodOpts.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CRFIDTagParticleMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& d) {
    const auto& def = dynamic_cast<const CRFIDTagParticleMap::TMapDefinition&>(d);
    auto* m = new CRFIDTagParticleMap();
    m->insertionOptions = def.insertionOpts;
    m->likelihoodOptions = def.likelihoodOpts;
    if (!def.priorMapFile.empty()) m->loadPriorFromTextFile(def.priorMapFile);
    return m;
}
