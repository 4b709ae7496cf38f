/* rfir: strict INI reading. MRPT silently ignores unknown keys; the project's
 * own sections reject them so that a misspelt key is not a silent default. */
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <limits>
#include <string>
#include <vector>

namespace rfir {
/** Throws std::runtime_error("[section] unknown key 'k' (allowed: ...)") if the
 * section has a key not in allowedKeys (case-sensitive). A missing section
 * passes. */
void checkIniKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                  const std::vector<std::string>& allowedKeys);

/** Reads `key` as one of `names` (returns its index); the default is returned
 * when the key is absent. Throws naming section, key, value and the choices. */
size_t readIniEnum(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                   const std::string& key, const std::vector<std::string>& names,
                   size_t defaultIndex);

/** Reads an integer in [1, maxValue]; throws naming section and key otherwise. */
size_t readIniPositiveInt(const mrpt::config::CConfigFileBase& cfg,
                          const std::string& section, const std::string& key,
                          size_t defaultValue,
                          size_t maxValue = std::numeric_limits<size_t>::max());

/** Reads a finite double >= minValue (or > minValue when strict). */
double readIniDouble(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                     const std::string& key, double defaultValue, double minValue,
                     bool strict);

}  // namespace rfir
