/* rfir-sim: sensor models. */
#include <rfir/models/range_bearing.h>
#include <rfir/models/read_model.h>
#include <rfir/obs/ir_decoder.h>
#include <cstddef>  // ir_decoder.h uses size_t

#include "world.h"

#include <algorithm>
#include <cmath>

namespace rfir::sim::detail {
rfir::obs::CObservationRFIDReaders::Ptr senseRFID(const TSimConfig& cfg, const TWorld& w,
                                                  const mrpt::poses::CPose2D& robot,
                                                  rfir::sim::TSimRandom& rng) {
    auto o = rfir::obs::CObservationRFIDReaders::Create();
    o->sensorLabel = "RFID";
    double reach = 0;
    for (const auto& r : cfg.readers)
        reach = std::max(reach, std::hypot(r.x, r.y) + std::hypot(r.halfX, r.halfY));
    std::vector<size_t> near;
    w.tagsNear(robot.x(), robot.y(), reach, near);
    std::sort(near.begin(), near.end());
    const mrpt::math::TPose2D pose = robot.asTPose();
    const double c = std::cos(pose.phi), s = std::sin(pose.phi);
    for (const auto& r : cfg.readers) {
        rfir::obs::CObservationRFIDReaders::TReading rd;
        rd.reader = r;
        for (size_t k : near) {
            // The likelihood's read model (SPEC 2: e), read inside its rectangle.
            const auto e =
                rfir::models::readModel(pose, c, s, r.x, r.y, {w.tags[k].x, w.tags[k].y});
            if (std::abs(e.x) >= r.halfX || std::abs(e.y) >= r.halfY) continue;
            // Draw only when misses are on, so that p = 0 leaves the stream alone.
            if (cfg.rfid.missProbability > 0 &&
                rng.drawUniform(0.0, 1.0) < cfg.rfid.missProbability)
                continue;
            rd.tags.push_back(w.tags[k].id);
        }
        o->readings.push_back(rd);
    }
    return o;
}

double modelVoltage(const TIRConfig& ir, double d, double h) {
    // The localizer's curve (eq. 5.3), inverse-square in the height.
    rfir::ir::TVoltageCurve curve;
    curve.fitHeight = ir.referenceHeight;
    curve.maxDistance = ir.visibleRadius;
    curve.heightModel = rfir::ir::TVoltageCurve::HeightModel::InverseSquare;
    return curve.expected(d, h);
}

rfir::obs::CObservationIRSignals::Ptr senseIR(const TSimConfig& cfg, const TWorld& w,
                                              const mrpt::poses::CPose2D& robot,
                                              rfir::sim::TSimRandom& rng) {
    const auto& ir = cfg.ir;
    auto o = rfir::obs::CObservationIRSignals::Create();
    o->sensorLabel = "IR";
    // Decoded output: receivers that see nothing (no code, 0 V) come after the
    // others, in receiver order, which is where the import of a text log puts
    // the declared receivers that have no `ir` record (docs/import.md).
    std::vector<rfir::obs::CObservationIRSignals::TReading> dark;
    for (const auto& rx : cfg.receivers) {
        rfir::obs::CObservationIRSignals::TReading rd;
        rd.receiver = rx;
        const auto p = robot + mrpt::poses::CPose2D(rx.x, rx.y, 0);
        // The nearest working emitter within the visible radius (the lattice
        // keeps two emitters from being in view at once with the seed's values).
        int best = -1;
        double bestD = ir.visibleRadius;
        for (size_t i = 0; i < w.emitters.size(); i++) {
            if (w.emitterFailed[i]) continue;
            const double d = std::hypot(w.emitters[i].x - p.x(), w.emitters[i].y - p.y());
            if (d <= bestD) best = int(i), bestD = d;
        }
        if (best >= 0) {
            const auto& e = w.emitters[best];
            rd.codes = e.codes;
            rd.volts =
                modelVoltage(ir, bestD, e.z - rx.z) + rng.drawGaussian1D(0, ir.voltSigma);
        }
        if (ir.output == TIRConfig::Output::Raw) {
            std::vector<double> phases(rd.codes.size());
            for (auto& ph : phases) ph = rng.drawUniform(0.0, 1.0);
            rd.raw = rfir::ir::synthesizeIRWindow(rd.codes, rd.volts, ir.rawOffset,
                                                  ir.rateHz, size_t(ir.samples), phases);
            for (auto& v : rd.raw) v += float(rng.drawGaussian1D(0, ir.rawNoiseSigma));
            rd.rateHz = ir.rateHz;
            // The window is kept with what the FFT decoder finds in it (with its
            // default parameters), exactly as the import of `ir_raw` stores it:
            // the true codes and voltage are not in the rawlog.
            const auto dec = rfir::ir::decodeIRWindow(rd.raw, rd.rateHz);
            rd.codes = dec.codes;
            rd.volts = dec.volts;
        } else if (rd.codes.empty()) {
            dark.push_back(rd);
            continue;
        }
        o->readings.push_back(rd);
    }
    // A textlog cannot say "no receiver saw anything" (no `ir` record at all
    // means no IR reading): such an instant has no IR observation.
    if (o->readings.empty()) return nullptr;
    for (auto& rd : dark) o->readings.push_back(std::move(rd));
    return o;
}

/** A bearing as a float in (-pi, pi], as the import stores a text `rb`
 * bearing: float rounding may push +-pi just outside. */
float floatBearing(double b) {
    float f = float(std::atan2(std::sin(b), std::cos(b)));
    if (!(double(f) > -M_PI && double(f) <= M_PI)) f = std::nextafter(f, 0.f);
    return f;
}

mrpt::obs::CObservationBearingRange::Ptr senseRB(const TSimConfig& cfg, const TWorld& w,
                                                 const mrpt::poses::CPose2D& robot,
                                                 rfir::sim::TSimRandom& rng) {
    const auto& sp = cfg.rbSensor;
    auto o = mrpt::obs::CObservationBearingRange::Create();
    o->sensorLabel = "RB";
    o->sensorLocationOnRobot = mrpt::poses::CPose3D(sp.x, sp.y, 0, sp.yaw, 0, 0);
    o->minSensorDistance = 0;
    o->maxSensorDistance = float(sp.maxRange);
    o->fieldOfView_yaw = float(sp.fov);
    o->fieldOfView_pitch = 0;
    // The noise fields (sensor_std_*, covariances) keep MRPT's defaults, as in
    // an imported text log, which cannot carry them: SLAM takes the noise from
    // its INI (rb_std_range, rb_std_bearing, equal to [range_bearing]'s defaults).
    const auto sensor = robot + mrpt::poses::CPose2D(sp.x, sp.y, sp.yaw);
    for (size_t i = 0; i < w.landmarks.size(); i++) {
        const auto h = rfir::models::rangeBearingModel(
            sensor.asTPose(), {w.landmarks[i].x, w.landmarks[i].y});
        const double r = h.range;
        const double b = std::atan2(std::sin(h.bearing), std::cos(h.bearing));
        if (r > sp.maxRange || std::abs(b) > 0.5 * sp.fov) continue;
        mrpt::obs::CObservationBearingRange::TMeasurement m;
        m.range = float(r + rng.drawGaussian1D(0, cfg.rb.sigmaRange));
        m.yaw = floatBearing(b + rng.drawGaussian1D(0, cfg.rb.sigmaBearing));
        // A sensor reports no range <= 0 (a landmark within the noise of the
        // sensor's centre); the text format has none either.
        if (!(m.range > 0)) continue;
        m.pitch = 0;
        // The landmark's index in the map; simulate() renumbers them in order of
        // first observation.
        m.landmarkID = int32_t(i);
        m.covariance.setZero();
        o->sensedData.push_back(m);
    }
    // An empty observation has no textlog form (it would have no `rb` record).
    if (o->sensedData.empty()) return nullptr;
    return o;
}

}  // namespace rfir::sim::detail
