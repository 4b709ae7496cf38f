/* rfir: one sensing instant's landmark detections, sensor-independent. Reader
 * geometry always comes from the observation itself, never from an INI file. */
#pragma once

#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace rfir::slam {
/** One detection of an identified landmark. */
struct TDetection {
    enum class Kind {
        RFID,         //!< tag inside a reader's area: (x, y) = reader centre, robot frame
        RangeBearing  //!< (range, bearing) from `sensor` (a pose in the robot frame)
    };
    Kind kind = Kind::RFID;
    std::string id;               //!< tag ID, or range-bearing landmark name
    double a = 0, b = 0;          //!< RFID: reader centre x, y; RB: range, bearing
    double halfX = 0, halfY = 0;  //!< RFID: half sizes of the detection area
    mrpt::poses::CPose2D sensor;  //!< RB: sensor pose on the robot
    double stdRange = 0, stdBearing = 0;  //!< RB: from the observation, 0 if unknown
};

/** Every (reader, tag) pair of an RFID observation. */
void appendDetections(const rfir::obs::CObservationRFIDReaders& o,
                      std::vector<TDetection>& out);
/** Every measurement of a bearing-range observation; landmark IDs are named
 * through the log header (docs/rawlog-layout.md). */
void appendDetections(const mrpt::obs::CObservationBearingRange& o,
                      const rfir::obs::CObservationLogHeader& hdr,
                      std::vector<TDetection>& out);

}  // namespace rfir::slam
