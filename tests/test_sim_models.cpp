// The simulator's sensor models checked against its ground truth: every RFID
// detection inside its reader's square, range-bearing within range and FOV with
// the configured noise, IR voltages following eq. 5.3.
#include <rfir/obs/ir_codes.h>
#include <rfir/obs/ir_decoder.h>
#include <rfir/obs/ir_lattice.h>
#include <rfir/sim/simulator.h>
#include <cstddef>  // before ir_decoder.h, which uses size_t

#include <gtest/gtest.h>
#include <mrpt/obs/CObservationBearingRange.h>

#include <cmath>
#include <iostream>
#include <map>

using namespace rfir::sim;
using mrpt::poses::CPose2D;
using rfir::common::TMapEntry;

namespace {
template <class T>
std::shared_ptr<T> find(const TSimStep& s) {
    for (const auto& o : s.obs)
        if (auto p = std::dynamic_pointer_cast<T>(o)) return p;
    return nullptr;
}

std::map<std::string, TMapEntry> byId(const TSimOutput& out, TMapEntry::Kind k) {
    std::map<std::string, TMapEntry> m;
    for (const auto& e : out.gtMap)
        if (e.kind == k) m[e.id] = e;
    return m;
}

/** Tag position minus reader centre, in the robot frame (the read model's e). */
std::pair<double, double> offset(const CPose2D& p, const rfir::obs::TRFIDReader& r,
                                 const TMapEntry& t) {
    const double dx = t.x - p.x(), dy = t.y - p.y(), c = cos(p.phi()), s = sin(p.phi());
    return {c * dx + s * dy - r.x, -s * dx + c * dy - r.y};
}

/** Checks every detection against the true pose and map, and that every tag
 * clearly inside a square was read; returns the number of detections. */
size_t checkRFID(const TSimOutput& out) {
    const auto tags = byId(out, TMapEntry::Kind::Tag);
    size_t n = 0, polls = 0;
    for (const auto& s : out.steps) {
        auto o = find<rfir::obs::CObservationRFIDReaders>(s);
        if (!o) continue;
        polls++;
        for (const auto& rd : o->readings) {
            for (const auto& id : rd.tags) {
                const auto it = tags.find(id);
                EXPECT_TRUE(it != tags.end()) << id;
                if (it == tags.end()) continue;
                const auto [ex, ey] = offset(s.truePose, rd.reader, it->second);
                EXPECT_LT(std::abs(ex), rd.reader.halfX) << "t=" << s.t << " " << id;
                EXPECT_LT(std::abs(ey), rd.reader.halfY) << "t=" << s.t << " " << id;
                n++;
            }
            for (const auto& [id, t] : tags) {
                const auto [ex, ey] = offset(s.truePose, rd.reader, t);
                if (std::abs(ex) < rd.reader.halfX - 1e-6 &&
                    std::abs(ey) < rd.reader.halfY - 1e-6) {
                    EXPECT_NE(std::find(rd.tags.begin(), rd.tags.end(), id),
                              rd.tags.end())
                        << "missed " << id << " at t=" << s.t;
                }
            }
        }
    }
    EXPECT_EQ(polls, out.steps.size());
    return n;
}
}  // namespace

TEST(SimRFID, CarpetDensityAndPlacement) {
    for (double density : {4.0, 16.0, 100.0}) {
        TSimConfig c;
        c.rfid.density = density;
        c.rfid.placementSigma = 0.004;
        c.maxDuration = 1;
        const auto out = simulate(c, 5);
        const auto tags = byId(out, TMapEntry::Kind::Tag);
        EXPECT_EQ(double(tags.size()), density * 16) << density;  // 4 x 4 m area
        // Offsets from the nearest grid node: their spread is the placement error.
        const double pitch = 1 / std::sqrt(density);
        double s2 = 0;
        for (const auto& [id, t] : tags) {
            EXPECT_EQ(id.size(), 16u);
            EXPECT_EQ(id.rfind("E0040150", 0), 0u);
            const double ox = t.x - pitch / 2, oy = t.y - pitch / 2;
            const double rx = ox - pitch * std::round(ox / pitch);
            const double ry = oy - pitch * std::round(oy / pitch);
            s2 += rx * rx + ry * ry;
        }
        EXPECT_NEAR(std::sqrt(s2 / (2 * tags.size())), 0.004, 0.0008) << density;
    }
}

