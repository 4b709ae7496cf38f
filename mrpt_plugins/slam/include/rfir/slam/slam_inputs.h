/* rfir: building the SLAM engines' inputs from instants that carry absolute
 * odometry poses and a list of observations (the simulator's in-memory steps,
 * or anything shaped like them). */
#pragma once

#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/slam/slam_engine.h>

#include <mrpt/obs/CObservationBearingRange.h>

#include <optional>
#include <vector>

namespace rfir::slam {
/** One input per step: the odometry increment between consecutive absolute
 * odometry poses (none for the first pose or a step without odometry) and the
 * step's RFID / range-bearing observations. `Steps` is any range of elements
 * with `t`, `odometry` (std::optional<CPose2D>) and `obs` (vector of
 * CObservation::Ptr), e.g. rfir::sim::TSimOutput::steps. */
template <class Steps>
std::vector<TSlamInput> inputsFromSteps(const Steps& steps) {
    std::vector<TSlamInput> v;
    v.reserve(steps.size());
    std::optional<mrpt::poses::CPose2D> last;
    double lastT = 0;
    for (const auto& s : steps) {
        TSlamInput in;
        in.t = s.t;
        if (s.odometry) {
            if (last) {
                in.odometryIncrement = *s.odometry - *last;
                in.odometryDt = s.t - lastT;
            }
            last = s.odometry;
            lastT = s.t;
        }
        for (const auto& o : s.obs) {
            if (auto r = std::dynamic_pointer_cast<rfir::obs::CObservationRFIDReaders>(o))
                in.rfid = r;
            else if (auto b =
                         std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(
                             o))
                in.rb = b;
        }
        v.push_back(std::move(in));
    }
    return v;
}

/** An instant as read from a log: its time, the absolute odometry pose if an
 * odometry record came with it, and its observations. */
struct TRawInstant {
    double t = 0;
    std::optional<mrpt::poses::CPose2D> odometry;
    rfir::obs::CObservationRFIDReaders::Ptr rfid;
    mrpt::obs::CObservationBearingRange::Ptr rb;
};

/** [motion] interpolate_polls: every instant placed at the odometry
 * interpolated to its time (an odometry record stamped t taken as the pose
 * at t - latency; before the first record the first pose, after the last the
 * last), its increment the change since the previous instant, with the parts
 * of the odometry intervals it covers (TOdometryPart), so that the motion
 * noise of an interval is drawn once in total. Times must not decrease. */
std::vector<TSlamInput> interpolatedInputs(const std::vector<TRawInstant>& instants,
                                           double latency);

}  // namespace rfir::slam
