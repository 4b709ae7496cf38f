/* rfir: trajectory metrics as evo and the TUM benchmark report them, beyond
 * the papers' unaligned mean/max: the absolute pose error after a closed-form
 * SE(2) (or Sim(2)) alignment of the estimate onto the truth (Umeyama 1991,
 * Horn 1987, in the plane), and the relative pose error over a fixed travelled
 * distance or time. Units: metres and radians. */
#pragma once

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <vector>

namespace rfir::eval {
/** One estimated pose and the true pose it is compared with. */
struct TPosePair {
    double t = 0;
    mrpt::poses::CPose2D est, gt;
};

/** x -> scale * R(theta) x + (tx, ty), applied to estimated positions; the
 * heading turns by theta. */
struct TAlignment {
    double tx = 0, ty = 0, theta = 0, scale = 1;
    mrpt::poses::CPose2D apply(const mrpt::poses::CPose2D& p) const;
};

/** Least-squares alignment of the estimated positions onto the true ones
 * (positions only, as evo's --align): closed form, rotation from the
 * cross-covariance of the centred point sets; the scale too with `withScale`
 * (evo's --correct_scale). Fewer than two distinct points give the identity
 * rotation (translation only). */
TAlignment alignPositions(const std::vector<TPosePair>& pairs, bool withScale = false);

/** Statistics of the relative pose error over one kind of step. */
struct TRpeStats {
    size_t pairs = 0;  //!< compared pose pairs (i, j)
    double delta = 0;  //!< step length: metres or seconds
    double mean_trans = 0, rmse_trans = 0, max_trans = 0;  //!< metres
    double mean_rot = 0, rmse_rot = 0, max_rot = 0;        //!< radians
};

enum class RpeUnit { Metres, Seconds };

/** Relative pose error E = (G_i^-1 G_j)^-1 (P_i^-1 P_j) for every start i,
 * with j the first later pose whose true travelled distance (Metres) or time
 * (Seconds) from i reaches `delta` (every start pose, as the TUM benchmark's
 * evaluate_rpe; evo without --all_pairs uses non-overlapping steps, hence
 * fewer pairs and the same expectation). Translation |E.t|, rotation
 * |E.phi|. Starts with no such j are not counted; no pair gives pairs == 0. */
TRpeStats relativePoseError(const std::vector<TPosePair>& pairs, double delta,
                            RpeUnit unit);

}  // namespace rfir::eval
