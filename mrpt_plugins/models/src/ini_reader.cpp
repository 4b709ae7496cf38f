/* rfir: the one strict INI section reader. */
#include <rfir/models/ini_reader.h>
#include <rfir/models/printable.h>

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <mutex>
#include <sstream>
#include <tuple>

namespace rfir::ini {
namespace {
std::atomic<bool> gRecording{false};
std::mutex gMutex;
std::string gProgram;
std::map<std::tuple<std::string, std::string, std::string>, TKeySpec>& registry() {
    static std::map<std::tuple<std::string, std::string, std::string>, TKeySpec> r;
    return r;
}

void record(const std::string& s, const std::string& k, const std::string& type,
            const std::string& def, const std::string& range) {
    if (!gRecording) return;
    std::lock_guard<std::mutex> lock(gMutex);
    registry()[{gProgram, s, k}] = {gProgram, s, k, type, def, range};
}

std::string num(double v) {
    std::ostringstream o;
    o.precision(10);
    o << v;
    return o.str();
}

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return {};
    const auto b = s.find_last_not_of(" \t\r\n");
    return s.substr(a, b - a + 1);
}

std::string joined(const std::vector<std::string>& v, const char* sep) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
    return s;
}
}  // namespace

void setRecording(bool on, const std::string& program) {
    std::lock_guard<std::mutex> lock(gMutex);
    gProgram = program;
    gRecording = on;
}

std::vector<TKeySpec> recordedKeys() {
    std::lock_guard<std::mutex> lock(gMutex);
    std::vector<TKeySpec> out;
    for (const auto& kv : registry()) out.push_back(kv.second);
    return out;
}

bool TRange::contains(double v) const {
    return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
}

std::string TRange::str() const {
    return std::string(loOpen ? "(" : "[") + num(lo) + ", " + num(hi) +
           (hiOpen ? ")" : "]");
}

bool parseDouble(const std::string& tok, double& v) {
    if (tok.empty() || std::isspace(static_cast<unsigned char>(tok[0]))) return false;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(tok.c_str(), &end);
    if (*end || !std::isfinite(x) || errno == ERANGE) return false;
    v = x;
    return true;
}

namespace {
bool parseInt(const std::string& tok, int64_t& v) {
    const size_t start = (!tok.empty() && (tok[0] == '-' || tok[0] == '+')) ? 1 : 0;
    if (tok.size() == start || tok.size() > 19 + start) return false;
    if (tok.find_first_not_of("0123456789", start) != std::string::npos) return false;
    errno = 0;
    const long long x = std::strtoll(tok.c_str(), nullptr, 10);
    if (errno == ERANGE) return false;
    v = x;
    return true;
}
}  // namespace

std::string fileNameOf(const mrpt::config::CConfigFileBase& cfg) {
    if (const auto* f = dynamic_cast<const mrpt::config::CConfigFile*>(&cfg))
        return f->getAssociatedFile();
    if (const auto* f = dynamic_cast<const CIniFile*>(&cfg)) return f->file();
    return {};
}

namespace {
std::string fileOf(const mrpt::config::CConfigFileBase& cfg) {
    const std::string f = fileNameOf(cfg);
    return f.empty() ? f : f + ": ";
}
}  // namespace

void checkSections(const mrpt::config::CConfigFileBase& cfg,
                   const std::vector<std::string>& known) {
    std::vector<std::string> sections;
    cfg.getAllSections(sections);
    for (const auto& s : sections)
        if (!s.empty() && std::find(known.begin(), known.end(), s) == known.end())
            throw CIniError(fileOf(cfg) + "[" + s +
                            "]: unknown section (known: " + joined(known, ", ") + ")");
}

namespace {
std::string where(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                  const std::string& key) {
    return fileOf(cfg) + "[" + section + "] " + key;
}
}  // namespace

void fail(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
          const std::string& key, const std::string& why) {
    // An INI value may be anything a corrupt file holds: quoted escaped.
    throw CIniError(rfir::printable(where(cfg, section, key) + ": " + why));
}

