/* rfir: robot paths in the TUM trajectory format (textlog.md outputs):
 * `t x y z qx qy qz qw`, z = 0, rotation about z only. */
#pragma once

#include <mrpt/poses/CPose2D.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace rfir::common {
struct TStampedPose2D {
    double t = 0;
    mrpt::poses::CPose2D pose;
};
using TPath2D = std::vector<TStampedPose2D>;

/** Wraps an angle to (-pi, pi] (the text format's range; MRPT's
 * mrpt::math::wrapToPi gives [-pi, pi)). */
double wrapToPi(double a);

/** The pose a fraction s (0: a, 1: b) of the way from a to b: x and y
 * linear, the heading along the shorter arc (stored by CPose2D in [-pi, pi)). */
mrpt::poses::CPose2D interpolatePose2D(const mrpt::poses::CPose2D& a,
                                       const mrpt::poses::CPose2D& b, double s);

/** Writes atomically. */
void saveTUM(const std::string& path, const TPath2D& traj);
/** Reads a TUM file; `#` comments and blank lines skipped. Throws
 * std::runtime_error("FILE:LINE: what is wrong") on a malformed line. */
TPath2D loadTUM(const std::string& path);
/** Same from a stream; `name` is used in messages. */
TPath2D loadTUM(std::istream& in, const std::string& name);

}  // namespace rfir::common
