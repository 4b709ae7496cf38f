/* rfir: the header of a rawlog, the header records of textlog.md. */
#pragma once

#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>
#include <vector>

namespace rfir::obs {
/** Range-and-bearing sensor on the robot (textlog `rb_sensor`). */
struct TRBSensor {
    double x = 0, y = 0, yaw = 0;
    double maxRange = 0.5, fov = 2.0943951023931953;  //!< fov: full angle, rad
    bool operator==(const TRBSensor& o) const {
        return x == o.x && y == o.y && yaw == o.yaw && maxRange == o.maxRange &&
               fov == o.fov;
    }
};

/** First observation of every project rawlog: the robot's declared sensors and
 * the optional start pose, so that a SLAM run needs no retyping. Range-and-
 * bearing landmark IDs are strings in the text format; CObservationBearingRange
 * stores int32 IDs, which index `rbLandmarkNames`. */
class CObservationLogHeader : public mrpt::obs::CObservation {
    DEFINE_SERIALIZABLE(CObservationLogHeader, rfir::obs)

  public:
    std::vector<TRFIDReader> readers;
    std::vector<TIRReceiver> receivers;
    std::optional<TRBSensor> rbSensor;
    std::optional<mrpt::poses::CPose2D> startPose;  //!< world pose at first odom
    std::vector<std::string> rbLandmarkNames;

    /** Name of a CObservationBearingRange landmark ID (its decimal text when
     * the ID is not in the table). */
    std::string landmarkName(int32_t id) const;

    void getSensorPose(mrpt::poses::CPose3D& p) const override {
        p = mrpt::poses::CPose3D();
    }
    void setSensorPose(const mrpt::poses::CPose3D&) override {}
    using mrpt::obs::CObservation::getSensorPose;
    using mrpt::obs::CObservation::setSensorPose;
    void getDescriptionAsText(std::ostream& o) const override;
};

}  // namespace rfir::obs
