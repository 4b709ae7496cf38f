/* rfir: strict INI reading for the IR localization. */
#include <rfir/ir/ini_util.h>

#include <cmath>
#include <stdexcept>

namespace rfir::ir::ini {
namespace {
std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return {};
    const auto b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

std::string fail(const std::string& section, const std::string& key,
                 const std::string& what) {
    return "INI section [" + section + "], key '" + key + "': " + what;
}

bool has(const mrpt::config::CConfigFileBase& c, const std::string& s,
         const std::string& k) {
    return c.keyExists(s, k);
}
}  // namespace

void checkKeys(const mrpt::config::CConfigFileBase& c, const std::string& section,
               const std::vector<std::string>& allowed) {
    std::vector<std::string> keys;
    c.getAllKeys(section, keys);
    for (const auto& k : keys) {
        bool ok = false;
        for (const auto& a : allowed) ok = ok || a == k;
        if (ok) continue;
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        throw std::runtime_error("INI section [" + section + "]: unknown key '" + k +
                                 "' (allowed: " + list + ")");
    }
}

double readDouble(const mrpt::config::CConfigFileBase& c, const std::string& s,
                  const std::string& k, double def, double lo, double hi) {
    if (!has(c, s, k)) return def;
    const std::string txt = trim(c.read_string(s, k, ""));
    char* end = nullptr;
    const double v = std::strtod(txt.c_str(), &end);
    if (txt.empty() || *end || !std::isfinite(v))
        throw std::runtime_error(fail(s, k, "'" + txt + "' is not a finite number"));
    if (v < lo || v > hi)
        throw std::runtime_error(fail(s, k,
                                      "must be in [" + std::to_string(lo) + ", " +
                                          std::to_string(hi) + "], got " + txt));
    return v;
}

size_t readSize(const mrpt::config::CConfigFileBase& c, const std::string& s,
                const std::string& k, size_t def, size_t lo, size_t hi) {
    if (!has(c, s, k)) return def;
    const std::string txt = trim(c.read_string(s, k, ""));
    if (txt.empty() || txt.find_first_not_of("0123456789") != std::string::npos)
        throw std::runtime_error(
            fail(s, k, "'" + txt + "' is not a non-negative integer"));
    const size_t v = std::stoull(txt);
    if (v < lo || v > hi)
        throw std::runtime_error(fail(s, k,
                                      "must be in [" + std::to_string(lo) + ", " +
                                          std::to_string(hi) + "], got " + txt));
    return v;
}

size_t readEnum(const mrpt::config::CConfigFileBase& c, const std::string& s,
                const std::string& k, const std::vector<std::string>& names, size_t def) {
    if (!has(c, s, k)) return def;
    const std::string txt = trim(c.read_string(s, k, ""));
    std::string list;
    for (size_t i = 0; i < names.size(); i++) {
        if (names[i] == txt) return i;
        list += (i ? ", " : "") + names[i];
    }
    throw std::runtime_error(fail(s, k, "'" + txt + "' is not one of: " + list));
}

bool readBool(const mrpt::config::CConfigFileBase& c, const std::string& s,
              const std::string& k, bool def) {
    return readEnum(c, s, k, {"false", "true"}, def ? 1 : 0) == 1;
}

std::string readString(const mrpt::config::CConfigFileBase& c, const std::string& s,
                       const std::string& k, const std::string& def) {
    if (!has(c, s, k)) return def;
    return trim(c.read_string(s, k, def));
}

}  // namespace rfir::ir::ini
