/* rfir: strict INI key and value checking for the project's own sections. */
#include <rfir/models/ini_check.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rfir {
namespace {
std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}
std::string where(const std::string& section, const std::string& key) {
    return "[" + section + "] " + key;
}
}  // namespace

void checkIniKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                  const std::vector<std::string>& allowedKeys) {
    std::vector<std::string> keys;
    cfg.getAllKeys(section, keys);
    for (const auto& k : keys)
        if (std::find(allowedKeys.begin(), allowedKeys.end(), k) == allowedKeys.end())
            throw std::runtime_error("[" + section + "] unknown key '" + k +
                                     "' (allowed: " + joined(allowedKeys) + ")");
}

size_t readIniEnum(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                   const std::string& key, const std::vector<std::string>& names,
                   size_t defaultIndex) {
    const std::string v = cfg.read_string(section, key, names.at(defaultIndex));
    const auto it = std::find(names.begin(), names.end(), v);
    if (it == names.end())
        throw std::runtime_error(where(section, key) + ": unknown value '" + v +
                                 "' (one of: " + joined(names) + ")");
    return static_cast<size_t>(it - names.begin());
}

size_t readIniPositiveInt(const mrpt::config::CConfigFileBase& cfg,
                          const std::string& section, const std::string& key,
                          size_t defaultValue, size_t maxValue) {
    const std::string v = cfg.read_string(section, key, std::to_string(defaultValue));
    size_t pos = 0;
    long long x = 0;
    try {
        x = std::stoll(v, &pos);
    } catch (const std::exception&) {
        pos = 0;
    }
    if (pos == 0 || pos != v.size() || x <= 0)
        throw std::runtime_error(where(section, key) +
                                 ": expected a positive integer, got '" + v + "'");
    if (static_cast<unsigned long long>(x) > maxValue)
        throw std::runtime_error(where(section, key) + ": at most " +
                                 std::to_string(maxValue) + ", got '" + v + "'");
    return static_cast<size_t>(x);
}

double readIniDouble(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                     const std::string& key, double defaultValue, double minValue,
                     bool strict) {
    const std::string v = cfg.read_string(section, key, "");
    if (v.empty()) return defaultValue;
    size_t pos = 0;
    double x = 0;
    try {
        x = std::stod(v, &pos);
    } catch (const std::exception&) {
        pos = 0;
    }
    if (pos == 0 || pos != v.size() || !std::isfinite(x))
        throw std::runtime_error(where(section, key) + ": expected a number, got '" + v +
                                 "'");
    if (strict ? !(x > minValue) : !(x >= minValue))
        throw std::runtime_error(where(section, key) + ": must be " +
                                 (strict ? "> " : ">= ") + std::to_string(minValue) +
                                 ", got " + v);
    return x;
}

}  // namespace rfir
