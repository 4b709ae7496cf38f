/* rfir: INI options and map definition of CRFIDTagParticleMap. */
#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/models/ini_reader.h>

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <memory>
#include <ostream>
#include <stdexcept>

using namespace rfir::maps;

MAP_DEFINITION_REGISTER("rfir::maps::CRFIDTagParticleMap,rfidTagMap",
                        rfir::maps::CRFIDTagParticleMap)

namespace {
const std::vector<std::string> kResamplingNames = {"systematic", "stratified",
                                                   "multinomial"};
const std::vector<std::string> kModelNames = {"step", "gaussian"};
const std::vector<std::string> kPolicyNames = {"literal", "revisit", "revisit_all"};
const std::vector<std::string> kRobotPoseNames = {"mean", "samples_init", "samples",
                                                  "samples_visit"};
const std::vector<std::string> kRobotLikNames = {"tag_mean", "tag_particles"};
}  // namespace

namespace {
const std::vector<std::string>& insertionKeys() {
    static const std::vector<std::string> k = {"estimator",
                                               "num_particles",
                                               "lag",
                                               "smoother_step_sigma",
                                               "roughening_sigma",
                                               "ess_threshold",
                                               "resampling",
                                               "seed",
                                               "tag_robot_pose",
                                               "spread_commit_travel",
                                               "reseat_contradicted",
                                               "contradict_margin",
                                               "hold_outvoted",
                                               "negative_information",
                                               "negative_window",
                                               "negative_min_half_size"};
    return k;
}
}  // namespace

void CRFIDTagParticleMap::TInsertionOptions::loadFromConfigFile(
    const mrpt::config::CConfigFileBase& c, const std::string& s) {
    using rfir::ini::TRange;
    const rfir::ini::CIniSection sec(c, s, insertionKeys());
    // Any registered estimator (one file and one registration line each).
    const auto names = rfir::models::tagEstimatorNames();
    const auto at = std::find(names.begin(), names.end(), estimator);
    if (at == names.end())
        throw std::invalid_argument("CRFIDTagParticleMap: estimator '" + estimator +
                                    "' set in code is not registered");
    estimator = names[sec.getEnum("estimator", names, size_t(at - names.begin()))];
    params.numParticles =
        size_t(sec.getInt("num_particles", int64_t(params.numParticles), 1, 1000000));
    params.lag = size_t(sec.getInt("lag", int64_t(params.lag), 1, 100000));
    // Sizes in metres: 10 m is far beyond any reader footprint or tag spread.
    params.stepSigma =
        sec.getDouble("smoother_step_sigma", params.stepSigma, TRange::closed(0, 10));
    params.rougheningSigma =
        sec.getDouble("roughening_sigma", params.rougheningSigma, TRange::closed(0, 10));
    params.essThreshold =
        sec.getDouble("ess_threshold", params.essThreshold, TRange::aboveZero(1));
    params.resampling = static_cast<rfir::models::ResamplingScheme>(sec.getEnum(
        "resampling", kResamplingNames, static_cast<size_t>(params.resampling)));
    seed = sec.getUInt64("seed", seed);
    tagRobotPose = static_cast<TTagRobotPose>(sec.getEnum(
        "tag_robot_pose", kRobotPoseNames, static_cast<size_t>(tagRobotPose)));
    spreadCommitTravel = sec.getDouble("spread_commit_travel", spreadCommitTravel,
                                       TRange::closed(0, 100000));
    reseatContradicted = sec.getBool("reseat_contradicted", reseatContradicted);
    contradictMargin =
        sec.getDouble("contradict_margin", contradictMargin, TRange::closed(-1, 10));
    holdOutvoted = sec.getBool("hold_outvoted", holdOutvoted);
    // p_d = 1 would give a particle inside an unread square weight 0.
    negativeInformation = sec.getDouble("negative_information", negativeInformation,
                                        TRange::closed(0, 0.99));
    negativeWindow =
        uint64_t(sec.getInt("negative_window", int64_t(negativeWindow), 1, 1000000));
    negativeMinHalfSize = sec.getDouble("negative_min_half_size", negativeMinHalfSize,
                                        TRange::closed(0, 10));
}

void CRFIDTagParticleMap::TInsertionOptions::dumpToTextStream(std::ostream& o) const {
    o << "estimator           = " << estimator << "\n"
      << "num_particles       = " << params.numParticles << "\n"
      << "lag                 = " << params.lag << "\n"
      << "smoother_step_sigma = " << params.stepSigma << "\n"
      << "roughening_sigma    = " << params.rougheningSigma << "\n"
      << "ess_threshold       = " << params.essThreshold << "\n"
      << "resampling          = " << rfir::models::toString(params.resampling) << "\n"
      << "seed                = " << seed << "\n"
      << "tag_robot_pose      = " << kRobotPoseNames[static_cast<size_t>(tagRobotPose)]
      << "\n"
      << "spread_commit_travel = " << spreadCommitTravel << "\n"
      << "reseat_contradicted = " << (reseatContradicted ? "true" : "false") << "\n"
      << "contradict_margin   = " << contradictMargin << "\n"
      << "hold_outvoted       = " << (holdOutvoted ? "true" : "false") << "\n"
      << "negative_information = " << negativeInformation << "\n"
      << "negative_window     = " << negativeWindow << "\n"
      << "negative_min_half_size = " << negativeMinHalfSize << "\n";
}

namespace {
const std::vector<std::string>& likelihoodKeys() {
    static const std::vector<std::string> k = {
        "detection_model",      "beta",
        "gaussian_sigma_scale", "rb_sigma_range",
        "rb_sigma_bearing_deg", "robot_update",
        "revisit_min_gap",      "revisit_min_travel",
        "rb_use_landmark_cov",  "robot_likelihood",
        "robot_likelihood_k",   "outlier_weight",
        "outlier_log_floor",    "robot_negative_information"};
    return k;
}
}  // namespace

