/* rfir: the HF RFID read model, written once (SPEC section 2; 003 eq. 5-6;
 * thesis eq. 3.7). h(robot pose, reader offset, tag) = e, the tag minus the
 * reader centre, in the robot frame:
 *     e = R(phi)^T (tag - t) - offset,
 * with its Jacobians wrt the pose (x, y, phi) and the tag. The noise objects
 * that turn e into a log-likelihood are apart from it (read_noise.h). Inline
 * and allocation-free: it runs once per particle and read. The robot filters,
 * the FastSLAM EKF, the smoothers' factors, the kidnap check, the evaluation
 * and the simulator all call it. */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <cmath>

namespace rfir::models {
/** de/d(x, y, phi) and de/d(tag x, tag y), row-major (row 0: e_x, row 1: e_y). */
struct TReadJacobians {
    double pose[2][3];
    double tag[2][2];
};

/** A world point (px, py) in the frame of the pose at (x, y) with heading
 * cos c and sin s: R(phi)^T (p - t). A template over the scalar, so that the
 * smoother's automatic differentiation (ceres::Jet) evaluates these same
 * lines; `using std::cos` style calls keep it free of any Ceres header. */
template <class T>
void worldToRobotFrame(const T& x, const T& y, const T& c, const T& s, const T& px,
                       const T& py, T& lx, T& ly) {
    const T dx = px - x, dy = py - y;
    lx = c * dx + s * dy;
    ly = -s * dx + c * dy;
}

/** The read model over any scalar: pose = (x, y, phi), tag = (x, y), e = the
 * tag minus the reader centre (offX, offY), robot frame. */
template <class T>
void readModel(const T* pose, const T* tag, double offX, double offY, T& ex, T& ey) {
    using std::cos;
    using std::sin;
    const T c = cos(pose[2]), s = sin(pose[2]);
    T lx, ly;
    worldToRobotFrame(pose[0], pose[1], c, s, tag[0], tag[1], lx, ly);
    ex = lx - offX;
    ey = ly - offY;
}

/** e = R(phi)^T (tag - t) - (offX, offY), given c = cos(phi), s = sin(phi) (a
 * particle weighed against several reads computes them once). The reader
 * offset is fixed on the robot, so it does not enter the Jacobians. */
inline mrpt::math::TPoint2D readModel(const mrpt::math::TPose2D& robot, double c,
                                      double s, double offX, double offY,
                                      const mrpt::math::TPoint2D& tag,
                                      TReadJacobians* J = nullptr) {
    double lx, ly;  // tag, robot frame
    worldToRobotFrame(robot.x, robot.y, c, s, tag.x, tag.y, lx, ly);
    if (J) {
        J->pose[0][0] = -c, J->pose[0][1] = -s, J->pose[0][2] = ly;
        J->pose[1][0] = s, J->pose[1][1] = -c, J->pose[1][2] = -lx;
        J->tag[0][0] = c, J->tag[0][1] = s;
        J->tag[1][0] = -s, J->tag[1][1] = c;
    }
    return {lx - offX, ly - offY};
}

/** The same, computing cos and sin of the heading. */
inline mrpt::math::TPoint2D readModel(const mrpt::math::TPose2D& robot, double offX,
                                      double offY, const mrpt::math::TPoint2D& tag,
                                      TReadJacobians* J = nullptr) {
    return readModel(robot, std::cos(robot.phi), std::sin(robot.phi), offX, offY, tag, J);
}

/** A point given in the robot frame, in the world (003 eq. 6): t + R(phi) (x, y).
 * With (x, y) = offset + e it inverts readModel for the tag; with e = 0 it is
 * the reader centre. */
inline mrpt::math::TPoint2D robotFrameToWorld(const mrpt::math::TPose2D& robot, double c,
                                              double s, double x, double y) {
    return {robot.x + c * x - s * y, robot.y + s * x + c * y};
}

/** readModel solved for the robot position: the robot at heading phi (c, s)
 * that sees a tag at `tag` at (x, y) in its frame stands at tag - R(phi) (x, y). */
inline mrpt::math::TPoint2D robotPositionFromRead(const mrpt::math::TPoint2D& tag,
                                                  double c, double s, double x,
                                                  double y) {
    return {tag.x - (c * x - s * y), tag.y - (s * x + c * y)};
}

}  // namespace rfir::models