CIniSection::CIniSection(const mrpt::config::CConfigFileBase& cfg, std::string section,
                         const std::vector<std::string>& known)
    : cfg_(cfg), section_(std::move(section)) {
    std::vector<std::string> keys;
    if (cfg_.sectionExists(section_)) cfg_.getAllKeys(section_, keys);
    for (const auto& k : keys)
        if (std::find(known.begin(), known.end(), trim(k)) == known.end())
            fail(trim(k), "unknown key (known keys: " + joined(known, ", ") + ")");
}

bool CIniSection::has(const std::string& key) const {
    return cfg_.sectionExists(section_) && cfg_.keyExists(section_, key);
}

std::string CIniSection::raw(const std::string& key) const {
    return has(key) ? trim(cfg_.read_string(section_, key, "")) : std::string();
}

void CIniSection::fail(const std::string& key, const std::string& why) const {
    rfir::ini::fail(cfg_, section_, key, why);
}

void CIniSection::declare(const std::string& key, const std::string& type,
                          const std::string& def, const std::string& range) const {
    record(section_, key, type, def, range);
}

double CIniSection::getDouble(const std::string& key, double def, const TRange& r) const {
    // Formatting the range costs more than the read: only when recording.
    if (gRecording) record(section_, key, "real", num(def), r.str());
    if (!has(key)) return def;
    const std::string t = raw(key);
    double v = 0;
    if (!parseDouble(t, v)) fail(key, "expected a finite number, got '" + t + "'");
    if (!r.contains(v)) fail(key, "must be in " + r.str() + ", got " + t);
    return v;
}

int64_t CIniSection::getInt(const std::string& key, int64_t def, int64_t lo,
                            int64_t hi) const {
    const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    record(section_, key, "integer", std::to_string(def), range);
    if (!has(key)) return def;
    const std::string t = raw(key);
    int64_t v = 0;
    if (!parseInt(t, v)) fail(key, "expected an integer, got '" + t + "'");
    if (v < lo || v > hi) fail(key, "must be in " + range + ", got " + t);
    return v;
}

uint64_t CIniSection::getUInt64(const std::string& key, uint64_t def) const {
    record(section_, key, "integer", std::to_string(def), "[0, 18446744073709551615]");
    if (!has(key)) return def;
    const std::string t = raw(key);
    if (t.empty() || t.size() > 20 || t.find_first_not_of("0123456789") != t.npos)
        fail(key, "expected a non-negative integer, got '" + t + "'");
    errno = 0;
    const unsigned long long v = std::strtoull(t.c_str(), nullptr, 10);
    if (errno == ERANGE) fail(key, "must be below 2^64, got " + t);
    return v;
}

bool CIniSection::getBool(const std::string& key, bool def) const {
    record(section_, key, "bool", def ? "true" : "false", "true, false (1, 0, yes, no)");
    if (!has(key)) return def;
    const std::string t = raw(key);
    if (t == "true" || t == "1" || t == "yes") return true;
    if (t == "false" || t == "0" || t == "no") return false;
    fail(key, "expected true or false, got '" + t + "'");
}

size_t CIniSection::getEnum(const std::string& key, const std::vector<std::string>& names,
                            size_t def) const {
    record(section_, key, "enum", names.at(def), joined(names, ", "));
    if (!has(key)) return def;
    const std::string t = raw(key);
    const auto it = std::find(names.begin(), names.end(), t);
    if (it == names.end())
        fail(key, "unknown value '" + t + "' (one of: " + joined(names, ", ") + ")");
    return static_cast<size_t>(it - names.begin());
}

std::string CIniSection::getString(const std::string& key, const std::string& def,
                                   bool nonEmpty) const {
    record(section_, key, "text", def.empty() ? "(none)" : def,
           nonEmpty ? "non-empty" : "any");
    if (!has(key)) return def;
    const std::string t = raw(key);
    if (nonEmpty && t.empty()) fail(key, "must not be empty");
    return t;
}

}  // namespace rfir::ini