TEST(SimRFID, DetectionsOnlyInsideReaderSquares60mm) {
    TSimConfig c;
    c.maxDuration = 70;
    EXPECT_GT(checkRFID(simulate(c, 2)), 200u);
}

TEST(SimRFID, DetectionsOnlyInsideReaderSquares300mmSpinning) {
    TSimConfig c;
    for (auto& r : c.readers) r.halfX = r.halfY = 0.15;
    c.rfid.density = 4;
    c.trajectory.kind = TTrajectoryConfig::Kind::Random;
    c.trajectory.rotation = TTrajectoryConfig::Rotation::Spin;
    c.trajectory.spinRate = 0.4;
    c.maxDuration = 60;
    EXPECT_GT(checkRFID(simulate(c, 3)), 500u);
}

TEST(SimRFID, MissProbability) {
    TSimConfig c;
    c.maxDuration = 90;
    const auto all = simulate(c, 4);
    c.rfid.missProbability = 0.3;
    const auto some = simulate(c, 4);  // same seed: same path and carpet
    size_t nAll = 0, nSome = 0;
    for (size_t k = 0; k < all.steps.size(); k++) {
        nAll += find<rfir::obs::CObservationRFIDReaders>(all.steps[k])->detectionCount();
        nSome +=
            find<rfir::obs::CObservationRFIDReaders>(some.steps[k])->detectionCount();
    }
    ASSERT_GT(nAll, 300u);
    EXPECT_NEAR(double(nSome) / nAll, 0.7, 0.05);
}

TEST(SimRB, WithinRangeAndFovWithConfiguredNoise) {
    for (auto rot :
         {TTrajectoryConfig::Rotation::None, TTrajectoryConfig::Rotation::Follow}) {
        TSimConfig c;
        c.rfid.enabled = false;
        c.rb.enabled = true;
        c.rbSensor.x = 0.1;
        c.trajectory.rotation = rot;
        c.maxDuration = 120;
        const auto out = simulate(c, 6);
        const auto lms = byId(out, TMapEntry::Kind::Landmark);
        // The header names the landmarks observed, in order of first observation.
        const auto& names = out.header.rbLandmarkNames;
        ASSERT_LE(names.size(), lms.size());
        for (const auto& nm : names) EXPECT_TRUE(lms.count(nm)) << nm;
        double sr = 0, sb = 0;
        size_t n = 0, withRB = 0;
        int32_t nextNew = 0;
        for (const auto& s : out.steps) {
            auto o = find<mrpt::obs::CObservationBearingRange>(s);
            if (!o) continue;  // nothing in view: no observation
            withRB++;
            EXPECT_FALSE(o->sensedData.empty());
            EXPECT_EQ(o->sensor_std_range, 0.f);  // the import's defaults
            EXPECT_EQ(o->sensor_std_yaw, 0.f);
            EXPECT_FLOAT_EQ(o->maxSensorDistance, 0.5f);
            for (const auto& m : o->sensedData) {
                ASSERT_LE(m.landmarkID, nextNew);
                if (m.landmarkID == nextNew) nextNew++;
            }
            const auto sensor = s.truePose + CPose2D(0.1, 0, 0);
            for (const auto& m : o->sensedData) {
                const auto& l = lms.at(out.header.landmarkName(m.landmarkID));
                const double r = std::hypot(l.x - sensor.x(), l.y - sensor.y());
                const double b = mrpt::math::wrapToPi(
                    std::atan2(l.y - sensor.y(), l.x - sensor.x()) - sensor.phi());
                EXPECT_LE(r, 0.5);
                EXPECT_LE(std::abs(b), M_PI / 3 + 1e-9);
                sr += (m.range - r) * (m.range - r);
                sb += std::pow(mrpt::math::wrapToPi(m.yaw - b), 2);
                n++;
            }
        }
        ASSERT_GT(n, 500u);
        EXPECT_GT(withRB, out.steps.size() / 2);
        EXPECT_EQ(size_t(nextNew), names.size());
        EXPECT_NEAR(std::sqrt(sr / n), 0.010, 0.0012);
        EXPECT_NEAR(std::sqrt(sb / n), 3 * M_PI / 180, 0.0065);
    }
}

