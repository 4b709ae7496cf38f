/* rfir: the probability that a polled reader reads a tag at offset e (tag
 * minus reader centre, robot frame), for negative information: a reader
 * that did not read the tag weighs it by 1 - p_d P(read). Written once, over
 * any scalar, for the tag filters ([tagmap] negative_information) and the
 * offline smoother's miss factors (ceres::Jet).
 *
 * P(read) is a square whose soft edge lies inside the reader's square: 1/2
 * at (h - 2 tau) from the centre, 0.12 on the edge, about 0 outside. A tag
 * just outside a reader, as every unread tag near it is, then costs
 * nothing. The read model's own tail (read_noise.h: w about 1 on the edge,
 * 0.2 half a side outside it) as P(read) pushed tags out of every square
 * they passed near: in the smoother the whole map moved outwards, and in
 * the filters, on a lawnmower path whose stripes re-read the previous
 * stripe's tags, the push added up stripe after stripe (docs/slam.md,
 * "Negative information"). */
#pragma once

#include <rfir/models/detection_likelihood.h>
#include <rfir/models/read_model.h>

#include <cmath>

namespace rfir::models {

/** |e| smoothed over tau (sqrt(e^2 + tau^2)): differentiable at 0. */
template <class T>
T smoothAbs(const T& e, double tau) {
    using std::sqrt;
    return sqrt(e * e + T(tau * tau));
}

/** Probability-like indicator of |e| < h (a logistic over tau). */
template <class T>
T softInside(const T& e, double h, double tau) {
    using std::exp;
    const T z = (smoothAbs(e, tau) - h) / tau;
    if (z > T(40)) return T(0) * z + T(std::exp(-40.0));
    return T(1) / (T(1) + exp(z));
}

/** P(read) of a tag at offset (ex, ey) from a reader of half-sizes (hx,
 * hy), the edge smoothed over (tauX, tauY). */
template <class T>
T readProbability(const T& ex, const T& ey, double hx, double hy, double tauX,
                  double tauY) {
    return softInside(ex, hx - 2 * tauX, tauX) * softInside(ey, hy - 2 * tauY, tauY);
}

/** The smoothing the filters use: this share of each half-size (the
 * smoother's `read_edge_smoothing` default). */
constexpr double kMissEdgeSmoothing = 0.1;

/** log(1 - pd P(read)) of a reader of `area` (robot frame) that did not read
 * a tag at `tag` (world), the robot at `robot` with cos c and sin s. */
inline double missLogLikelihood(const mrpt::math::TPose2D& robot, double c, double s,
                                const ReaderArea& area, const mrpt::math::TPoint2D& tag,
                                double pd) {
    const auto e = readModel(robot, c, s, area.x, area.y, tag);
    return std::log1p(-pd * readProbability(e.x, e.y, area.halfX, area.halfY,
                                            kMissEdgeSmoothing * area.halfX,
                                            kMissEdgeSmoothing * area.halfY));
}

}  // namespace rfir::models
