#include "ini_section.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace rfir::sim::detail {
namespace {
std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::string cur;
    std::istringstream is(s);
    while (std::getline(is, cur, sep)) out.push_back(trim(cur));
    if (!s.empty() && s.back() == sep) out.push_back({});
    return out;
}
}  // namespace

bool parseNumber(const std::string& tok, double& v) {
    return rfir::ini::parseDouble(tok, v);
}

namespace {
std::vector<std::string> names(std::initializer_list<const char*> l) {
    return std::vector<std::string>(l.begin(), l.end());
}
}  // namespace

CIniSection::CIniSection(const mrpt::config::CConfigFileBase& cfg, std::string section,
                         std::initializer_list<const char*> known)
    : core_(cfg, std::move(section), names(known)) {}

void CIniSection::num(const std::string& key, double& v, double lo, double hi) const {
    v = core_.getDouble(key, v, rfir::ini::TRange::closed(lo, hi));
}

void CIniSection::positive(const std::string& key, double& v, double hi) const {
    v = core_.getDouble(key, v, rfir::ini::TRange::aboveZero(hi));
}

void CIniSection::nonNegative(const std::string& key, double& v, double hi) const {
    v = core_.getDouble(key, v, rfir::ini::TRange::closed(0, hi));
}

void CIniSection::integer(const std::string& key, int& v, int lo, int hi) const {
    v = int(core_.getInt(key, v, lo, hi));
}

void CIniSection::boolean(const std::string& key, bool& v) const {
    v = core_.getBool(key, v);
}

void CIniSection::text(const std::string& key, std::string& v) const {
    v = core_.getString(key, v);
}

int CIniSection::choice(const std::string& key,
                        std::initializer_list<const char*> choices) const {
    const size_t i = core_.getEnum(key, names(choices), 0);
    return has(key) ? int(i) : -1;
}

bool CIniSection::entries(const std::string& key, std::vector<std::string>& out) const {
    core_.declare(key, "list", "(none)", "comma-separated entries");
    if (!has(key)) return false;
    out.clear();
    const auto s = core_.raw(key);
    if (s.empty()) return true;
    for (const auto& e : split(s, ',')) {
        if (e.empty()) fail(key, "empty entry in comma-separated list");
        out.push_back(e);
    }
    return true;
}

bool CIniSection::numberLists(const std::string& key,
                              std::initializer_list<size_t> counts,
                              std::vector<std::vector<double>>& out) const {
    std::vector<std::string> es;
    const bool present = entries(key, es);
    std::string allowedCounts;
    for (size_t c : counts)
        allowedCounts += (allowedCounts.empty() ? "" : " or ") + std::to_string(c);
    core_.declare(
        key, "number lists", "(none)",
        "comma-separated entries of " + allowedCounts + " numbers, each in [-1e6, 1e6]");
    if (!present) return false;
    out.clear();
    for (size_t n = 0; n < es.size(); n++) {
        std::vector<double> nums;
        std::istringstream is(es[n]);
        std::string tok;
        while (is >> tok) {
            double v = 0;
            if (!parseNumber(tok, v) || std::abs(v) > 1e6)
                fail(key, "entry " + std::to_string(n + 1) + ": '" + tok +
                              "' is not a finite number in [-1e6, 1e6]");
            nums.push_back(v);
        }
        bool ok = false;
        std::string allowed;
        for (size_t c : counts) {
            ok = ok || nums.size() == c;
            allowed += std::string(allowed.empty() ? "" : " or ") + std::to_string(c);
        }
        if (!ok)
            fail(key, "entry " + std::to_string(n + 1) + " '" + es[n] + "' must have " +
                          allowed + " numbers");
        out.push_back(nums);
    }
    return true;
}

}  // namespace rfir::sim::detail
