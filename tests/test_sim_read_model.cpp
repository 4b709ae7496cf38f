// The simulator decides with the estimators' own models: a tag is read exactly
// when the read model puts it inside the reader's rectangle, i.e. where the
// step likelihood is 1; an IR voltage is the localizer's eq. 5.3 curve.
#include <rfir/ir/sensor_model.h>
#include <rfir/models/detection_likelihood.h>
#include <rfir/obs/ir_voltage_curve.h>
#include <rfir/sim/simulator.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace rfir::sim;
using rfir::common::TMapEntry;

namespace {
template <class T>
std::shared_ptr<T> find(const TSimStep& s) {
    for (const auto& o : s.obs)
        if (auto p = std::dynamic_pointer_cast<T>(o)) return p;
    return nullptr;
}

/** Every (poll, reader, tag): read iff the step likelihood at the true pose is
 * 1. Returns the number of reads. */
size_t checkReadsAgreeWithLikelihood(const TSimOutput& out) {
    const rfir::models::DetectionLikelihood det;
    size_t reads = 0;
    for (const auto& s : out.steps) {
        const auto o = find<rfir::obs::CObservationRFIDReaders>(s);
        if (!o) continue;
        const auto pose = s.truePose.asTPose();
        for (const auto& rd : o->readings) {
            const rfir::models::ReaderArea a{rd.reader.x, rd.reader.y, rd.reader.halfX,
                                             rd.reader.halfY};
            for (const auto& t : out.gtMap) {
                if (t.kind != TMapEntry::Kind::Tag) continue;
                const bool read =
                    std::find(rd.tags.begin(), rd.tags.end(), t.id) != rd.tags.end();
                const bool inside = det.logLikelihood(pose, a, {t.x, t.y}) == 0.0;
                EXPECT_EQ(read, inside) << "t=" << s.t << " " << t.id;
                reads += read;
            }
        }
    }
    return reads;
}
}  // namespace

TEST(SimReadModel, ReadsAreTheLikelihoodsRectangle60mm) {
    TSimConfig c;
    c.maxDuration = 30;
    EXPECT_GT(checkReadsAgreeWithLikelihood(simulate(c, 2)), 100u);
}

TEST(SimReadModel, ReadsAreTheLikelihoodsRectangle300mmSpinning) {
    TSimConfig c;
    for (auto& r : c.readers) r.halfX = r.halfY = 0.15;
    c.rfid.density = 4;
    c.trajectory.kind = TTrajectoryConfig::Kind::Random;
    c.trajectory.rotation = TTrajectoryConfig::Rotation::Spin;
    c.trajectory.spinRate = 0.4;
    c.maxDuration = 30;
    EXPECT_GT(checkReadsAgreeWithLikelihood(simulate(c, 3)), 200u);
}

TEST(SimReadModel, VoltageIsTheLocalizersCurve) {
    TSimConfig c =
        loadSimConfig(std::string(RFIR_SOURCE_DIR) + "/config_ini/sim_ir_loop.ini");
    c.maxDuration = 60;
    c.ir.voltSigma = 0;
    c.ir.heightSpread = 0.1;
    c.ir.failed.clear();  // the nearest emitter is then the one seen
    const auto out = simulate(c, 8);
    rfir::ir::TVoltageCurve curve;  // as the localizer's INI sets it for heights
    curve.heightModel = rfir::ir::TVoltageCurve::HeightModel::InverseSquare;
    curve.fitHeight = c.ir.referenceHeight;
    size_t n = 0;
    for (const auto& s : out.steps) {
        const auto o = find<rfir::obs::CObservationIRSignals>(s);
        if (!o) continue;
        for (const auto& rd : o->readings) {
            if (rd.codes.empty()) continue;
            // The emitter seen is the nearest one (the lattice keeps one in view).
            const auto q = rfir::ir::receiverInWorld(s.truePose.asTPose(), rd.receiver);
            const TMapEntry* best = nullptr;
            double bestD = 1e9;
            for (const auto& e : out.gtMap) {
                if (e.kind != TMapEntry::Kind::Emitter) continue;
                const double d = std::hypot(e.x - q.x, e.y - q.y);
                if (d < bestD) best = &e, bestD = d;
            }
            ASSERT_NE(best, nullptr);
            // Bit for bit: the same function, not merely the same formula.
            EXPECT_EQ(rd.volts, curve.expected(bestD, best->z - rd.receiver.z));
            n++;
        }
    }
    EXPECT_GT(n, 100u);
}