TEST(SimIR, LatticeOfTheThesisRoom) {
    const auto em = rfir::ir::makeEmitterLattice({0, 0, 2.4, 0.8});
    size_t rep = 0, uni = 0;
    for (const auto& e : em) {
        (e.repeated ? rep : uni)++;
        EXPECT_EQ(e.repeated, e.codes.size() == 1);
        EXPECT_DOUBLE_EQ(e.z, 1.5);
        if (!e.repeated) {
            EXPECT_NEAR(std::fmod(e.x, 0.8), 0.4, 1e-9);
        }
        for (const auto& f : em)  // grid neighbours of one type never share a code
        {
            if (&e != &f && e.repeated && f.repeated &&
                std::hypot(e.x - f.x, e.y - f.y) < 0.81) {
                EXPECT_NE(e.id, f.id);
            }
        }
    }
    EXPECT_EQ(rep, 8u);  // thesis 5.4: 8 repeated-ID and 3 unique-ID emitters
    EXPECT_EQ(uni, 3u);
    EXPECT_EQ(em[8].id, "12");
    EXPECT_DOUBLE_EQ(rfir::ir::TVoltageCurve().expected(0, 0), 1.81997);
    EXPECT_NEAR(rfir::ir::TVoltageCurve().expected(0.1, 0), -0.327 + 0.2855 + 1.81997,
                1e-12);
    EXPECT_THROW(rfir::ir::makeEmitterLattice({0, 0, 100, 100}), std::invalid_argument);
}

namespace {
TSimConfig irConfig() {
    TSimConfig c =
        loadSimConfig(std::string(RFIR_SOURCE_DIR) + "/config_ini/sim_ir_loop.ini");
    c.maxDuration = 120;
    return c;
}

/** Per reading: the nearest working emitter to the receiver and its distance. */
struct TNearest {
    const TMapEntry* e = nullptr;
    double d = 1e9;
};
TNearest nearest(const TSimOutput& out, const CPose2D& p,
                 const rfir::obs::TIRReceiver& rx,
                 const std::vector<std::pair<double, double>>& failed = {}) {
    const auto w = p + CPose2D(rx.x, rx.y, 0);
    TNearest n;
    for (const auto& e : out.gtMap) {
        bool off = false;
        for (const auto& [fx, fy] : failed)
            off = off || std::hypot(e.x - fx, e.y - fy) < 1e-6;
        const double d = std::hypot(e.x - w.x(), e.y - w.y());
        if (e.kind == TMapEntry::Kind::Emitter && !off && d < n.d) n = {&e, d};
    }
    return n;
}
}  // namespace

TEST(SimIR, DecodedVoltageFollowsEq53) {
    const auto c = irConfig();
    const auto out = simulate(c, 7);
    ASSERT_EQ(out.spots.size() > 0, true);
    double s1 = 0, s2 = 0;
    size_t n = 0, dark = 0, allDark = 0;
    for (const auto& s : out.steps) {
        auto o = find<rfir::obs::CObservationIRSignals>(s);
        if (!o) {
            // No receiver sees anything: no observation (textlog 1 cannot say so).
            for (const auto& rx : c.receivers)
                EXPECT_GT(nearest(out, s.truePose, rx).d, c.ir.visibleRadius);
            allDark++;
            continue;
        }
        ASSERT_EQ(o->readings.size(), 2u);
        // Receivers that see nothing come last.
        EXPECT_FALSE(o->readings[0].codes.empty());
        for (const auto& rd : o->readings) {
            const auto nn = nearest(out, s.truePose, rd.receiver);
            if (rd.codes.empty()) {
                EXPECT_GT(nn.d, c.ir.visibleRadius);
                dark++;
                continue;
            }
            EXPECT_LE(nn.d, c.ir.visibleRadius);
            EXPECT_EQ(rd.emitterId(), nn.e->id);
            const double r = rd.volts - rfir::ir::TVoltageCurve().expected(nn.d, 0);
            s1 += r, s2 += r * r, n++;
        }
    }
    ASSERT_GT(n, 500u);
    EXPECT_GT(dark, 100u);
    std::cout << "IR instants with one receiver dark " << dark << ", with both "
              << allDark << " of " << out.steps.size() << "\n";
    EXPECT_NEAR(s1 / n, 0, 0.006);
    EXPECT_NEAR(std::sqrt(s2 / n), c.ir.voltSigma, 0.004);
}

