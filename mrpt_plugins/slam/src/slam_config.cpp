#include <rfir/common/ini_file.h>
#include <rfir/models/ini_reader.h>
#include <rfir/slam/slam_config.h>
#include <rfir/slam/tagmap_engine.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <stdexcept>
#include <vector>

namespace rfir::slam {
namespace {
template <class Opts>
void loadSection(Opts& o, const mrpt::config::CConfigFileBase& ini,
                 const std::string& s) {
    o.loadFromConfigFile(ini, s);  // each section refuses keys it does not read
}
}  // namespace

TSlamConfig loadSlamConfig(const mrpt::config::CConfigFileBase& ini,
                           const std::optional<std::string>& methodOverride) {
    TSlamConfig c;
    rfir::ini::checkSections(ini, slamConfigSections());
    loadSection(c.slam, ini, "slam");
    if (methodOverride) c.slam.method = parseMethod(*methodOverride);
    loadSection(c.motion, ini, "motion");
    loadSection(c.kidnap, ini, "kidnap");
    loadSection(c.fastslam, ini, "fastslam");
    loadSection(c.smoother, ini, "smoother");
    c.tagmap = loadTagMapOptions(ini, c.method());
    return c;
}

TSlamConfig loadSlamConfigFile(const std::string& path,
                               const std::optional<std::string>& methodOverride) {
    return loadSlamConfig(rfir::common::readIniFile(path), methodOverride);
}

std::vector<std::string> slamConfigSections() {
    std::vector<std::string> v = {"slam", "motion", "kidnap", "fastslam", "smoother"};
    for (const auto& s : tagMapSections()) v.push_back(s);
    return v;
}

std::string dumpSlamConfig(const TSlamConfig& cfg) {
    mrpt::config::CConfigFileMemory mem;
    cfg.slam.saveToConfigFile(mem, "slam");
    cfg.motion.saveToConfigFile(mem, "motion");
    cfg.kidnap.saveToConfigFile(mem, "kidnap");
    cfg.fastslam.saveToConfigFile(mem, "fastslam");
    cfg.smoother.saveToConfigFile(mem, "smoother");
    return mem.getContent() + "\n" + dumpTagMapOptions(cfg.tagmap, cfg.seed);
}

}  // namespace rfir::slam
