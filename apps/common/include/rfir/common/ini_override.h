/* rfir: "section.key=value" edits written over an INI before it is read (the
 * apps' --set options, the experiment rows' INI edits). */
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace rfir::common {
/** Writes one "section.key=value" edit into `ini` (the section is what comes
 * before the last '.' ahead of the '='). Throws std::runtime_error
 * "INI edit (--set) '<edit>': expected section.key=value" when malformed. */
void applyIniOverride(mrpt::config::CConfigFileBase& ini, const std::string& edit);

/** applyIniOverride for each edit, in order. */
void applyIniOverrides(mrpt::config::CConfigFileBase& ini,
                       const std::vector<std::string>& edits);
}  // namespace rfir::common
