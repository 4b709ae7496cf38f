/* rfir-sim: strict reading of one INI section (MRPT ignores unknown keys; we
 * reject them, and every bad value names its section and key). */
#pragma once

#include <rfir/models/ini_reader.h>

#include <mrpt/config/CConfigFileBase.h>

#include <initializer_list>
#include <set>
#include <string>
#include <vector>

namespace rfir::sim::detail {
class CIniSection {
  public:
    /** Throws rfir::ini::CIniError("[section] key: unknown key ...") if the
     * section holds a key not in `known`. */
    CIniSection(const mrpt::config::CConfigFileBase& cfg, std::string section,
                std::initializer_list<const char*> known);

    bool has(const std::string& key) const { return core_.has(key); }
    /** Each reader leaves `v` untouched when the key is absent; every range
     * has a finite upper bound (docs/ini-reference.md). */
    void num(const std::string& key, double& v, double lo, double hi) const;
    void positive(const std::string& key, double& v, double hi) const;     //!< (0, hi]
    void nonNegative(const std::string& key, double& v, double hi) const;  //!< [0, hi]
    void integer(const std::string& key, int& v, int lo, int hi) const;
    void boolean(const std::string& key, bool& v) const;
    void text(const std::string& key, std::string& v) const;
    /** One of `choices` (case-sensitive); returns its index or -1 if absent. */
    int choice(const std::string& key, std::initializer_list<const char*> choices) const;
    /** Comma-separated entries, each a list of numbers in [-1e6, 1e6] whose
     * count is in `counts`; returns false if the key is absent. */
    bool numberLists(const std::string& key, std::initializer_list<size_t> counts,
                     std::vector<std::vector<double>>& out) const;
    /** Comma-separated entries, trimmed, none empty. */
    bool entries(const std::string& key, std::vector<std::string>& out) const;

    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        core_.fail(key, what);
    }
    const std::string& name() const { return core_.name(); }

  private:
    rfir::ini::CIniSection core_;
};

/** Strict number parse: the whole token, finite. */
bool parseNumber(const std::string& tok, double& v);

}  // namespace rfir::sim::detail
