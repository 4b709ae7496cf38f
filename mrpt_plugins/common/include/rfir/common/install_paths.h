/* rfir: where an installed (or built) program finds the project's files. */
#pragma once

#include <string>

namespace rfir::common {
/** <folder of the running program>/../share/rfir/config_ini, normalised: the
 * stock INIs, installed beside the programs and copied there by the build.
 * Throws std::runtime_error if the program's path cannot be read. */
std::string stockConfigDir();
}  // namespace rfir::common
