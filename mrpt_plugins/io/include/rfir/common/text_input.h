/* rfir: bounded reading of every text input (logs, maps, trajectories, INIs).
 * A binary file or a device given by mistake must give an error naming the
 * file and line, not be read whole into one string. */
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <istream>
#include <string>

namespace rfir::common {
/** Longest line of a text input, in bytes (the newline excluded). */
constexpr size_t kMaxTextLineBytes = size_t(1) << 20;
/** Largest INI file read into memory. */
constexpr uint64_t kMaxIniFileBytes = uint64_t(16) << 20;

/** Opens `path` for reading. Throws std::runtime_error "PATH: is a directory,
 * not a WHAT" or "PATH: cannot open WHAT". */
void openTextInput(std::ifstream& f, const std::string& path, const std::string& what);

/** std::getline with a bound: false at the end of the input (as getline).
 * Throws std::runtime_error "NAME:LINE_NO: line longer than ..." as soon as a
 * line exceeds `maxBytes`, before storing more. */
bool getBoundedLine(std::istream& in, std::string& line, const std::string& name,
                    size_t lineNo, size_t maxBytes = kMaxTextLineBytes);

/** The whole text of a small file (an INI): a regular file of at most
 * `maxBytes` bytes whose lines are each bounded as above; throws naming the
 * file (and the line) otherwise. */
std::string readSmallTextFile(const std::string& path, const std::string& what,
                              uint64_t maxBytes = kMaxIniFileBytes);
}  // namespace rfir::common
