/* rfir: IR emitter ID scheme (thesis 5.2; textlog.md code table). */
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rfir::ir {
/** Number of on-off-keying frequencies of the thesis' emitters. */
constexpr int kNumCodes = 9;
/** Frequency in Hz of code c (1..9): 100, 150, 250, 350, 550, 650, 850, 950, 1150. */
double codeFrequencyHz(int code);
/** Emitter ID of an ascending code set: {3, 9} -> "39". Throws on a bad set. */
std::string emitterIdFromCodes(const std::vector<uint8_t>& codes);
/** Codes of an emitter ID: "39" -> {3, 9}; nullopt if not a valid ID
 * (digits 1..9, strictly ascending, non-empty). */
std::optional<std::vector<uint8_t>> codesFromEmitterId(const std::string& id);
/** A repeated-ID emitter sends one code only. */
inline bool isRepeatedId(const std::vector<uint8_t>& codes) {
    return codes.size() == 1;
}
/** Parses "3,9" (textlog `codes` field); nullopt if malformed or not ascending. */
std::optional<std::vector<uint8_t>> parseCodeList(const std::string& s);
/** "3,9" */
std::string formatCodeList(const std::vector<uint8_t>& codes);
/** Number of IDs from n frequencies using combinations of 1..k of them
 * (sum of C(n, i), i = 1..k): 9, 9 -> 511. */
uint64_t countIds(int nFrequencies, int maxCodesPerId);

}  // namespace rfir::ir
