/* rfir: JSON text for the writers that still lay out their documents by hand
 * (written by nlohmann-json, so that user input is escaped by a library). */
#pragma once

#include <string>

namespace rfir::common {
/** `s` as a JSON string, quotes included; bytes that are not UTF-8 become
 * U+FFFD (paths and arguments are bytes, a JSON text is UTF-8). */
std::string jsonString(const std::string& s);
}  // namespace rfir::common