TEST(SimIR, FailedEmittersNeverSeenAndHeightsScaleVoltage) {
    auto c = irConfig();
    c.ir.failed = {"0.8 0.8", "2.4 0.8"};
    c.ir.heightSpread = 0.1;
    c.ir.voltSigma = 0;
    const auto out = simulate(c, 8);
    EXPECT_EQ(out.failedEmitters.size(), 2u);
    const std::vector<std::pair<double, double>> failed{{0.8, 0.8}, {2.4, 0.8}};
    size_t n = 0;
    for (const auto& s : out.steps) {
        const auto o = find<rfir::obs::CObservationIRSignals>(s);
        if (!o) continue;  // nothing in view
        for (const auto& rd : o->readings) {
            if (rd.codes.empty()) continue;
            const auto nn = nearest(out, s.truePose, rd.receiver, failed);
            ASSERT_EQ(rd.emitterId(), nn.e->id);
            const double h = nn.e->z - rd.receiver.z;
            EXPECT_GE(h, 1.1 - 1e-9);
            EXPECT_LE(h, 1.3 + 1e-9);
            EXPECT_NEAR(
                rd.volts,
                rfir::ir::TVoltageCurve().expected(nn.d, 0) * std::pow(1.2 / h, 2), 1e-9);
            n++;
        }
    }
    EXPECT_GT(n, 300u);
}

TEST(SimIR, RawWindowsDecodeToTheEmitter) {
    auto c = irConfig();
    c.ir.output = TIRConfig::Output::Raw;
    c.maxDuration = 25;
    const auto out = simulate(c, 9);
    size_t seen = 0;
    double s2 = 0;
    for (const auto& s : out.steps) {
        const auto o = find<rfir::obs::CObservationIRSignals>(s);
        ASSERT_TRUE(o);  // raw windows: every receiver, every period
        ASSERT_EQ(o->readings.size(), 2u);
        for (const auto& rd : o->readings) {
            ASSERT_TRUE(rd.hasRaw());
            ASSERT_EQ(rd.raw.size(), 800u);
            const auto dec = rfir::ir::decodeIRWindow(rd.raw, rd.rateHz);
            // Stored with its decoding, as the import of `ir_raw` stores it.
            EXPECT_EQ(rd.codes, dec.codes);
            EXPECT_EQ(rd.volts, dec.volts);
            const auto nn = nearest(out, s.truePose, rd.receiver);
            // Near the visible edge the voltage drops to the noise: only check
            // readings with a clear signal.
            const double v = rfir::ir::TVoltageCurve().expected(nn.d, 0);
            if (nn.d > c.ir.visibleRadius) {
                EXPECT_TRUE(dec.codes.empty()) << s.t;
            }
            if (nn.d > c.ir.visibleRadius || v < 0.5) continue;
            EXPECT_EQ(rfir::ir::emitterIdFromCodes(dec.codes), nn.e->id) << s.t;
            s2 += (dec.volts - v) * (dec.volts - v);
            seen++;
        }
    }
    ASSERT_GT(seen, 30u);
    EXPECT_LT(std::sqrt(s2 / seen), 0.1);
}
