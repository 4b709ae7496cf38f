/* rfir: the one strict INI section reader. MRPT ignores unknown keys, keeps the
 * leading integer of "5e2" and accepts nan; every section the project reads
 * goes through CIniSection instead, so that a misspelt key or a value out of
 * its documented range is an error naming file, section and key. */
#pragma once

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfir::ini {
/** The one exception type of INI errors: "file: [section] key: why". */
class CIniError : public std::invalid_argument {
  public:
    using std::invalid_argument::invalid_argument;
};

/** One key as a loader declared it (for docs/ini-reference.md and the tests). */
struct TKeySpec {
    std::string program, section, key, type, def, range;
};

/** While on, every getter records its key's spec (tests and the doc generator
 * switch it on; off by default, so arbitrary section names cost nothing). */
void setRecording(bool on, const std::string& program = "");
/** The keys recorded so far, sorted by program, section, key. */
std::vector<TKeySpec> recordedKeys();

/** A closed or half-open interval of doubles; both ends finite. */
struct TRange {
    double lo, hi;
    bool loOpen = false;  //!< (lo, ...: lo itself refused
    bool hiOpen = false;
    static TRange closed(double lo, double hi) { return {lo, hi}; }
    static TRange aboveZero(double hi) { return {0, hi, true}; }  //!< (0, hi]
    bool contains(double v) const;
    std::string str() const;
};

/** An INI file's text held in memory (edits such as --set go to the copy,
 * never back to the file) that keeps the file's name for messages. */
class CIniFile : public mrpt::config::CConfigFileMemory {
  public:
    CIniFile(std::string file, const std::string& text)
        : mrpt::config::CConfigFileMemory(text), file_(std::move(file)) {}
    const std::string& file() const { return file_; }

  private:
    std::string file_;
};

/** The file of a CConfigFile or a CIniFile, empty for other in-memory configs. */
std::string fileNameOf(const mrpt::config::CConfigFileBase& cfg);

/** Throws CIniError("file: [section] key: why"). */
[[noreturn]] void fail(const mrpt::config::CConfigFileBase& cfg,
                       const std::string& section, const std::string& key,
                       const std::string& why);

/** Refuses (CIniError "file: [s]: unknown section (known: ...)") any section
 * of `cfg` not in `known`; the unnamed section before the first header is
 * MRPT's and always passes. */
void checkSections(const mrpt::config::CConfigFileBase& cfg,
                   const std::vector<std::string>& known);

class CIniSection {
  public:
    /** Refuses (CIniError) any key of `section` outside `known`. A missing
     * section passes: every getter then returns its default. */
    CIniSection(const mrpt::config::CConfigFileBase& cfg, std::string section,
                const std::vector<std::string>& known);

    bool has(const std::string& key) const;
    /** The whole token a finite number inside `r`. */
    double getDouble(const std::string& key, double def, const TRange& r) const;
    /** The whole token a decimal integer in [lo, hi] ("5e2", "2.9", "500x" refused). */
    int64_t getInt(const std::string& key, int64_t def, int64_t lo, int64_t hi) const;
    uint64_t getUInt64(const std::string& key, uint64_t def) const;  //!< [0, 2^64)
    /** true/false (also 1/0, yes/no). */
    bool getBool(const std::string& key, bool def) const;
    /** One of `names` (case-sensitive); returns its index. */
    size_t getEnum(const std::string& key, const std::vector<std::string>& names,
                   size_t def) const;
    /** Any text (trimmed); `nonEmpty` refuses an empty value. */
    std::string getString(const std::string& key, const std::string& def,
                          bool nonEmpty = false) const;
    /** Records a key a caller parses itself (lists, areas) for the docs. */
    void declare(const std::string& key, const std::string& type, const std::string& def,
                 const std::string& range) const;

    [[noreturn]] void fail(const std::string& key, const std::string& why) const;
    const std::string& name() const { return section_; }
    /** The raw (trimmed) value; empty when absent. */
    std::string raw(const std::string& key) const;

  private:
    const mrpt::config::CConfigFileBase& cfg_;
    std::string section_;
};

/** Strict whole-token parses (no trailing text, finite). */
bool parseDouble(const std::string& tok, double& v);

}  // namespace rfir::ini
