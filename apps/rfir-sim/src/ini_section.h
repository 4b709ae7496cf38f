/* rfir-sim: strict reading of one INI section (MRPT ignores unknown keys; we
 * reject them, and every bad value names its section and key). */
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <initializer_list>
#include <set>
#include <string>
#include <vector>

namespace rfir::sim::detail
{
class CIniSection
{
public:
    /** Throws std::runtime_error("[section] key: unknown key ...") if the
     * section holds a key not in `known`. */
    CIniSection(const mrpt::config::CConfigFileBase& cfg, std::string section,
                std::initializer_list<const char*> known);

    bool has(const std::string& key) const;
    /** Each reader leaves `v` untouched when the key is absent. */
    void num(const std::string& key, double& v) const;
    void positive(const std::string& key, double& v) const;     //!< > 0
    void nonNegative(const std::string& key, double& v) const;  //!< >= 0
    void integer(const std::string& key, int& v, int lo, int hi) const;
    void boolean(const std::string& key, bool& v) const;
    void text(const std::string& key, std::string& v) const;
    /** One of `choices` (case-sensitive); returns its index or -1 if absent. */
    int choice(const std::string& key, std::initializer_list<const char*> choices) const;
    /** Comma-separated entries, each a list of numbers whose count is in
     * `counts`; returns false if the key is absent. */
    bool numberLists(const std::string& key, std::initializer_list<size_t> counts,
                     std::vector<std::vector<double>>& out) const;
    /** Comma-separated entries, trimmed, none empty. */
    bool entries(const std::string& key, std::vector<std::string>& out) const;

    [[noreturn]] void fail(const std::string& key, const std::string& what) const;
    const std::string& name() const { return section_; }

private:
    std::string raw(const std::string& key) const;
    const mrpt::config::CConfigFileBase& cfg_;
    std::string section_;
    std::set<std::string> present_;
};

/** Strict number parse: the whole token, finite. */
bool parseNumber(const std::string& tok, double& v);

}  // namespace rfir::sim::detail
