/* rfir: accuracy metrics of the papers' tables (thesis tables 3.1, 3.2, 4.1,
 * 4.2, 5.2; PS-SLAM paper tables 3-7): mean and max of |dx|, |dy|, |dtheta|
 * and distance, for the robot path and for the mapped landmarks.
 * Units: metres and radians (tables convert to mm). */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/eval/trajectory_metrics.h>
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rfir::eval {
/** Mean and max of the absolute errors. For maps, dtheta is unused (0). */
struct TErrorStats {
    size_t count = 0;  //!< number of evaluated items (poses or landmarks)
    double mean_dx = 0, mean_dy = 0, mean_dtheta = 0, mean_dist = 0;
    double max_dx = 0, max_dy = 0, max_dtheta = 0, max_dist = 0;
    /** Root mean square of dist and of dtheta (evo's APE "rmse"). */
    double rmse_dist = 0, rmse_dtheta = 0;
};

/** Error of one estimated pose against the ground truth at the same time. */
struct TPoseError {
    double t = 0;
    double dx = 0, dy = 0;  //!< estimate minus truth, world frame (signed)
    double dtheta = 0;      //!< estimate minus truth, wrapped to (-pi, pi]
    double dist = 0;        //!< hypot(dx, dy)
};

struct TRobotErrors {
    TErrorStats stats;
    std::vector<TPoseError> perPose;  //!< in the estimated path's order
    /** Estimated poses outside the ground truth's time span (not evaluated). */
    size_t skipped = 0;
    /** The compared poses, in perPose's order. */
    std::vector<TPosePair> pairs;
    /** SE(2) alignment of the estimate onto the truth (alignPositions, no
     * scale) and the errors after it (evo_ape --align). */
    TAlignment alignment;
    TErrorStats aligned;
    /** Relative pose error per metre travelled and per second (evo_rpe
     * --delta 1 --delta_unit m / s). */
    TRpeStats rpePerMetre, rpePerSecond;
};

/** Error of one mapped landmark against its true position. */
struct TLandmarkError {
    std::string id;
    double dx = 0, dy = 0, dist = 0;  //!< estimate minus truth (signed dx, dy)
};

struct TMapErrors {
    rfir::common::TMapEntry::Kind kind = rfir::common::TMapEntry::Kind::Tag;
    TErrorStats stats;  //!< over the mapped landmarks whose ID is in the truth
    std::vector<TLandmarkError> perLandmark;
    size_t mapped = 0;  //!< estimated entries of `kind` whose ID is in the truth
    size_t total = 0;   //!< ground-truth entries of `kind`
    /** Estimated IDs absent from the ground truth (wrong or spurious IDs). */
    std::vector<std::string> unknownIds;
    /** Ground-truth landmarks the robot passed over (came inside a reader's
     * detection area, or the range-bearing sensor's field of view, along the
     * true path); unset when the sensor geometry is unknown. */
    std::optional<size_t> passedOver;
    /** Of the passed-over landmarks, how many were mapped. */
    std::optional<size_t> mappedOfPassedOver;
};

/** Wraps an angle to (-pi, pi] (one definition, in rfir_appcommon). */
using rfir::common::wrapToPi;

/** Ground-truth pose at time t: linear interpolation of x, y and shortest-arc
 * interpolation of the heading between the two bracketing poses (exact when t
 * equals a stored time). nullopt when t is outside [gt.front().t, gt.back().t]
 * (1e-6 s tolerance). `gt` must be sorted by time (checked by the callers below). */
std::optional<mrpt::poses::CPose2D> interpolatePose(const rfir::common::TPath2D& gt,
                                                    double t);

/** Checks that a path is non-empty and in non-decreasing time; throws
 * std::runtime_error naming `what` (e.g. the file) otherwise. */
void checkPath(const rfir::common::TPath2D& p, const std::string& what);

/** How estimated and true poses are paired. */
enum class Association {
    /** Each estimated pose against the truth interpolated at its time (the
     * papers' tables: errors along the whole estimated path). */
    AtEstimateTimes,
    /** Each true pose against the estimate interpolated at its time: for a
     * sparse ground truth such as the IR experiment's marked spots
     * (thesis table 5.2). */
    AtTruthTimes
};

/** Robot errors, pairing poses by time (interpolatePose; errors are always
 * estimate minus truth). Poses with no partner inside the other path's time
 * span are counted in `skipped`. Throws std::runtime_error if no pose can be
 * evaluated or a path is empty / not sorted by time (the interpolated path
 * must be sorted). */
TRobotErrors computeRobotErrors(const rfir::common::TPath2D& est,
                                const rfir::common::TPath2D& gt,
                                Association assoc = Association::AtEstimateTimes);

/** Statistics of a set of per-pose errors (e.g. a time window of perPose). */
TErrorStats statsOf(const std::vector<TPoseError>& errs);

/** Statistics per time window: [t0, t1] cut into n equal windows (the last
 * one closed); an error at time t goes to window floor(n (t - t0) / (t1 -
 * t0)), clamped to the first or last window when t lies outside [t0, t1]. A
 * window with no pose has count 0. Throws std::invalid_argument if n == 0 or
 * t1 <= t0. For instance the laps of a loop run: where a filter's error comes
 * from (the first lap's drift, or what it keeps later). */
std::vector<TErrorStats> segmentStats(const std::vector<TPoseError>& errs, double t0,
                                      double t1, size_t n);

/** Map errors for the landmarks of one kind, associated by ID. Without `kind`,
 * the kind of the estimated entries (Tag if the estimate is empty); throws
 * std::runtime_error if the estimate mixes tags and landmarks and no kind is
 * given. Emitters are skipped when inferring (IR maps are known, not mapped). */
TMapErrors computeMapErrors(const rfir::common::TMapFile& est,
                            const rfir::common::TMapFile& gt,
                            std::optional<rfir::common::TMapEntry::Kind> kind = {});

/** IDs of the ground-truth tags that came inside some reader's detection area
 * (|e_x| < halfX and |e_y| < halfY, textlog `reader`) at some point of the true
 * path. The path is densified between its poses (linear x, y, shortest-arc
 * heading) so that no sample moves a reader by more than a quarter of the
 * smallest half-size: the count does not depend on the ground truth's rate.
 * A step longer than `maxGap` metres (a kidnapping, a teleport) is not
 * densified: only its end poses are checked. Throws if `readers` is empty. */
std::set<std::string> tagsPassedOver(const rfir::common::TMapFile& gt,
                                     const rfir::common::TPath2D& gtPath,
                                     const std::vector<rfir::obs::TRFIDReader>& readers,
                                     double maxGap = 0.5);

/** IDs of the ground-truth range-bearing landmarks that were inside the
 * sensor's range and field of view at some pose of the true path (the ground
 * truth's poses, densified to 1/8 of the range, same `maxGap` rule). */
std::set<std::string> landmarksInView(const rfir::common::TMapFile& gt,
                                      const rfir::common::TPath2D& gtPath,
                                      const rfir::obs::TRBSensor& sensor,
                                      double maxGap = 0.5);

/** Fills `m.passedOver` and `m.mappedOfPassedOver` from a set of IDs. */
void setPassedOver(TMapErrors& m, const std::set<std::string>& passedIds,
                   const rfir::common::TMapFile& est);

/** What the evaluation needs from a rawlog: the sensor geometry and the
 * odometry path. */
struct TRawlogInfo {
    /** Reader geometry: the log header's, or (logs without it) the union of
     * the readers seen in the RFID observations. */
    std::vector<rfir::obs::TRFIDReader> readers;
    std::optional<rfir::obs::TRBSensor> rbSensor;
    /** Absolute odometry poses (CObservationOdometry), or the accumulated
     * odometry increments when absolute poses are absent. Raw odometry frame. */
    rfir::common::TPath2D odometry;
    /** The robot's world pose at the first odometry record (textlog `start`). */
    std::optional<mrpt::poses::CPose2D> startPose;
    size_t steps = 0;
    /** The time of each sensing instant, in order. */
    std::vector<double> instantTimes;
    /** The rawlog has the rfir log header (its own action-observation pair
     * before the first instant's, in the project's layout). */
    bool hasHeader = false;
};

/** Builds a TRawlogInfo step by step, for a program that reads the rawlog's
 * steps for its own use too (readRawlogInfo is this over a whole file). */
class CRawlogInfoBuilder {
  public:
    explicit CRawlogInfoBuilder(const rfir::obs::CObservationLogHeader& header);
    void add(const rfir::common::TRawlogStep& st);
    TRawlogInfo finish();

  private:
    TRawlogInfo info_;
    bool readersFromHeader_;
    std::map<std::string, rfir::obs::TRFIDReader> seenReaders_;
    rfir::common::TPath2D absolute_, accumulated_;
    mrpt::poses::CPose2D acc_;
};

/** Reads a rawlog once (rfir::common::CRawlogReader); throws on a corrupt file. */
TRawlogInfo readRawlogInfo(const std::string& rawlogPath);

/** Dead-reckoning path: the odometry re-expressed so that its first pose
 * coincides with the ground truth at that time (G0 + (O0^-1 + Oi)). Odometry
 * poses before the truth's start are dropped. Throws if nothing overlaps. */
rfir::common::TPath2D alignOdometryAtStart(const rfir::common::TPath2D& odometry,
                                           const rfir::common::TPath2D& gt);

/** Dead-reckoning path from a known world pose at the first odometry record
 * (the rawlog header's start pose): start + (O0^-1 + Oi). */
rfir::common::TPath2D alignOdometryAt(const rfir::common::TPath2D& odometry,
                                      const mrpt::poses::CPose2D& start);

/** The dead-reckoning row's path: from `start` when known (where the filters
 * start: the header's start pose, or rfir-slam's --start), else from the
 * ground truth at the first odometry time. */
rfir::common::TPath2D deadReckoning(const rfir::common::TPath2D& odometry,
                                    const std::optional<mrpt::poses::CPose2D>& start,
                                    const rfir::common::TPath2D& gt);

}  // namespace rfir::eval
