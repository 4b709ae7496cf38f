// Helpers of the import tests: temporary folders, files, rawlog comparison and
// random (simulator-like) rawlog content.
#pragma once

#include <rfir/common/log_convert.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/obs/ir_decoder.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/serialization/CArchive.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace rfir_test {
inline const std::string kFull =
    std::string(RFIR_SOURCE_DIR) + "/tests/data/textlog/full.txt";

inline std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

inline std::string gunzip(const std::string& path) {
    mrpt::io::CFileGZInputStream f(path);
    std::string out;
    char buf[65536];
    for (size_t n; (n = f.Read(buf, sizeof(buf))) > 0;) out.append(buf, n);
    return out;
}

/** "" if both rawlogs hold the same objects, byte for byte; else where not. */
inline std::string compareRawlogs(const std::string& a, const std::string& b) {
    using rfir::common::sameSerialization;
    rfir::common::CRawlogReader ra(a), rb(b);
    if (!sameSerialization(ra.header(), rb.header())) return "headers differ";
    rfir::common::TRawlogStep sa, sb;
    for (size_t i = 0;; i++) {
        const bool ha = ra.next(sa), hb = rb.next(sb);
        if (ha != hb) return "different number of instants (" + std::to_string(i) + ")";
        if (!ha) return "";
        const std::string at = "instant " + std::to_string(i) + ": ";
        if (!sameSerialization(*sa.action, *sb.action)) return at + "actions differ";
        if (sa.sf->size() != sb.sf->size()) return at + "observation counts differ";
        for (size_t k = 0; k < sa.sf->size(); k++)
            if (!sameSerialization(*sa.sf->getObservationByIndex(k),
                                   *sb.sf->getObservationByIndex(k)))
                return at + "observation " + std::to_string(k) + " (" +
                       sa.sf->getObservationByIndex(k)->GetRuntimeClass()->className +
                       ") differs";
    }
}

/** A header with full-precision values; 5 landmark names used in order. */
inline rfir::obs::CObservationLogHeader randomHeader(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-1, 1), s(0.01, 0.2);
    rfir::obs::CObservationLogHeader h;
    for (int i = 0; i < 8; i++)
        h.readers.push_back({"R" + std::to_string(i), u(rng), u(rng), s(rng), s(rng)});
    h.receivers = {{"left", u(rng), u(rng), 0.3 + s(rng)},
                   {"right", u(rng), u(rng), 0.4}};
    h.rbSensor =
        rfir::obs::TRBSensor{u(rng), u(rng), 3 * u(rng), 0.5 + s(rng), 2 + u(rng)};
    h.startPose = rfir::common::exactPose(u(rng), u(rng), 3 * u(rng));
    for (int i = 0; i < 5; i++) h.rbLandmarkNames.push_back("LM" + std::to_string(i));
    h.timestamp = mrpt::Clock::fromDouble(0);  // what the import will rebuild
    return h;
}

/** Observations of instant k, as a simulator would make them (ir_raw
 * readings carry their own decoding, as the import computes it). */
inline void randomInstant(std::mt19937& rng, const rfir::obs::CObservationLogHeader& h,
                          int k, std::vector<mrpt::obs::CObservation::Ptr>& obs) {
    using namespace rfir::obs;
    std::uniform_real_distribution<double> u(0, 1);
    auto rf = CObservationRFIDReaders::Create();
    rf->sensorLabel = "RFID";
    for (const auto& r : h.readers) {
        if (u(rng) < 0.5) continue;
        std::vector<std::string> tags;
        for (int n = int(3 * u(rng)); n > 0; n--)
            tags.push_back("E004" + std::to_string(int(1e6 * u(rng))));
        rf->readings.push_back({r, tags});
    }
    if (!rf->readings.empty()) obs.push_back(rf);
    auto ir = CObservationIRSignals::Create();
    ir->sensorLabel = "IR";
    for (const auto& rc : h.receivers) {
        CObservationIRSignals::TReading rd;
        rd.receiver = rc;
        std::vector<uint8_t> codes;
        for (uint8_t c = 1; c <= 9; c++)
            if (u(rng) < 0.25) codes.push_back(c);
        if (codes.empty()) codes.push_back(uint8_t(1 + k % 9));
        if (k % 2) {
            rd.codes = codes;
            rd.volts = 2 * u(rng);
        } else {
            rd.rateHz = 4000 + 1000 * u(rng);
            rd.raw = rfir::ir::synthesizeIRWindow(codes, 1 + u(rng), 0.3, rd.rateHz, 600,
                                                  {u(rng), u(rng), u(rng), u(rng)});
            for (auto& v : rd.raw) v += float(0.02 * (u(rng) - 0.5));
            const auto dec = rfir::ir::decodeIRWindow(rd.raw, rd.rateHz);
            rd.codes = dec.codes;
            rd.volts = dec.volts;
        }
        ir->readings.push_back(rd);
    }
    obs.push_back(ir);
    if (k % 3 && k >= 5) return;
    auto rb = mrpt::obs::CObservationBearingRange::Create();
    rb->sensorLabel = "RB";
    const auto& s = *h.rbSensor;
    rb->sensorLocationOnRobot = mrpt::poses::CPose3D(s.x, s.y, 0, s.yaw, 0, 0);
    rb->maxSensorDistance = float(s.maxRange);
    rb->fieldOfView_yaw = float(s.fov);
    rb->fieldOfView_pitch = 0;
    // Landmarks LM0..LM4 first appear at instants 0..4, in that order; MRPT
    // allows one measurement per landmark and observation.
    std::vector<int32_t> ids;
    for (int32_t i = 0; i < std::min(k, 5); i++) ids.push_back(i);
    std::shuffle(ids.begin(), ids.end(), rng);
    if (k < 5) ids.insert(ids.begin(), k);
    ids.resize(std::min<size_t>(ids.size(), 3));
    for (int32_t id : ids) {
        mrpt::obs::CObservationBearingRange::TMeasurement m;
        m.landmarkID = id;
        m.range = float(0.5 * u(rng) + 1e-3);
        m.yaw = float(M_PI * (2 * u(rng) - 1));
        m.pitch = 0;
        m.covariance.setZero();
        rb->sensedData.push_back(m);
    }
    obs.push_back(rb);
}

}  // namespace rfir_test
