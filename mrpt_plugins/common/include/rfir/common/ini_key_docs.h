/* rfir: what every INI key of the programs means, in one table: the source of
 * docs/ini-reference.md's meaning and unit columns, of the comments in the
 * settings.ini the programs write and of their --help-keys. The loaders
 * declare type, default and range (rfir::ini::CIniSection records them);
 * this table joins them by program, section and key, so that a loader's
 * code says nothing twice. test_ini_reference fails on a key the loaders
 * read that has no entry here, and on an entry no loader reads. */
#pragma once

#include <rfir/models/ini_reader.h>

#include <functional>
#include <string>
#include <vector>

namespace rfir::common {
/** One key's meaning: what it does physically and when a user changes it. */
struct TKeyDoc {
    std::string program;  //!< rfir-slam, rfir-sim or rfir-localize
    /** The section, or a glob of MRPT's numbered map sections
     * (MetricMap_irEmitterMap_*_likelihoodOpts). */
    std::string section;
    std::string key;
    std::string unit;  //!< "m", "rad/m", ...; "-" for names, switches, counts of a kind
    std::string meaning;
};

/** Every entry, by program. */
const std::vector<TKeyDoc>& iniKeyDocs();

/** The entry of [section] key as `program` reads it; nullptr when none. */
const TKeyDoc* findKeyDoc(const std::string& program, const std::string& section,
                          const std::string& key);

/** The INI text with, before each key line that has an entry, a comment
 * "# meaning [unit]"; every other line unchanged. */
std::string annotateIni(const std::string& iniText, const std::string& program);

/** --help-keys: runs `load` with the INI reader's recording on; `load`
 * returns the effective settings as INI text. Lists every key `program`
 * read: section, key, value, unit, type, default, range and meaning. */
std::string describeKeys(const std::string& program,
                         const std::function<std::string()>& load);

/** The text of the --help-keys option of the programs. */
extern const char* const kHelpKeysHelp;
}  // namespace rfir::common
