/* rfir: where an installed (or built) program finds the project's files. */
#pragma once

#include <string>

namespace rfir::common {
/** <folder of the running program>/../share/rfir/config_ini, normalised: the
 * stock INIs, installed beside the programs and copied there by the build.
 * Throws std::runtime_error if the program's path cannot be read. */
std::string stockConfigDir();
/** Replaces stockConfigDir() for this process (non-empty `dir`): the Python
 * module, whose program is the interpreter, points it at its prefix's. */
void setStockConfigDir(const std::string& dir);
/** The stock INI of a SLAM method in `dir`: "<dir>/slam_<m>.ini" with m
 * "fastslam", "ps", or "pf" for any other method (the ones without an INI of
 * their own run on PF-SLAM's). */
std::string slamIniPath(const std::string& dir, const std::string& method);
/** The same in stockConfigDir(). */
std::string slamIniPath(const std::string& method);
/** A rawlog's path without ".rawlog" or ".rawlog.gz": the stem its dataset's
 * other files share ("<stem>.gt.tum", ...). Other paths come back unchanged. */
std::string rawlogStem(const std::string& path);
}  // namespace rfir::common
