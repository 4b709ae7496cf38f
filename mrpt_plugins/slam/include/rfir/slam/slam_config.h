/* rfir: every setting of a SLAM run, from one INI file (config_ini/slam_*.ini).
 * Our sections reject unknown keys and unknown sections, naming them. */
#pragma once

#include <rfir/slam/CFastSLAMParticles.h>
#include <rfir/slam/graph_smoother_options.h>
#include <rfir/slam/kidnap.h>
#include <rfir/slam/motion_model.h>
#include <rfir/slam/slam_options.h>

#include <mrpt/config/CConfigFileBase.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rfir::slam {
struct TTagMapSettings;  // tagmap_engine.h

struct TSlamConfig {
    TSlamOptions slam;               //!< [slam]
    TMotionOptions motion;           //!< [motion]
    TKidnapOptions kidnap;           //!< [kidnap]
    TFastSLAMOptions fastslam;       //!< [fastslam]
    TGraphSmootherOptions smoother;  //!< [smoother] (--smooth)
    /** The tag map's options (PF-SLAM / PS-SLAM), see tagmap_engine.h. */
    std::shared_ptr<TTagMapSettings> tagmap;
    /** Seed of every random draw of the run (--seed), not an INI key. */
    uint64_t seed = 1;
    TMethod method() const { return slam.method; }
};

/** Loads and checks every section; `methodOverride` (from --method) replaces
 * [slam] method. Throws std::invalid_argument naming the section and key. */
TSlamConfig loadSlamConfig(const mrpt::config::CConfigFileBase& ini,
                           const std::optional<std::string>& methodOverride = {});
TSlamConfig loadSlamConfigFile(const std::string& path,
                               const std::optional<std::string>& methodOverride = {});
/** Every effective setting, as an INI text (settings.ini). */
std::string dumpSlamConfig(const TSlamConfig& cfg);
/** The sections loadSlamConfig knows (for routing a program's --set edits). */
std::vector<std::string> slamConfigSections();

}  // namespace rfir::slam
