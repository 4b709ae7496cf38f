/* rfir: outputs are written whole or not at all. */
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace rfir::common {
/** Writes `path` through `fill` into "<path>.tmp.<pid>", then renames it over
 * `path`. If `fill` throws or the stream fails, the temporary file is removed,
 * `path` is left untouched and std::runtime_error names the file. */
void writeFileAtomically(const std::string& path,
                         const std::function<void(std::ostream&)>& fill);

/** Same for binary writers that need a file name (e.g. a gz rawlog or a PNG):
 * `write(tmpPath)` writes the temporary file, which is then renamed. */
void writeViaTempFile(const std::string& path,
                      const std::function<void(const std::string& tmpPath)>& write);

}  // namespace rfir::common
