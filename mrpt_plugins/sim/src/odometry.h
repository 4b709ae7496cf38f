/* rfir-sim: wheel odometry noise (model and defaults in docs/simulator.md). */
#pragma once

#include <rfir/sim/simulator.h>

#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include "sim_random.h"

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
}  // namespace rfir::sim::detail
