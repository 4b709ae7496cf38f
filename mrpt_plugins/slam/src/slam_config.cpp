#include <rfir/models/ini_reader.h>
#include <rfir/slam/slam_config.h>
#include <rfir/slam/tagmap_engine.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/filesystem.h>

#include <filesystem>
#include <set>
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
    std::vector<std::string> sections;
    ini.getAllSections(sections);
    const std::set<std::string> ours = {"slam", "motion", "kidnap", "fastslam",
                                        "smoother"};
    const std::set<std::string> mapSections = tagMapSections();
    for (const auto& s : sections)
        if (!s.empty() && !ours.count(s) && !mapSections.count(s))
            throw rfir::ini::CIniError(rfir::ini::fileOf(ini) + "unknown section [" + s +
                                       "] (known: slam, motion, "
                                       "kidnap, fastslam, smoother, " +
                                       joinSections(mapSections) + ")");
    loadSection(c.slam, ini, "slam");
    if (methodOverride) c.slam.method = methodName(parseMethod(*methodOverride));
    loadSection(c.motion, ini, "motion");
    loadSection(c.kidnap, ini, "kidnap");
    loadSection(c.fastslam, ini, "fastslam");
    loadSection(c.smoother, ini, "smoother");
    c.tagmap = loadTagMapOptions(ini, c.method());
    return c;
}

TSlamConfig loadSlamConfigFile(const std::string& path,
                               const std::optional<std::string>& methodOverride) {
    if (!mrpt::system::fileExists(path))
        throw std::invalid_argument("cannot read INI file '" + path + "'");
    // CConfigFile reads any file whole: refuse a directory, a device or a
    // file far larger than any INI (rfir::common::kMaxIniFileBytes).
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw std::invalid_argument(path + ": not a regular file (INI file)");
    if (std::filesystem::file_size(path, ec) > (uint64_t(16) << 20))
        throw std::invalid_argument(path +
                                    ": over the 16777216-byte limit of an INI file");
    mrpt::config::CConfigFile f(path);
    try {
        return loadSlamConfig(f, methodOverride);
    } catch (const std::exception& e) {
        // The reader's errors already start with the file's name.
        const std::string what = e.what();
        if (what.rfind(path + ": ", 0) == 0) throw;
        throw rfir::ini::CIniError(path + ": " + what);
    }
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
