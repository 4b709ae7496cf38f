#include <rfir/slam/detections.h>

namespace rfir::slam {
void appendDetections(const rfir::obs::CObservationRFIDReaders& o,
                      std::vector<TDetection>& out) {
    for (const auto& r : o.readings)
        for (const auto& tag : r.tags) {
            TDetection d;
            d.kind = TDetection::Kind::RFID;
            d.id = tag;
            d.a = r.reader.x;
            d.b = r.reader.y;
            d.halfX = r.reader.halfX;
            d.halfY = r.reader.halfY;
            out.push_back(std::move(d));
        }
}

void appendDetections(const mrpt::obs::CObservationBearingRange& o,
                      const rfir::obs::CObservationLogHeader& hdr,
                      std::vector<TDetection>& out) {
    const mrpt::poses::CPose2D sensor(o.sensorLocationOnRobot);
    for (const auto& m : o.sensedData) {
        TDetection d;
        d.kind = TDetection::Kind::RangeBearing;
        d.id = hdr.landmarkName(m.landmarkID);
        d.a = m.range;
        d.b = m.yaw;
        d.sensor = sensor;
        d.stdRange = o.sensor_std_range;
        d.stdBearing = o.sensor_std_yaw;
        out.push_back(std::move(d));
    }
}

}  // namespace rfir::slam
