/* rfir-sim: the planned robot path, a piecewise-linear function of time. */
#pragma once

#include <rfir/sim/simulator.h>

#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include "sim_random.h"

#include <vector>

namespace rfir::sim::detail {
/** Pose with an unwrapped heading, so that turns interpolate the right way. */
struct TPoseU {
    double x = 0, y = 0, phi = 0;
    mrpt::poses::CPose2D pose() const { return {x, y, phi}; }
};

struct TSegment {
    double t0 = 0, t1 = 0;
    TPoseU from, to;
};

class CPlan {
  public:
    /** Builds the path of `cfg.trajectory` inside the area (random waypoints
     * drawn from `rng`). */
    CPlan(const TSimConfig& cfg, rfir::sim::TSimRandom& rng);
    /** Pose at plan time t (clamped to [0, duration]). */
    mrpt::poses::CPose2D at(double t) const;
    double duration() const { return segs_.empty() ? 0 : segs_.back().t1; }
    /** Plan times of the middle of every stop at a spot. */
    const std::vector<double>& spotTimes() const { return spots_; }
    /** Corner waypoints the path visits (for tests and docs). */
    const std::vector<TPoseU>& waypoints() const { return wps_; }

  private:
    void addTranslation(const TPoseU& to, const TSimConfig& cfg, double spotStep,
                        double& arcDone, double& nextSpot);
    void addTurn(double phi, double rate);
    void addPause(double seconds);
    TPoseU cur_;
    double t_ = 0;
    std::vector<TSegment> segs_;
    std::vector<double> spots_;
    std::vector<TPoseU> wps_;
};

/** Waypoints (x, y) of a trajectory kind inside the rectangle [x0,x1]x[y0,y1]. */
std::vector<TPoseU> trajectoryWaypoints(const TTrajectoryConfig& t, double x0, double y0,
                                        double x1, double y1, rfir::sim::TSimRandom& rng);

}  // namespace rfir::sim::detail
