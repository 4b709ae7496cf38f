/* rfir: strict reading of the IR localization's INI sections. MRPT ignores
 * unknown keys; ours reject them, naming the key and the section. */
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace rfir::ir::ini {
/** Throws std::runtime_error("INI section [S]: unknown key 'k' (allowed: ...)");
 * the readers below throw "INI section [S], key 'k': what is wrong". */
void checkKeys(const mrpt::config::CConfigFileBase& c, const std::string& section,
               const std::vector<std::string>& allowed);

/** A finite double in [lo, hi]; the default when the key is absent. */
double readDouble(const mrpt::config::CConfigFileBase& c, const std::string& section,
                  const std::string& key, double def, double lo = -1e300,
                  double hi = 1e300);

/** A non-negative integer in [lo, hi]. */
size_t readSize(const mrpt::config::CConfigFileBase& c, const std::string& section,
                const std::string& key, size_t def, size_t lo = 0,
                size_t hi = size_t(1) << 40);

/** One of `names`; returns its index. */
size_t readEnum(const mrpt::config::CConfigFileBase& c, const std::string& section,
                const std::string& key, const std::vector<std::string>& names,
                size_t def);

bool readBool(const mrpt::config::CConfigFileBase& c, const std::string& section,
              const std::string& key, bool def);

std::string readString(const mrpt::config::CConfigFileBase& c, const std::string& section,
                       const std::string& key, const std::string& def);

}  // namespace rfir::ir::ini
