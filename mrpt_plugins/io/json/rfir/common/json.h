/* rfir: the JSON documents the libraries write (nlohmann-json). Not installed
 * and in no public header: nlohmann-json is needed to build rfir, not to use it. */
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace rfir::common {
/** Keys stay in insertion order: the order the outputs document. */
using TJson = nlohmann::ordered_json;

/** `v` as the value `printf(format, v)` writes (the outputs' documented
 * precision, "%.9g" unless said otherwise); NaN and infinities are null. */
inline TJson printed(double v, const char* format = "%.9g") {
    if (!std::isfinite(v)) return nullptr;
    char b[64];
    std::snprintf(b, sizeof b, format, v);
    const double x = std::strtod(b, nullptr);
    // A whole number is written as printf writes it: 2, not 2.0.
    if (x == std::trunc(x) && std::fabs(x) < 1e15) return static_cast<int64_t>(x);
    return x;
}

inline TJson printed(const std::vector<double>& v, const char* format = "%.9g") {
    TJson a = TJson::array();
    for (const double x : v) a.push_back(printed(x, format));
    return a;
}

/** One line. Paths, labels and arguments are bytes: bytes that are not UTF-8
 * become U+FFFD instead of a throw. */
inline std::string dumpJson(const TJson& j) {
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}
}  // namespace rfir::common
