/* rfir: INI options and map definition of CIREmitterMap. */
#include <rfir/maps/CIREmitterMap.h>
#include <rfir/models/ini_reader.h>

#include <mrpt/system/filesystem.h>

#include <memory>
#include <ostream>

using namespace rfir::maps;
using R = rfir::ini::TRange;

MAP_DEFINITION_REGISTER("rfir::maps::CIREmitterMap,irEmitterMap",
                        rfir::maps::CIREmitterMap)

namespace {
const std::vector<std::string> kHeightModels = {"fixed", "inverse_square", "angular"};
const std::vector<std::string> kAssociations = {"estimate", "particle"};
}  // namespace

namespace {
const std::vector<std::string>& likelihoodKeys() {
    static const std::vector<std::string> k = {"curve_c0",
                                               "curve_c1",
                                               "curve_c2",
                                               "fit_height",
                                               "max_distance",
                                               "height_model",
                                               "sigma_volts",
                                               "sigma_belief",
                                               "association",
                                               "out_of_range_loglik",
                                               "vertical_distance",
                                               "miss_loglik",
                                               "miss_radius_fraction",
                                               "area_margin",
                                               "out_of_area_loglik",
                                               "out_of_range_ramp",
                                               "volt_outlier_weight",
                                               "volt_outlier_range"};
    return k;
}
}  // namespace

void CIREmitterMap::TLikelihoodOptions::loadFromConfigFile(
    const mrpt::config::CConfigFileBase& c, const std::string& s) {
    const rfir::ini::CIniSection s_sec(c, s, likelihoodKeys());
    auto& cv = params.curve;
    cv.c0 = s_sec.getDouble("curve_c0", cv.c0, R::closed(-1000, 1000));
    cv.c1 = s_sec.getDouble("curve_c1", cv.c1, R::closed(-1000, 1000));
    cv.c2 = s_sec.getDouble("curve_c2", cv.c2, R::closed(-1000, 1000));
    cv.fitHeight = s_sec.getDouble("fit_height", cv.fitHeight, R::closed(1e-3, 100));
    cv.maxDistance =
        s_sec.getDouble("max_distance", cv.maxDistance, R::closed(1e-3, 1000));
    cv.heightModel = rfir::ir::TVoltageCurve::HeightModel(
        s_sec.getEnum("height_model", kHeightModels, size_t(cv.heightModel)));
    params.sigmaVolts =
        s_sec.getDouble("sigma_volts", params.sigmaVolts, R::closed(1e-6, 100));
    params.sigmaBelief =
        s_sec.getDouble("sigma_belief", params.sigmaBelief, R::closed(1e-6, 100));
    params.outOfRangeLogLik = s_sec.getDouble(
        "out_of_range_loglik", params.outOfRangeLogLik, R::closed(-1e6, 0));
    params.missLogLik =
        s_sec.getDouble("miss_loglik", params.missLogLik, R::closed(-1e6, 0));
    params.missRadiusFraction = s_sec.getDouble(
        "miss_radius_fraction", params.missRadiusFraction, R::closed(0, 1));
    params.outOfRangeRamp =
        s_sec.getDouble("out_of_range_ramp", params.outOfRangeRamp, R::closed(0, 1000));
    params.voltOutlierWeight =
        s_sec.getDouble("volt_outlier_weight", params.voltOutlierWeight, R::closed(0, 1));
    params.voltOutlierRange = s_sec.getDouble(
        "volt_outlier_range", params.voltOutlierRange, R::closed(1e-3, 1000));
    params.areaMargin =
        s_sec.getDouble("area_margin", params.areaMargin, R::closed(0, 1000));
    params.outOfAreaLogLik =
        s_sec.getDouble("out_of_area_loglik", params.outOfAreaLogLik, R::closed(-1e6, 0));
    association =
        TAssociation(s_sec.getEnum("association", kAssociations, size_t(association)));
    verticalDistance =
        s_sec.getDouble("vertical_distance", verticalDistance, R::closed(0, 100));
}

void CIREmitterMap::TLikelihoodOptions::dumpToTextStream(std::ostream& o) const {
    const auto& cv = params.curve;
    o << "curve_c0            = " << cv.c0 << "\n"
      << "curve_c1            = " << cv.c1 << "\n"
      << "curve_c2            = " << cv.c2 << "\n"
      << "fit_height          = " << cv.fitHeight << "\n"
      << "max_distance        = " << cv.maxDistance << "\n"
      << "height_model        = " << kHeightModels[size_t(cv.heightModel)] << "\n"
      << "sigma_volts         = " << params.sigmaVolts << "\n"
      << "sigma_belief        = " << params.sigmaBelief << "\n"
      << "out_of_range_loglik = " << params.outOfRangeLogLik << "\n"
      << "miss_loglik         = " << params.missLogLik << "\n"
      << "miss_radius_fraction = " << params.missRadiusFraction << "\n"
      << "out_of_range_ramp   = " << params.outOfRangeRamp << "\n"
      << "volt_outlier_weight = " << params.voltOutlierWeight << "\n"
      << "volt_outlier_range  = " << params.voltOutlierRange << "\n"
      << "area_margin         = " << params.areaMargin << "\n"
      << "out_of_area_loglik  = " << params.outOfAreaLogLik << "\n"
      << "association         = " << kAssociations[size_t(association)] << "\n"
      << "vertical_distance   = " << verticalDistance << "\n";
}

CIREmitterMap::TMapDefinition::TMapDefinition() = default;

// Errors are kept and raised at creation: MRPT leaks the definition when this
// throws (see CRFIDTagParticleMap::TMapDefinition).
void CIREmitterMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& c, const std::string& prefix) try {
    loadError = nullptr;
    const std::string s = prefix + "_creationOpts";
    const rfir::ini::CIniSection s_sec(c, s, {"emitter_file"});
    emitterFile = s_sec.getString("emitter_file", "");
    // A relative path is taken from the INI file's folder.
    const std::string ini = rfir::ini::fileNameOf(c);
    if (!emitterFile.empty() && emitterFile[0] != '/' && !ini.empty()) {
        const std::string dir = mrpt::system::extractFileDirectory(ini);
        if (!dir.empty()) emitterFile = dir + "/" + emitterFile;
    }
    likelihoodOpts.loadFromConfigFile(c, prefix + "_likelihoodOpts");
} catch (...) {
    loadError = std::current_exception();
}

void CIREmitterMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& o) const {
    o << "emitter_file        = " << emitterFile << "\n";
    likelihoodOpts.dumpToTextStream(o);
}

mrpt::maps::CMetricMap* CIREmitterMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& d) {
    const auto& def = dynamic_cast<const CIREmitterMap::TMapDefinition&>(d);
    if (def.loadError) std::rethrow_exception(def.loadError);
    // Owned until returned: a bad emitter file throws (found by fuzz_ini: the
    // map leaked).
    auto m = std::make_unique<CIREmitterMap>();
    m->likelihoodOptions = def.likelihoodOpts;
    if (!def.emitterFile.empty()) m->loadEmitterFile(def.emitterFile);
    return m.release();
}
