/* rfir: IR receivers observation. */
#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/ir_codes.h>
#include <rfir/obs/registerAllClasses.h>

#include <mrpt/serialization/CArchive.h>

#include <iomanip>
#include <sstream>
#include <stdexcept>

using namespace rfir::obs;

IMPLEMENTS_SERIALIZABLE(CObservationIRSignals, mrpt::obs::CObservation, rfir::obs)
RFIR_REGISTER_CLASS(CObservationIRSignals, rfir::obs::CObservationIRSignals)

std::string CObservationIRSignals::TReading::emitterId() const {
    return codes.empty() ? std::string() : rfir::ir::emitterIdFromCodes(codes);
}

uint8_t CObservationIRSignals::serializeGetVersion() const {
    return 0;
}

void CObservationIRSignals::serializeTo(mrpt::serialization::CArchive& out) const {
    out << timestamp << sensorLabel;
    out.WriteAs<uint32_t>(readings.size());
    for (const auto& r : readings) {
        out << r.receiver.id << r.receiver.x << r.receiver.y << r.receiver.z;
        out.WriteAs<uint32_t>(r.codes.size());
        for (auto c : r.codes) out << c;
        out << r.volts << r.rateHz;
        out.WriteAs<uint32_t>(r.raw.size());
        if (!r.raw.empty()) out.WriteBufferFixEndianness(r.raw.data(), r.raw.size());
    }
}

void CObservationIRSignals::serializeFrom(mrpt::serialization::CArchive& in,
                                          uint8_t version) {
    switch (version) {
        case 0: {
            using B = TReadBounds;
            constexpr const char* kWhat = "CObservationIRSignals";
            in >> timestamp;
            sensorLabel = readBoundedString(in, kWhat);
            // On disk a reading takes at least an empty id, 5 doubles, 2 counts.
            readings.resize(readBoundedCount(in, kWhat, B::kMaxSensors, 4 + 40 + 8));
            for (auto& r : readings) {
                r.receiver.id = readBoundedString(in, kWhat);
                in >> r.receiver.x >> r.receiver.y >> r.receiver.z;
                requireFinite(kWhat, "receiver x y z",
                              {r.receiver.x, r.receiver.y, r.receiver.z});
                r.codes.resize(readBoundedCount(in, kWhat, B::kMaxCodesPerReading, 1));
                for (auto& c : r.codes) in >> c;
                in >> r.volts >> r.rateHz;
                requireFinite(kWhat, "volts and rate", {r.volts, r.rateHz});
                r.raw.resize(
                    readBoundedCount(in, kWhat, B::kMaxRawSamples, sizeof(float)));
                // ReadBuffer only throws when nothing at all is read.
                if (!r.raw.empty() &&
                    in.ReadBufferFixEndianness(r.raw.data(), r.raw.size()) !=
                        r.raw.size() * sizeof(float))
                    throw std::runtime_error(std::string(kWhat) +
                                             ": raw window cut short");
                for (const float v : r.raw) requireFinite(kWhat, "a raw sample", {v});
            }
        } break;
        default:
            MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
    }
}

void CObservationIRSignals::getDescriptionAsText(std::ostream& o) const {
    CObservation::getDescriptionAsText(o);
    o << "IR receivers observation: " << readings.size() << " receiver(s)\n";
    o << "receiver     position x,y,z [m]            codes (kHz)                 emitter "
         " volts\n";
    for (const auto& r : readings) {
        o << std::left << std::setw(12) << r.receiver.id << " " << std::right
          << std::fixed << std::setprecision(3) << std::setw(7) << r.receiver.x << ","
          << std::setw(7) << r.receiver.y << "," << std::setw(7) << r.receiver.z << "   ";
        std::ostringstream cs;
        if (r.codes.empty()) cs << "(no emitter)";
        for (size_t i = 0; i < r.codes.size(); i++)
            cs << (i ? " " : "") << int(r.codes[i]) << "(" << std::setprecision(2)
               << std::fixed << rfir::ir::codeFrequencyHz(r.codes[i]) / 1000.0 << ")";
        o << std::left << std::setw(28) << cs.str() << std::setw(8)
          << (r.codes.empty() ? "-" : r.emitterId()) << " " << std::setprecision(4)
          << r.volts << std::right << "\n";
        if (r.hasRaw())
            o << "    raw window: " << r.raw.size() << " samples at "
              << std::setprecision(1) << r.rateHz << " Hz (" << std::setprecision(4)
              << r.raw.size() / r.rateHz << " s)\n";
    }
}

std::string CObservationIRSignals::exportTxtHeader() const {
    return "[RECEIVER_ID  X  Y  Z  CODES  VOLTS]";
}

std::string CObservationIRSignals::exportTxtDataRow() const {
    std::ostringstream s;
    s << std::setprecision(9);
    for (size_t k = 0; k < readings.size(); k++) {
        const auto& r = readings[k];
        s << (k ? " | " : "") << r.receiver.id << " " << r.receiver.x << " "
          << r.receiver.y << " " << r.receiver.z << " "
          << (r.codes.empty() ? "-" : rfir::ir::formatCodeList(r.codes)) << " "
          << r.volts;
    }
    return s.str();
}
