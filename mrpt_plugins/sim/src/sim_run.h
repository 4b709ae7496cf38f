/* rfir-sim: one run in progress: the timeline (true path with kidnapping)
 * and what the time loops share (simulator.cpp: one step per dt;
 * sim_events.cpp: event-driven timing). */
#pragma once

#include <rfir/sim/simulator.h>

#include "odometry.h"
#include "trajectory.h"
#include "world.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfir::sim::detail {
using mrpt::poses::CPose2D;

/** Maps real time to the plan, with the kidnapping: before `ts` the plan is
 * followed; during the carry the robot moves from plan(ts) to the target; after
 * `te` it follows K (+) plan(t - te + s0). wheels(t) is the pose its wheels
 * would have integrated (they stop while carried). */
class CTimeline {
  public:
    CTimeline(const TSimConfig& cfg, const CPlan& plan) : plan_(plan) {
        const auto& k = cfg.kidnap;
        end_ = plan.duration();
        if (!k.enabled) return;
        if (k.time >= plan.duration())
            throw std::invalid_argument(
                "[kidnap] time is after the end of the trajectory (" +
                std::to_string(plan.duration()) + " s)");
        on_ = true;
        ts_ = k.time, te_ = k.time + k.carryTime;
        s0_ = k.toTime >= 0 ? k.toTime : k.time;
        const CPose2D target =
            k.toTime >= 0 ? plan.at(s0_) : CPose2D(k.toX, k.toY, k.toPhi);
        K_ = target + (CPose2D() - plan.at(s0_));
        lift_ = plan.at(ts_);
        end_ = te_ + plan.duration() - s0_;
    }
    double end() const { return end_; }
    bool carried(double t) const { return on_ && t >= ts_ && t < te_; }
    CPose2D truePose(double t) const {
        if (!on_ || t < ts_) return plan_.at(t);
        if (t >= te_) return K_ + plan_.at(t - te_ + s0_);
        const CPose2D to = K_ + plan_.at(s0_);
        const double f = te_ > ts_ ? (t - ts_) / (te_ - ts_) : 1.0;
        const double dphi = std::atan2(std::sin(to.phi() - lift_.phi()),
                                       std::cos(to.phi() - lift_.phi()));
        return {lift_.x() + f * (to.x() - lift_.x()),
                lift_.y() + f * (to.y() - lift_.y()), lift_.phi() + f * dphi};
    }
    CPose2D wheels(double t) const {
        if (!on_ || t < ts_) return plan_.at(t);
        if (t < te_) return lift_;
        return lift_ + (CPose2D() - plan_.at(s0_)) + plan_.at(t - te_ + s0_);
    }
    /** Real times at which the robot stands at plan time `s`. */
    std::vector<double> realTimes(double s) const {
        std::vector<double> v;
        if (!on_ || s < ts_) v.push_back(s);
        if (on_ && s >= s0_) v.push_back(s - s0_ + te_);
        return v;
    }

  private:
    const CPlan& plan_;
    bool on_ = false;
    double ts_ = 0, te_ = 0, s0_ = 0, end_ = 0;
    CPose2D K_, lift_;
};

/** CPose2D wraps headings into [-pi, pi); textlog angles are in (-pi, pi]:
 * a heading of exactly -pi (a start facing -x) is stored as pi, the value the
 * import of its text gives. */
inline CPose2D textPose(CPose2D p) {
    if (p.phi() == -M_PI) p.phi(M_PI);
    return p;
}

/** Everything a time loop reads and draws from. */
struct TSimRun {
    const TSimConfig& cfg;
    const CTimeline& tl;
    const TWorld& world;
    COdometrySimulator& odo;
    CSlipSchedule& slips;
    rfir::sim::TSimRandom &rfid, &ir, &rb, &fault, &timing;
    double end = 0;  //!< elapsed time of the last step (s)
    size_t n = 0;    //!< steps of the dt grid
};

/** The event-driven loop (odometry rate or latency, round-robin polls). */
void runEvents(TSimRun& run, TSimOutput& out);
}  // namespace rfir::sim::detail
