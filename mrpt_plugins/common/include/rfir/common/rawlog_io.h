/* rfir: writing and reading rawlogs in the project's layout
 * (docs/rawlog-layout.md). */
#pragma once

#include <rfir/common/gz_input.h>
#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationRFID.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rfir::common {
/** Streams a rawlog to "<path>.tmp.<pid>"; close() renames it to `path`, so a
 * failed run leaves no half-written file. */
class CRawlogWriter {
  public:
    /** Writes the header pair at once. `motion` sets the Gaussian odometry model
     * stored in each CActionRobotMovement2D (SLAM apps use their own INI model). */
    CRawlogWriter(
        const std::string& path, const rfir::obs::CObservationLogHeader& hdr,
        const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions& motion = {});
    ~CRawlogWriter();
    CRawlogWriter(const CRawlogWriter&) = delete;
    CRawlogWriter& operator=(const CRawlogWriter&) = delete;

    /** One sensing instant at time t: odometry (absolute pose, if any) and the
     * observations; timestamps of the observations are set to t here. */
    void writeStep(double t, const std::optional<mrpt::poses::CPose2D>& odometry,
                   const std::vector<mrpt::obs::CObservation::Ptr>& obs);
    void close();
    size_t stepsWritten() const { return steps_; }

  private:
    mrpt::obs::CActionRobotMovement2D zeroMovement(mrpt::Clock::time_point ts) const;
    std::string path_, tmp_;
    std::unique_ptr<mrpt::io::CFileGZOutputStream> out_;
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motion_;
    std::optional<mrpt::poses::CPose2D> lastOdom_;
    size_t steps_ = 0;
};

/** One sensing instant read back. */
struct TRawlogStep {
    double t = 0;
    size_t index = 0;  //!< 0-based instant index (header excluded)
    mrpt::obs::CActionCollection::Ptr action;  //!< may hold no movement
    mrpt::obs::CSensoryFrame::Ptr sf;
    std::optional<mrpt::poses::CPose2D> odometry;  //!< absolute odometry pose
    /** Odometry increment since the previous instant (nullopt: none given, or
     * the instant of the first absolute odometry record, which only anchors
     * the odometry frame: the same inputs as rfir::slam::inputsFromSteps). */
    std::optional<mrpt::poses::CPose2D> odometryIncrement;
    rfir::obs::CObservationRFIDReaders::Ptr rfid;
    rfir::obs::CObservationIRSignals::Ptr ir;
    mrpt::obs::CObservationBearingRange::Ptr rb;
};

/** Reads a rawlog instant by instant: the project's action/sensory-frame
 * layout, or MRPT's observation-only layout (observations with the same
 * timestamp form an instant; CObservationOdometry poses give the increments).
 * MRPT's CObservationRFID is read into `rfid` (docs/rawlog-layout.md). Unlike
 * CRawlog's helpers it never swallows an error: a corrupt entry or an
 * unregistered class throws std::runtime_error naming the file and entry. */
class CRawlogReader {
  public:
    explicit CRawlogReader(const std::string& path);
    /** The log header (an empty one, with a warning on stderr, when the rawlog
     * was not written by this project). */
    const rfir::obs::CObservationLogHeader& header() const { return *header_; }
    /** False when the rawlog has no rfir log header (header() is then empty). */
    bool hasHeader() const { return hasHeader_; }
    /** Next instant; false at the end of the file. */
    bool next(TRawlogStep& step);
    const std::string& path() const { return path_; }

  private:
    mrpt::serialization::CSerializable::Ptr readObject();
    bool nextPair(mrpt::obs::CActionCollection::Ptr& acts,
                  mrpt::obs::CSensoryFrame::Ptr& sf);
    bool nextFlatInstant(mrpt::obs::CSensoryFrame::Ptr& sf);
    void addMrptRFID(TRawlogStep& st, const mrpt::obs::CObservationRFID& o);
    bool readStep(TRawlogStep& st);
    /** Refuses a non-finite pose or measurement of MRPT's classes. */
    void checkFinite(const TRawlogStep& st) const;
    /** Warns once per class of an observation no method uses. */
    void warnUnused(const mrpt::obs::CObservation& o);
    rfir::obs::TRFIDReader readerOf(const mrpt::obs::CObservationRFID& o,
                                    const std::string& id);
    std::string path_;
    CGzInputStream in_;
    size_t entry_ = 0, steps_ = 0;
    bool sawOdometry_ = false;  //!< an absolute odometry record was read
    bool obsOnly_ = false;      //!< MRPT's observation-only layout
    bool hasHeader_ = true;
    rfir::obs::CObservationLogHeader::Ptr header_;
    std::optional<
        std::pair<mrpt::obs::CActionCollection::Ptr, mrpt::obs::CSensoryFrame::Ptr>>
        pending_;
    mrpt::obs::CObservation::Ptr pendingObs_;           //!< observation-only: read ahead
    std::optional<mrpt::poses::CPose2D> lastOdometry_;  //!< observation-only
    std::set<std::string> warnedReaders_, warnedClasses_;
};

}  // namespace rfir::common
