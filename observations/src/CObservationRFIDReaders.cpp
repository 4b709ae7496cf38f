/* rfir: multi-reader HF RFID observation. */
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/datetime.h>

#include <iomanip>
#include <sstream>

using namespace rfir::obs;

IMPLEMENTS_SERIALIZABLE(CObservationRFIDReaders, mrpt::obs::CObservation, rfir::obs)
RFIR_REGISTER_CLASS(CObservationRFIDReaders, rfir::obs::CObservationRFIDReaders)

size_t CObservationRFIDReaders::detectionCount() const {
    size_t n = 0;
    for (const auto& r : readings) n += r.tags.size();
    return n;
}

uint8_t CObservationRFIDReaders::serializeGetVersion() const {
    return 0;
}

void CObservationRFIDReaders::serializeTo(mrpt::serialization::CArchive& out) const {
    out << timestamp << sensorLabel;
    out.WriteAs<uint32_t>(readings.size());
    for (const auto& r : readings) {
        out << r.reader.id << r.reader.x << r.reader.y << r.reader.halfX
            << r.reader.halfY;
        out.WriteAs<uint32_t>(r.tags.size());
        for (const auto& t : r.tags) out << t;
    }
}

void CObservationRFIDReaders::serializeFrom(mrpt::serialization::CArchive& in,
                                            uint8_t version) {
    switch (version) {
        case 0: {
            using B = TReadBounds;
            constexpr const char* kWhat = "CObservationRFIDReaders";
            in >> timestamp;
            sensorLabel = readBoundedString(in, kWhat);
            // On disk a reading takes at least an empty id, 4 doubles and a count.
            readings.resize(readBoundedCount(in, kWhat, B::kMaxSensors, 4 + 32 + 4));
            for (auto& r : readings) {
                r.reader.id = readBoundedString(in, kWhat);
                in >> r.reader.x >> r.reader.y >> r.reader.halfX >> r.reader.halfY;
                requireFinite(kWhat, "reader x y halfX halfY",
                              {r.reader.x, r.reader.y, r.reader.halfX, r.reader.halfY});
                r.tags.resize(readBoundedCount(in, kWhat, B::kMaxTagsPerReading, 4));
                for (auto& t : r.tags) t = readBoundedString(in, kWhat);
            }
        } break;
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

void CObservationRFIDReaders::getDescriptionAsText(std::ostream& o) const {
    CObservation::getDescriptionAsText(o);
    o << "Multi-reader HF RFID observation: " << readings.size() << " reader(s) polled, "
      << detectionCount() << " detection(s)\n";
    o << "reader       centre x,y [m]        half-size x,y [m]   tags read\n";
    for (const auto& r : readings) {
        o << std::left << std::setw(12) << r.reader.id << " " << std::fixed
          << std::setprecision(4) << std::right << std::setw(8) << r.reader.x << ","
          << std::setw(8) << r.reader.y << "   " << std::setw(7) << r.reader.halfX << ","
          << std::setw(7) << r.reader.halfY << "    ";
        if (r.tags.empty()) o << "(none)";
        for (size_t i = 0; i < r.tags.size(); i++) o << (i ? " " : "") << r.tags[i];
        o << "\n";
    }
}

std::string CObservationRFIDReaders::exportTxtHeader() const {
    return "[READER_ID  X  Y  HALF_X  HALF_Y  N_TAGS  TAG_IDS...]";
}

std::string CObservationRFIDReaders::exportTxtDataRow() const {
    // One line per observation: reader blocks separated by " | ".
    std::ostringstream s;
    s << std::setprecision(9);
    for (size_t k = 0; k < readings.size(); k++) {
        const auto& r = readings[k];
        s << (k ? " | " : "") << r.reader.id << " " << r.reader.x << " " << r.reader.y
          << " " << r.reader.halfX << " " << r.reader.halfY << " " << r.tags.size();
        for (const auto& t : r.tags) s << " " << t;
    }
    return s.str();
}
