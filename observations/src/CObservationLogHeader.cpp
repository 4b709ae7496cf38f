/* rfir: rawlog header observation. */
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/serialization/CArchive.h>

#include <iomanip>

using namespace rfir::obs;

IMPLEMENTS_SERIALIZABLE(CObservationLogHeader, mrpt::obs::CObservation, rfir::obs)
RFIR_REGISTER_CLASS(CObservationLogHeader, rfir::obs::CObservationLogHeader)

std::string CObservationLogHeader::landmarkName(int32_t id) const {
    if (id >= 0 && size_t(id) < rbLandmarkNames.size()) return rbLandmarkNames[id];
    return std::to_string(id);
}

uint8_t CObservationLogHeader::serializeGetVersion() const {
    return 0;
}

void CObservationLogHeader::serializeTo(mrpt::serialization::CArchive& out) const {
    out << timestamp << sensorLabel;
    out.WriteAs<uint32_t>(readers.size());
    for (const auto& r : readers) out << r.id << r.x << r.y << r.halfX << r.halfY;
    out.WriteAs<uint32_t>(receivers.size());
    for (const auto& r : receivers) out << r.id << r.x << r.y << r.z;
    out << rbSensor.has_value();
    if (rbSensor)
        out << rbSensor->x << rbSensor->y << rbSensor->yaw << rbSensor->maxRange
            << rbSensor->fov;
    out << startPose.has_value();
    if (startPose) out << startPose->x() << startPose->y() << startPose->phi();
    out.WriteAs<uint32_t>(rbLandmarkNames.size());
    for (const auto& n : rbLandmarkNames) out << n;
}

void CObservationLogHeader::serializeFrom(mrpt::serialization::CArchive& in,
                                          uint8_t version) {
    switch (version) {
        case 0: {
            using B = TReadBounds;
            constexpr const char* kWhat = "CObservationLogHeader";
            in >> timestamp;
            sensorLabel = readBoundedString(in, kWhat);
            readers.resize(readBoundedCount(in, kWhat, B::kMaxSensors, 4 + 32));
            for (auto& r : readers) {
                r.id = readBoundedString(in, kWhat);
                in >> r.x >> r.y >> r.halfX >> r.halfY;
                requireFinite(kWhat, "reader x y halfX halfY",
                              {r.x, r.y, r.halfX, r.halfY});
            }
            receivers.resize(readBoundedCount(in, kWhat, B::kMaxSensors, 4 + 24));
            for (auto& r : receivers) {
                r.id = readBoundedString(in, kWhat);
                in >> r.x >> r.y >> r.z;
                requireFinite(kWhat, "receiver x y z", {r.x, r.y, r.z});
            }
            rbSensor.reset();
            if (readStrictBool(in, kWhat)) {
                TRBSensor s;
                in >> s.x >> s.y >> s.yaw >> s.maxRange >> s.fov;
                requireFinite(kWhat, "rb_sensor x y yaw max_range fov",
                              {s.x, s.y, s.yaw, s.maxRange, s.fov});
                rbSensor = s;
            }
            startPose.reset();
            if (readStrictBool(in, kWhat)) {
                double x, y, phi;
                in >> x >> y >> phi;
                requireFinite(kWhat, "start pose", {x, y, phi});
                // Set field by field: CPose2D(x, y, phi) normalizes a
                // heading of pi to -pi, and the pose must read back as written.
                startPose.emplace();
                startPose->x(x);
                startPose->y(y);
                startPose->phi(phi);
            }
            rbLandmarkNames.resize(readBoundedCount(in, kWhat, B::kMaxNames, 4));
            for (auto& n : rbLandmarkNames) n = readBoundedString(in, kWhat);
        } break;
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

void CObservationLogHeader::getDescriptionAsText(std::ostream& o) const {
    CObservation::getDescriptionAsText(o);
    o << "rfir log header (the robot's declared sensors)\n"
      << std::fixed << std::setprecision(4);
    o << "RFID readers: " << readers.size() << "\n";
    for (const auto& r : readers)
        o << "  " << std::left << std::setw(12) << r.id << std::right << " centre ("
          << r.x << ", " << r.y << ") m, detection half-size (" << r.halfX << ", "
          << r.halfY << ") m\n";
    o << "IR receivers: " << receivers.size() << "\n";
    for (const auto& r : receivers)
        o << "  " << std::left << std::setw(12) << r.id << std::right << " at (" << r.x
          << ", " << r.y << ") m, height " << r.z << " m\n";
    if (rbSensor)
        o << "Range-bearing sensor at (" << rbSensor->x << ", " << rbSensor->y
          << ") m, yaw " << rbSensor->yaw << " rad, max range " << rbSensor->maxRange
          << " m, field of view " << rbSensor->fov << " rad; " << rbLandmarkNames.size()
          << " landmark name(s)\n";
    else
        o << "Range-bearing sensor: none\n";
    if (startPose)
        o << "Start pose (world): x=" << startPose->x() << " m, y=" << startPose->y()
          << " m, phi=" << startPose->phi() << " rad\n";
    else
        o << "Start pose: not given (the world frame is the start pose)\n";
}
