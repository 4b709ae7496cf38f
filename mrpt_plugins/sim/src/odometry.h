/* rfir-sim: wheel odometry noise (model and defaults in docs/simulator.md). */
#pragma once

#include <rfir/sim/simulator.h>

#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include "sim_random.h"

#include <string>
#include <vector>

namespace rfir::sim::detail {
/** Corrupts true increments with the TOdometryNoise model: per-run biases are
 * drawn at construction, per-step Gaussian noise on each call. */
class COdometrySimulator {
  public:
    COdometrySimulator(const TOdometryNoise& n, rfir::sim::TSimRandom& rng);
    /** The increment (robot frame) the odometry reports for a true one. A zero
     * increment (robot standing or carried) stays exactly zero. */
    mrpt::poses::CPose2D noisyIncrement(const mrpt::poses::CPose2D& trueInc);
    double scaleBias() const { return s_; }
    double rotScaleBias() const { return r_; }
    double headingDrift() const { return h_; }

  private:
    TOdometryNoise n_;
    rfir::sim::TSimRandom& rng_;
    double s_ = 0, r_ = 0, h_ = 0;
};

/** The wheel slips of a run (TOdometryNoise slip keys): the given times plus
 * slipCount uniform ones, drawn at construction from the fault generator. */
class CSlipSchedule {
  public:
    CSlipSchedule(const TOdometryNoise& n, double end, rfir::sim::TSimRandom& rng);
    /** `inc` (the reported increment of the interval ending at elapsed time e,
     * true increment `trueInc`) plus every slip not applied yet at or before
     * e; each is recorded as "slip t dx dy dphi" in `log`. */
    mrpt::poses::CPose2D apply(double e, double t, const mrpt::poses::CPose2D& trueInc,
                               mrpt::poses::CPose2D inc, std::vector<std::string>& log);

  private:
    std::vector<double> times_;
    size_t next_ = 0;
    double size_ = 0, heading_ = 0;
};

/** The extra odometry increment (robot frame) of one wheel slip during the
 * true increment `inc`: `size` m along its direction, `heading` rad. */
mrpt::poses::CPose2D slipIncrement(const mrpt::poses::CPose2D& inc, double size,
                                   double heading);
}  // namespace rfir::sim::detail
