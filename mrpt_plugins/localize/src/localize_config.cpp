/* rfir-localize: configuration. */
#include <rfir/localize/localize_config.h>

#include <rfir/common/ini_file.h>
#include <rfir/common/ini_override.h>
#include <rfir/common/install_paths.h>
#include <rfir/models/ini_reader.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace rfir::localize {
namespace {
const std::string kMapPrefix = "MetricMap_irEmitterMap_00";

void checkSections(const mrpt::config::CConfigFileBase& c) {
    rfir::ini::checkSections(c, configSections());
    const rfir::ini::CIniSection mm(c, "MetricMap", {"irEmitterMap_count"});
    mm.getInt("irEmitterMap_count", 1, 1, 1);
    const rfir::ini::CIniSection ins(
        c, kMapPrefix + "_insertOpts",
        {"enableSaveAs3DObject", "enableObservationLikelihood",
         "enableObservationInsertion"});
    for (const char* k : {"enableSaveAs3DObject", "enableObservationLikelihood",
                          "enableObservationInsertion"})
        ins.getBool(k, true);
}
}  // namespace

std::vector<std::string> configSections() {
    return {"localization",
            "motion",
            "MetricMap",
            kMapPrefix + "_creationOpts",
            kMapPrefix + "_insertOpts",
            kMapPrefix + "_likelihoodOpts"};
}

std::string cleanMessage(const std::exception& e) {
    // MRPT wraps exceptions that cross its code in banners and a backtrace:
    // keep the text lines only.
    std::istringstream in(e.what());
    std::string line, out;
    while (std::getline(in, line)) {
        if (line.rfind("====", 0) == 0 || line.rfind("Call stack", 0) == 0 ||
            line.rfind("[", 0) == 0 || line.empty())
            continue;
        if (line.rfind("Message: ", 0) == 0) line = line.substr(9);
        if (line.rfind("Location: ", 0) == 0) continue;
        out += (out.empty() ? "" : " ") + line;
    }
    return out.empty() ? std::string(e.what()) : out;
}

std::string stockIniPath() {
    return rfir::common::stockConfigDir() + "/ir_localize.ini";
}

void loadConfig(TConfig& cfg, const std::string& emitterOverride, bool requireEmitters) {
    // A memory copy: CConfigFile would write our additions back to the file.
    auto c = rfir::common::readIniFile(cfg.iniPath);
    rfir::common::applyIniOverrides(c, cfg.overrides);  // a bad edit: a usage error
    std::string ef;
    try {
        checkSections(c);
        cfg.params.loadFromConfigFile(c, "");
        // The map as MRPT builds its own: initializers, then a multi-map. Set
        // the count to 1 when the section omits it.
        if (!c.keyExists("MetricMap", "irEmitterMap_count"))
            c.write("MetricMap", "irEmitterMap_count", 1);
        // --emitters wins; a relative emitter_file is relative to the INI.
        const std::string sec = kMapPrefix + "_creationOpts";
        ef = rfir::ini::CIniSection(c, sec, {"emitter_file"})
                 .getString("emitter_file", "");
        if (!emitterOverride.empty())
            ef = std::filesystem::absolute(emitterOverride).string();
        else if (!ef.empty() && std::filesystem::path(ef).is_relative())
            ef = (std::filesystem::path(cfg.iniPath).parent_path() / ef).string();
        // Absolute for the map factory, which takes a relative one from the
        // INI's folder.
        if (!ef.empty())
            c.write(sec, "emitter_file", std::filesystem::absolute(ef).string());
        // Check our sections and the emitter file first: errors raised inside
        // MRPT's map factory come back wrapped in its exception format.
        rfir::maps::CIREmitterMap::TLikelihoodOptions check;
        check.loadFromConfigFile(c, kMapPrefix + "_likelihoodOpts");
        if (!ef.empty()) rfir::ir::TEmitterSet::load(ef);
        mrpt::maps::TSetOfMetricMapInitializers inits;
        inits.loadFromConfigFile(c, "MetricMap");
        mrpt::maps::CMultiMetricMap mm;
        mm.setListOfMaps(inits);
        cfg.map = mm.mapByClass<rfir::maps::CIREmitterMap>();
        cfg.emitterPath = ef;
    } catch (const rfir::ini::CIniError&) {
        throw;  // names file, section and key already
    } catch (const std::exception& e) {
        // MRPT's map factory wraps what crosses it in banners: keep the text.
        const std::string what = cleanMessage(e);
        // Emitter-file errors name their file and line; the INI reader's name
        // the INI.
        if (what.rfind(ef + ":", 0) == 0) throw std::runtime_error(what);
        if (what.rfind(cfg.iniPath + ":", 0) == 0) throw rfir::ini::CIniError(what);
        throw rfir::ini::CIniError(cfg.iniPath + ": " + what);
    }
    if (!cfg.map)
        throw rfir::ini::CIniError(cfg.iniPath +
                                   ": [MetricMap]: no irEmitterMap was created");
    if (cfg.emitterPath.empty() && requireEmitters)
        throw rfir::ini::CIniError(cfg.iniPath + ": [" + kMapPrefix +
                                   "_creationOpts] emitter_file: no emitter file (set it "
                                   "or give --emitters FILE)");
}

std::string settingsIni(const TConfig& cfg, const std::string& commandLine) {
    std::ostringstream o;
    o << "# rfir-localize effective settings; rerun with --config this_file\n"
      << "# " << commandLine << "\n"
      << "# rawlog = " << cfg.rawlogPath << "\n# seed = " << cfg.seed
      << "\n# mode = " << (cfg.odometryOnly ? "odometry-only" : "monte-carlo") << "\n";
    for (const auto& s : cfg.overrides) o << "# --set " << s << "\n";
    o << "\n";
    cfg.params.dumpToTextStream(o);
    o << "\n[MetricMap]\nirEmitterMap_count = 1\n\n[" << kMapPrefix
      << "_creationOpts]\nemitter_file = " << cfg.emitterPath << "\n\n[" << kMapPrefix
      << "_likelihoodOpts]\n";
    cfg.map->likelihoodOptions.dumpToTextStream(o);
    return o.str();
}

}  // namespace rfir::localize
