/* rfir: the bytes of a corrupt file quoted in an error message, escaped. */
#pragma once

#include <cstdio>
#include <string>

namespace rfir {
/** `s` with every byte outside printable ASCII written as \xNN, so that an
 * error quoting a corrupt file stays text on any terminal and log. */
inline std::string printable(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (const unsigned char c : s) {
        if (c >= 0x20 && c < 0x7F) {
            out += char(c);
            continue;
        }
        char hex[5];
        std::snprintf(hex, sizeof(hex), "\\x%02X", c);
        out += hex;
    }
    return out;
}
}  // namespace rfir
