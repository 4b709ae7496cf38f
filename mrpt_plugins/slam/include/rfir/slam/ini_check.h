/* rfir: strict INI sections. MRPT ignores unknown keys; our own sections must
 * reject misspelt ones, naming the key and the section. */
#pragma once

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>

#include <set>
#include <string>

namespace rfir::slam {
/** The keys an options struct writes with saveToConfigFile: by construction
 * the keys its loadFromConfigFile understands. */
std::set<std::string> knownKeysOf(const mrpt::config::CLoadableOptions& opts,
                                  const std::string& section);

/** Throws std::invalid_argument("unknown key 'k' in section [s] ...") if
 * `section` of `cfg` holds a key outside `known`. */
void rejectUnknownKeys(const mrpt::config::CConfigFileBase& cfg,
                       const std::string& section, const std::set<std::string>& known);

/** Loads `opts` from `section` after rejecting keys it would not read. */
void loadStrict(mrpt::config::CLoadableOptions& opts,
                const mrpt::config::CConfigFileBase& cfg, const std::string& section);

/** std::invalid_argument naming the INI key: "[section] key: why". */
[[noreturn]] void badSetting(const std::string& section, const std::string& key,
                             const std::string& why);

}  // namespace rfir::slam
