/* rfir: every INI file the programs read comes in through readIniFile, so a
 * file that is missing, a directory or too large is a CIniError naming it,
 * like a bad key (rfir/models/ini_reader.h). */
#pragma once

#include <rfir/models/ini_reader.h>

#include <string>

namespace rfir::common {
/** The INI file `path` in memory (bounded as readSmallTextFile); messages of
 * CIniSection over it name `path`. Throws rfir::ini::CIniError. */
rfir::ini::CIniFile readIniFile(const std::string& path);
}  // namespace rfir::common
