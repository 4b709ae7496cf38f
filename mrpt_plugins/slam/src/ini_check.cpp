#include <rfir/slam/ini_check.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/string_utils.h>

#include <stdexcept>
#include <vector>

namespace rfir::slam {
std::set<std::string> knownKeysOf(const mrpt::config::CLoadableOptions& opts,
                                  const std::string& section) {
    mrpt::config::CConfigFileMemory mem;
    opts.saveToConfigFile(mem, section);
    std::vector<std::string> keys;
    mem.getAllKeys(section, keys);
    std::set<std::string> out;
    for (const auto& k : keys) out.insert(mrpt::system::trim(k));
    return out;
}

void rejectUnknownKeys(const mrpt::config::CConfigFileBase& cfg,
                       const std::string& section, const std::set<std::string>& known) {
    std::vector<std::string> keys;
    cfg.getAllKeys(section, keys);
    for (const auto& k : keys) {
        if (known.count(mrpt::system::trim(k))) continue;
        std::string list;
        for (const auto& s : known) list += (list.empty() ? "" : ", ") + s;
        throw std::invalid_argument("unknown key '" + k + "' in section [" + section +
                                    "] (known keys: " + list + ")");
    }
}

void loadStrict(mrpt::config::CLoadableOptions& opts,
                const mrpt::config::CConfigFileBase& cfg, const std::string& section) {
    rejectUnknownKeys(cfg, section, knownKeysOf(opts, section));
    opts.loadFromConfigFile(cfg, section);
}

void badSetting(const std::string& section, const std::string& key,
                const std::string& why) {
    throw std::invalid_argument("[" + section + "] " + key + ": " + why);
}

}  // namespace rfir::slam
