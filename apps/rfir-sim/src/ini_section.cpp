#include "ini_section.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace rfir::sim::detail
{
namespace
{
std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& s, char sep)
{
    std::vector<std::string> out;
    std::string cur;
    std::istringstream is(s);
    while (std::getline(is, cur, sep)) out.push_back(trim(cur));
    if (!s.empty() && s.back() == sep) out.push_back({});
    return out;
}
}  // namespace

bool parseNumber(const std::string& tok, double& v)
{
    if (tok.empty()) return false;
    char* end = nullptr;
    const double x = std::strtod(tok.c_str(), &end);
    if (*end || !std::isfinite(x)) return false;
    v = x;
    return true;
}

CIniSection::CIniSection(const mrpt::config::CConfigFileBase& cfg, std::string section,
                         std::initializer_list<const char*> known)
    : cfg_(cfg), section_(std::move(section))
{
    std::vector<std::string> keys;
    if (cfg_.sectionExists(section_)) cfg_.getAllKeys(section_, keys);
    std::string list;
    for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
    for (const auto& k : keys)
    {
        bool ok = false;
        for (const char* kk : known) ok = ok || k == kk;
        if (!ok) fail(k, "unknown key (known keys: " + list + ")");
        present_.insert(k);
    }
}

bool CIniSection::has(const std::string& key) const { return present_.count(key) > 0; }

void CIniSection::fail(const std::string& key, const std::string& what) const
{
    throw std::runtime_error("[" + section_ + "] " + key + ": " + what);
}

std::string CIniSection::raw(const std::string& key) const
{
    return trim(cfg_.read_string(section_, key, "", false));
}

void CIniSection::num(const std::string& key, double& v) const
{
    if (!has(key)) return;
    const auto s = raw(key);
    if (!parseNumber(s, v)) fail(key, "'" + s + "' is not a finite number");
}

void CIniSection::positive(const std::string& key, double& v) const
{
    num(key, v);
    if (has(key) && !(v > 0)) fail(key, "must be > 0");
}

void CIniSection::nonNegative(const std::string& key, double& v) const
{
    num(key, v);
    if (has(key) && !(v >= 0)) fail(key, "must be >= 0");
}

void CIniSection::integer(const std::string& key, int& v, int lo, int hi) const
{
    if (!has(key)) return;
    const auto s = raw(key);
    double x = 0;
    if (!parseNumber(s, x) || x != std::floor(x))
        fail(key, "'" + s + "' is not an integer");
    if (x < lo || x > hi)
        fail(key, "must be in " + std::to_string(lo) + ".." + std::to_string(hi));
    v = int(x);
}

void CIniSection::boolean(const std::string& key, bool& v) const
{
    if (!has(key)) return;
    const auto s = raw(key);
    if (s == "true" || s == "1" || s == "yes") v = true;
    else if (s == "false" || s == "0" || s == "no") v = false;
    else fail(key, "'" + s + "' is not a boolean (true/false)");
}

void CIniSection::text(const std::string& key, std::string& v) const
{
    if (has(key)) v = raw(key);
}

int CIniSection::choice(const std::string& key,
                        std::initializer_list<const char*> choices) const
{
    if (!has(key)) return -1;
    const auto s = raw(key);
    int i = 0;
    std::string list;
    for (const char* c : choices)
    {
        if (s == c) return i;
        list += std::string(i ? ", " : "") + c;
        i++;
    }
    fail(key, "'" + s + "' is not one of: " + list);
}

bool CIniSection::entries(const std::string& key, std::vector<std::string>& out) const
{
    if (!has(key)) return false;
    out.clear();
    const auto s = raw(key);
    if (s.empty()) return true;
    for (const auto& e : split(s, ','))
    {
        if (e.empty()) fail(key, "empty entry in comma-separated list");
        out.push_back(e);
    }
    return true;
}

bool CIniSection::numberLists(const std::string& key, std::initializer_list<size_t> counts,
                              std::vector<std::vector<double>>& out) const
{
    std::vector<std::string> es;
    if (!entries(key, es)) return false;
    out.clear();
    for (size_t n = 0; n < es.size(); n++)
    {
        std::vector<double> nums;
        std::istringstream is(es[n]);
        std::string tok;
        while (is >> tok)
        {
            double v = 0;
            if (!parseNumber(tok, v))
                fail(key, "entry " + std::to_string(n + 1) + ": '" + tok +
                              "' is not a finite number");
            nums.push_back(v);
        }
        bool ok = false;
        std::string allowed;
        for (size_t c : counts)
        {
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
