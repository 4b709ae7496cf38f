/* rfir: the rows of the INI key table, one function per program
 * (ini_key_docs_*.cpp). */
#pragma once

#include <vector>

namespace rfir::common::detail {
struct TKeyRow {
    const char *section, *key, *unit, *meaning;
};
const std::vector<TKeyRow>& localizeKeyRows();
const std::vector<TKeyRow>& simKeyRows();
const std::vector<TKeyRow>& slamKeyRows();
}  // namespace rfir::common::detail
