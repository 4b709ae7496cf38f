/* rfir: one SLAM method behind a common step interface, so the app, the tests
 * and the benchmarks run every method the same way on the same data. */
#pragma once

#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/slam/slam_config.h>

#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rfir::slam {
/** One sensing instant as the methods see it. */
struct TSlamInput {
    double t = 0;
    /** Odometry increment since the previous instant (none: not moved). */
    std::optional<mrpt::poses::CPose2D> odometryIncrement;
    /** Seconds the increment covers (0: unknown): the slip test's time. */
    double odometryDt = 0;
    /** Interpolated polls ([motion] interpolate_polls): the odometry
     * intervals the increment is part of; empty: one whole interval. */
    std::vector<TOdometryPart> odometryParts;
    rfir::obs::CObservationRFIDReaders::Ptr rfid;
    mrpt::obs::CObservationBearingRange::Ptr rb;
};

/** A landmark estimate for map.txt. */
struct TLandmarkOut {
    bool isTag = true;  //!< RFID tag, else range-bearing landmark
    std::string id;
    double x = 0, y = 0, sx = 0, sy = 0;
    /** PF/PS: the (reader, tag) reads and how many of them the estimate at
     * the time contradicted (map.txt's last two columns); FastSLAM: unset. */
    std::optional<uint64_t> reads{};
    uint64_t contradicted = 0;
    /** PF/PS: times the tag was placed again ([tagmap] reseat_contradicted). */
    uint64_t reseats = 0;
};

class CSlamEngine {
  public:
    virtual ~CSlamEngine() = default;
    /** Starts at `start` (the rawlog's start pose or --start). */
    virtual void reset(const mrpt::poses::CPose2D& start) = 0;
    virtual void step(const TSlamInput& in) = 0;
    /** The current robot estimate. */
    virtual mrpt::poses::CPose2D pose() const = 0;
    virtual std::vector<TLandmarkOut> landmarks() const = 0;
    /** The robot particles now (for a live view); empty: the method keeps none. */
    virtual std::vector<mrpt::math::TPose2D> particlePoses() const { return {}; }
    /** Times (TSlamInput::t) of the sensor resettings done so far
     * (kidnapping recovery), in order. */
    virtual const std::vector<double>& resetTimes() const {
        static const std::vector<double> none;
        return none;
    }
    /** Times of the kidnap check's triggers that smoothing took for loop
     * closures ([kidnap] loop_closure_smoothing), in order. */
    virtual const std::vector<double>& loopClosureTimes() const {
        static const std::vector<double> none;
        return none;
    }
};

/** The engine for cfg.slam.method; `hdr` names range-bearing landmarks. */
std::unique_ptr<CSlamEngine> makeEngine(const TSlamConfig& cfg,
                                        const rfir::obs::CObservationLogHeader& hdr);

/** A run's estimated path and timing. */
struct TSlamRun {
    std::vector<std::pair<double, mrpt::poses::CPose2D>> path;  //!< (t, pose) per step
    std::vector<TLandmarkOut> map;
    double totalTime = 0, meanStepTime = 0, maxStepTime = 0;  //!< s, of step() calls
    size_t resets = 0;
    std::vector<double> resetTimes;        //!< s, one per reset
    std::vector<double> loopClosureTimes;  //!< s, triggers taken for loop closures
};

/** Runs `engine` from `start` over the inputs; `progress(i)` after each step. */
TSlamRun runEngine(CSlamEngine& engine, const mrpt::poses::CPose2D& start,
                   const std::vector<TSlamInput>& inputs,
                   const std::function<void(size_t)>& progress = {});

}  // namespace rfir::slam
