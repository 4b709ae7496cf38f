/* rfir tests: every loader of the project run on the stock INIs, with one key
 * set to a given value (for docs/ini-reference.md and the bad-value sweep). */
#pragma once

#include <rfir/models/ini_reader.h>

#include <string>
#include <vector>

namespace rfir_test {
/** One stock INI and the loader that reads it. */
struct TStockIni {
    std::string file;  //!< path
    enum class Kind { Slam, Sim, Localize } kind;
};
std::vector<TStockIni> stockInis();

/** Loads `ini` through its program's loader with [section] key = value set
 * (nothing set when section is empty). Throws what the loader throws. */
void loadWith(const TStockIni& ini, const std::string& section, const std::string& key,
              const std::string& value);

/** The (section, key) pairs present in an INI file. */
std::vector<std::pair<std::string, std::string>> keysOf(const std::string& file);

/** Every key the loaders read on the stock INIs (and the slam defaults). */
std::vector<rfir::ini::TKeySpec> recordAllKeys();

/** docs/ini-reference.md's table as the loaders declare it. */
std::string referenceTable();
}  // namespace rfir_test
