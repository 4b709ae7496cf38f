/* rfir-localize: the run's configuration (INI + command line). */
#pragma once

#include <rfir/ir/ir_localizer.h>
#include <rfir/maps/CIREmitterMap.h>

#include <memory>
#include <string>
#include <vector>

namespace rfir::localize {
struct TConfig {
    std::string iniPath;  //!< the INI read (stock or --config)
    std::string rawlogPath;
    std::string emitterPath;  //!< --emitters, else the INI's emitter_file
    std::string outDir;
    /** The ground-truth path (TUM) the run is scored against: --gt-path, else
     * <stem>.gt.tum beside the rawlog when it exists; empty: none. */
    std::string gtPath;
    uint64_t seed = 1;
    bool odometryOnly = false;
    bool quiet = false;
    /** "SECTION.KEY=VALUE" written over the INI before it is read (--set). */
    std::vector<std::string> overrides;
    rfir::ir::TLocalizerParams params;
    std::shared_ptr<rfir::maps::CIREmitterMap> map;
};

/** The text of an exception without MRPT's banners and backtrace. */
std::string cleanMessage(const std::exception& e);

/** <exe_dir>/../share/rfir/config_ini/ir_localize.ini */
std::string stockIniPath();

/** The sections loadConfig knows (for routing a program's --set edits). */
std::vector<std::string> configSections();

/** Reads the INI: sections [localization], [motion], [MetricMap] and the
 * emitter map's sections, created through MRPT's map factory
 * (TSetOfMetricMapInitializers + CMultiMetricMap). Unknown sections and keys
 * are errors naming them. `emitterOverride` (non-empty) replaces
 * emitter_file. Fills cfg.params, cfg.map, cfg.emitterPath. `requireEmitters`
 * false: no emitter file is no error (a check of the INI and its --set edits
 * before the emitters exist). */
void loadConfig(TConfig& cfg, const std::string& emitterOverride,
                bool requireEmitters = true);

/** The effective configuration as an INI (settings.ini). */
std::string settingsIni(const TConfig& cfg, const std::string& commandLine);

}  // namespace rfir::localize
