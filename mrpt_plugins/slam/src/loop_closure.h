/* rfir: loop closure by smoothing ([kidnap] loop_closure_smoothing; beyond the
 * seeds; docs/slam.md, "Loop closure by smoothing"). A filter whose odometry
 * drifts meets its first tags again metres off, and the kidnap check cannot
 * tell that from a carried robot: both are reads that disagree with every
 * particle. The offline smoother can: with the odometry's heading drift as a
 * variable and no cut at the trigger, it bends a drifted path onto the old
 * tags (the floor's third seed: 95 mm over 20 minutes, where the filter is
 * metres off), while a carried robot's frozen odometry leaves its smoothed
 * path metres from the reads after the put-down. */
#pragma once

#include <rfir/slam/graph_smoother.h>
#include <rfir/slam/slam_config.h>
#include <rfir/slam/slam_engine.h>

#include <optional>
#include <vector>

namespace rfir::slam {

/** The run so far (one input and one filter pose each, the filter's map and
 * earlier resets), smoothed with the drift estimated whatever the number of
 * closures; returned if it explains at least 90 % of the last
 * [kidnap] max_gap seconds' reads (none contradicted by the map's own test,
 * [tagmap] contradict_margin included). */
std::optional<TGraphSmootherResult> smoothedLoopClosure(
    const std::vector<TSlamInput>& inputs, const mrpt::poses::CPose2D& start,
    const TSlamRun& soFar, const TSlamConfig& cfg);

/** The run so far, kept for the smoother: every input, and the estimate of
 * every step before the current one (the smoothed poses after a closure). */
class CRunHistory {
  public:
    void reset(const mrpt::poses::CPose2D& start) {
        start_ = start;
        inputs_.clear();
        path_.clear();
        rangeBearing_ = false;
    }
    void addInput(const TSlamInput& in) {
        inputs_.push_back(in);
        rangeBearing_ = rangeBearing_ || in.rb;
    }
    void addPose(double t, const mrpt::poses::CPose2D& p) { path_.emplace_back(t, p); }
    /** The smoother reads RFID only. */
    bool rangeBearing() const { return rangeBearing_; }
    /** smoothedLoopClosure with the current step at `now` (time t): the
     * smoothed run if it was a loop closure (the history's poses become the
     * smoothed ones), none if not or if the solver failed. */
    std::optional<TSlamRun> closeLoop(double t, const mrpt::poses::CPose2D& now,
                                      std::vector<TLandmarkOut> map,
                                      const std::vector<double>& resetTimes,
                                      const TSlamConfig& cfg);

  private:
    mrpt::poses::CPose2D start_;
    std::vector<TSlamInput> inputs_;
    std::vector<std::pair<double, mrpt::poses::CPose2D>> path_;
    bool rangeBearing_ = false;
};

}  // namespace rfir::slam