void CRFIDTagParticleMap::TLikelihoodOptions::loadFromConfigFile(
    const mrpt::config::CConfigFileBase& c, const std::string& s) {
    using rfir::ini::TRange;
    const rfir::ini::CIniSection sec(c, s, likelihoodKeys());
    detection.model = static_cast<rfir::models::DetectionModel>(sec.getEnum(
        "detection_model", kModelNames, static_cast<size_t>(detection.model)));
    detection.beta = sec.getDouble("beta", detection.beta, TRange::aboveZero(100));
    detection.gaussianSigmaScale = sec.getDouble(
        "gaussian_sigma_scale", detection.gaussianSigmaScale, TRange::aboveZero(100));
    // A share of ghost reads above one half would make the model itself the
    // outlier; the floor is log(reader area / area reads can come from).
    detection.outlierWeight =
        sec.getDouble("outlier_weight", detection.outlierWeight, TRange::closed(0, 0.5));
    detection.outlierLogFloor = sec.getDouble(
        "outlier_log_floor", detection.outlierLogFloor, TRange::closed(-50, 0));
    rangeBearing.sigmaRange =
        sec.getDouble("rb_sigma_range", rangeBearing.sigmaRange, TRange::aboveZero(100));
    rangeBearing.sigmaBearing = mrpt::DEG2RAD(
        sec.getDouble("rb_sigma_bearing_deg", mrpt::RAD2DEG(rangeBearing.sigmaBearing),
                      TRange::aboveZero(180)));
    robotUpdate = static_cast<TRobotUpdatePolicy>(
        sec.getEnum("robot_update", kPolicyNames, static_cast<size_t>(robotUpdate)));
    revisitMinGap =
        size_t(sec.getInt("revisit_min_gap", int64_t(revisitMinGap), 1, 100000000));
    revisitMinTravel =
        sec.getDouble("revisit_min_travel", revisitMinTravel, TRange::closed(0, 100000));
    rbUseLandmarkCov = sec.getBool("rb_use_landmark_cov", rbUseLandmarkCov);
    robotLikelihood = static_cast<TRobotLikelihood>(sec.getEnum(
        "robot_likelihood", kRobotLikNames, static_cast<size_t>(robotLikelihood)));
    robotLikelihoodK = size_t(sec.getInt("robot_likelihood_k", int64_t(robotLikelihoodK),
                                         1, int64_t(kMaxRobotLikelihoodK)));
    robotNegativeInformation = sec.getDouble(
        "robot_negative_information", robotNegativeInformation, TRange::closed(0, 0.99));
}

void CRFIDTagParticleMap::TLikelihoodOptions::dumpToTextStream(std::ostream& o) const {
    o << "detection_model      = " << kModelNames[static_cast<size_t>(detection.model)]
      << "\n"
      << "beta                 = " << detection.beta << "\n"
      << "gaussian_sigma_scale = " << detection.gaussianSigmaScale << "\n"
      << "outlier_weight       = " << detection.outlierWeight << "\n"
      << "outlier_log_floor    = " << detection.outlierLogFloor << "\n"
      << "rb_sigma_range       = " << rangeBearing.sigmaRange << "\n"
      << "rb_sigma_bearing_deg = " << mrpt::RAD2DEG(rangeBearing.sigmaBearing) << "\n"
      << "robot_update         = " << kPolicyNames[static_cast<size_t>(robotUpdate)]
      << "\n"
      << "revisit_min_gap      = " << revisitMinGap << "\n"
      << "revisit_min_travel   = " << revisitMinTravel << "\n"
      << "rb_use_landmark_cov  = " << (rbUseLandmarkCov ? "true" : "false") << "\n"
      << "robot_likelihood     = " << kRobotLikNames[static_cast<size_t>(robotLikelihood)]
      << "\n"
      << "robot_likelihood_k   = " << robotLikelihoodK << "\n"
      << "robot_negative_information = " << robotNegativeInformation << "\n";
}

CRFIDTagParticleMap::TMapDefinition::TMapDefinition() = default;

// MRPT 2.5.8's TSetOfMetricMapInitializers::loadFromConfigFile holds the new
// definition in a raw pointer while this runs and leaks it when this throws:
// the error is kept and raised by internal_CreateFromMapDefinition, which every
// loader of [MetricMap] reaches next (CMultiMetricMap).
void CRFIDTagParticleMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& source, const std::string& prefix) try {
    loadError = nullptr;
    const std::string creation = prefix + "_creationOpts";
    if (source.sectionExists(creation)) {
        // MRPT reads its generic map options from the same section.
        const rfir::ini::CIniSection sec(
            source, creation,
            {"prior_map_file", "enableSaveAs3DObject", "enableObservationLikelihood",
             "enableObservationInsertion"});
        priorMapFile = sec.getString("prior_map_file", "");
        for (const char* k : {"enableSaveAs3DObject", "enableObservationLikelihood",
                              "enableObservationInsertion"})
            sec.getBool(k, true);
    }
    insertionOpts.loadFromConfigFile(source, prefix + "_insertOpts");
    likelihoodOpts.loadFromConfigFile(source, prefix + "_likelihoodOpts");
} catch (...) {
    loadError = std::current_exception();
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
    if (def.loadError) std::rethrow_exception(def.loadError);
    // Owned until returned: a prior file that is refused must not leak the map.
    auto m = std::make_unique<CRFIDTagParticleMap>();
    m->insertionOptions = def.insertionOpts;
    m->likelihoodOptions = def.likelihoodOpts;
    if (!def.priorMapFile.empty()) m->loadPriorFromTextFile(def.priorMapFile);
    return m.release();
}
