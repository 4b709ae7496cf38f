/* rfir: INI options and map definition of CIREmitterMap. */
#include <rfir/ir/ini_util.h>
#include <rfir/maps/CIREmitterMap.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/system/filesystem.h>

#include <memory>
#include <ostream>

using namespace rfir::maps;
namespace ini = rfir::ir::ini;

MAP_DEFINITION_REGISTER("rfir::maps::CIREmitterMap,irEmitterMap",
                        rfir::maps::CIREmitterMap)

namespace {
const std::vector<std::string> kHeightModels = {"fixed", "inverse_square", "angular"};
const std::vector<std::string> kAssociations = {"estimate", "particle"};
}  // namespace

const std::vector<std::string>& CIREmitterMap::TLikelihoodOptions::allowedKeys() {
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
                                               "out_of_range_ramp"};
    return k;
}

void CIREmitterMap::TLikelihoodOptions::loadFromConfigFile(
    const mrpt::config::CConfigFileBase& c, const std::string& s) {
    ini::checkKeys(c, s, allowedKeys());
    auto& cv = params.curve;
    cv.c0 = ini::readDouble(c, s, "curve_c0", cv.c0);
    cv.c1 = ini::readDouble(c, s, "curve_c1", cv.c1);
    cv.c2 = ini::readDouble(c, s, "curve_c2", cv.c2);
    cv.fitHeight = ini::readDouble(c, s, "fit_height", cv.fitHeight, 1e-3);
    cv.maxDistance = ini::readDouble(c, s, "max_distance", cv.maxDistance, 1e-3);
    cv.heightModel = rfir::ir::TVoltageCurve::HeightModel(
        ini::readEnum(c, s, "height_model", kHeightModels, size_t(cv.heightModel)));
    params.sigmaVolts = ini::readDouble(c, s, "sigma_volts", params.sigmaVolts, 1e-6);
    params.sigmaBelief = ini::readDouble(c, s, "sigma_belief", params.sigmaBelief, 1e-6);
    params.outOfRangeLogLik =
        ini::readDouble(c, s, "out_of_range_loglik", params.outOfRangeLogLik, -1e6, 0);
    params.missLogLik = ini::readDouble(c, s, "miss_loglik", params.missLogLik, -1e6, 0);
    params.missRadiusFraction =
        ini::readDouble(c, s, "miss_radius_fraction", params.missRadiusFraction, 0, 1);
    params.outOfRangeRamp =
        ini::readDouble(c, s, "out_of_range_ramp", params.outOfRangeRamp, 0);
    params.areaMargin = ini::readDouble(c, s, "area_margin", params.areaMargin, 0);
    params.outOfAreaLogLik =
        ini::readDouble(c, s, "out_of_area_loglik", params.outOfAreaLogLik, -1e6, 0);
    association = TAssociation(
        ini::readEnum(c, s, "association", kAssociations, size_t(association)));
    verticalDistance = ini::readDouble(c, s, "vertical_distance", verticalDistance, 0);
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
      << "area_margin         = " << params.areaMargin << "\n"
      << "out_of_area_loglik  = " << params.outOfAreaLogLik << "\n"
      << "association         = " << kAssociations[size_t(association)] << "\n"
      << "vertical_distance   = " << verticalDistance << "\n";
}

CIREmitterMap::TMapDefinition::TMapDefinition() = default;

void CIREmitterMap::TMapDefinition::loadFromConfigFile_map_specific(
    const mrpt::config::CConfigFileBase& c, const std::string& prefix) {
    const std::string s = prefix + "_creationOpts";
    ini::checkKeys(c, s, {"emitter_file"});
    emitterFile = ini::readString(c, s, "emitter_file", "");
    // A relative path is taken from the INI file's folder.
    const auto* f = dynamic_cast<const mrpt::config::CConfigFile*>(&c);
    if (!emitterFile.empty() && emitterFile[0] != '/' && f) {
        const std::string dir =
            mrpt::system::extractFileDirectory(f->getAssociatedFile());
        if (!dir.empty()) emitterFile = dir + "/" + emitterFile;
    }
    likelihoodOpts.loadFromConfigFile(c, prefix + "_likelihoodOpts");
}

void CIREmitterMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& o) const {
    o << "emitter_file        = " << emitterFile << "\n";
    likelihoodOpts.dumpToTextStream(o);
}

mrpt::maps::CMetricMap* CIREmitterMap::internal_CreateFromMapDefinition(
    const mrpt::maps::TMetricMapInitializer& d) {
    const auto& def = dynamic_cast<const CIREmitterMap::TMapDefinition&>(d);
    // Owned until returned: a bad emitter file throws (found by fuzz_ini: the
    // map leaked).
    auto m = std::make_unique<CIREmitterMap>();
    m->likelihoodOptions = def.likelihoodOpts;
    if (!def.emitterFile.empty()) m->loadEmitterFile(def.emitterFile);
    return m.release();
}
