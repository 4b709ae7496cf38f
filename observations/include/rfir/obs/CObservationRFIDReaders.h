/* rfir: multi-reader HF RFID observation (the readers under the robot of the
 * thesis, chapter 3). */
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

namespace rfir::obs {
/** Geometry of one HF RFID reader antenna under the robot: it detects a tag
 * whose centre lies in the axis-aligned rectangle of half-sizes (halfX, halfY)
 * around (x, y), both in the robot frame (metres). */
struct TRFIDReader {
    std::string id;
    double x = 0, y = 0;
    double halfX = 0.03, halfY = 0.03;
    bool operator==(const TRFIDReader& o) const {
        return id == o.id && x == o.x && y == o.y && halfX == o.halfX && halfY == o.halfY;
    }
};

/** One sensing instant of several HF RFID readers. HF readers give no signal
 * strength, so an entry is just (reader, tag IDs). A reader that was polled and
 * read nothing has an empty tag list; a reader not polled is absent. The reader
 * geometry travels with every observation so that SLAM never needs it from an
 * INI file. */
class CObservationRFIDReaders : public mrpt::obs::CObservation {
    DEFINE_SERIALIZABLE(CObservationRFIDReaders, rfir::obs)

  public:
    struct TReading {
        TRFIDReader reader;
        std::vector<std::string> tags;
        bool operator==(const TReading& o) const {
            return reader == o.reader && tags == o.tags;
        }
    };
    std::vector<TReading> readings;

    /** Number of (reader, tag) detections in this observation. */
    size_t detectionCount() const;

    void getSensorPose(mrpt::poses::CPose3D& p) const override {
        p = mrpt::poses::CPose3D();
    }
    void setSensorPose(const mrpt::poses::CPose3D&) override {}
    using mrpt::obs::CObservation::getSensorPose;
    using mrpt::obs::CObservation::setSensorPose;
    void getDescriptionAsText(std::ostream& o) const override;
    bool exportTxtSupported() const override { return true; }
    std::string exportTxtHeader() const override;
    std::string exportTxtDataRow() const override;
};

}  // namespace rfir::obs
