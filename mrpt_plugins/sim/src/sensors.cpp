/* rfir-sim: sensor models. */
#include <rfir/models/range_bearing.h>
#include <rfir/models/read_model.h>
#include <rfir/obs/ir_codes.h>
#include <rfir/obs/ir_decoder.h>
#include <cstddef>  // ir_decoder.h uses size_t

#include "world.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace rfir::sim::detail {
std::string faultNumber(double v) {
    // The shortest of 15-17 digits that reads back as v: a record's time is
    // then the log's time exactly.
    for (int p = 15;; p++) {
        std::ostringstream o;
        o << std::setprecision(p) << v;
        if (p == 17 || std::stod(o.str()) == v) return o.str();
    }
}

namespace {
bool deadAt(const TSimConfig& cfg, size_t reader, double elapsed) {
    for (const auto& d : cfg.rfid.deadReaders)
        if (d.reader == reader && elapsed >= d.from && elapsed < d.to) return true;
    return false;
}

/** A ghost read: one real tag, not read by this reader now, whose centre lies
 * within the configured distances of the reader's centre (world frame). */
void addGhost(const TSimConfig& cfg, const TWorld& w, const mrpt::math::TPose2D& pose,
              rfir::obs::CObservationRFIDReaders::TReading& rd, const TFaultContext& f) {
    const auto centre = rfir::models::robotFrameToWorld(
        pose, std::cos(pose.phi), std::sin(pose.phi), rd.reader.x, rd.reader.y);
    const double rx = centre.x, ry = centre.y;
    const double lo = cfg.rfid.ghostMinDistance, hi = cfg.rfid.ghostMaxDistance;
    std::vector<size_t> near, cand;
    w.tagsNear(rx, ry, hi, near);
    std::sort(near.begin(), near.end());
    for (size_t k : near) {
        const double d = std::hypot(w.tags[k].x - rx, w.tags[k].y - ry);
        if (d < lo || d > hi) continue;
        if (std::find(rd.tags.begin(), rd.tags.end(), w.tags[k].id) != rd.tags.end())
            continue;
        cand.push_back(k);
    }
    // No tag at that distance (an empty corner): no ghost, and no record.
    if (cand.empty()) return;
    const auto& t = w.tags[cand[f.rng->drawUniform32bit() % cand.size()]];
    rd.tags.push_back(t.id);
    f.log->push_back("ghost " + faultNumber(f.t) + " " + rd.reader.id + " " + t.id + " " +
                     faultNumber(std::hypot(t.x - rx, t.y - ry)));
}
}  // namespace

rfir::obs::CObservationRFIDReaders::Ptr senseRFID(const TSimConfig& cfg, const TWorld& w,
                                                  const mrpt::poses::CPose2D& robot,
                                                  rfir::sim::TSimRandom& rng,
                                                  const std::vector<size_t>& which,
                                                  const TFaultContext& f) {
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
    for (size_t i = 0; i < cfg.readers.size(); i++) {
        if (!which.empty() && std::find(which.begin(), which.end(), i) == which.end())
            continue;
        const auto& r = cfg.readers[i];
        rfir::obs::CObservationRFIDReaders::TReading rd;
        rd.reader = r;
        const bool dead = deadAt(cfg, i, f.elapsed);
        for (size_t k : near) {
            if (dead) break;  // polled, answers nothing
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
        if (!dead && cfg.rfid.ghostRate > 0 &&
            f.rng->drawUniform(0.0, 1.0) < cfg.rfid.ghostRate)
            addGhost(cfg, w, pose, rd, f);
        if (rd.tags.empty() && !cfg.rfid.writeEmptyPolls) continue;
        o->readings.push_back(rd);
    }
    // A text log has no record for "polled, nothing written".
    if (o->readings.empty()) return nullptr;
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

namespace {
/** Wrong codes (another emitter's ID, or one code misread) and voltage
 * outliers on a reading of an emitter in view. */
void applyIRFaults(const TIRConfig& ir, const TWorld& w,
                   rfir::obs::CObservationIRSignals::TReading& rd,
                   const TFaultContext& f) {
    auto& rng = *f.rng;
    const std::string at = faultNumber(f.t) + " " + rd.receiver.id + " ";
    if (ir.wrongCodeRate > 0 && rng.drawUniform(0.0, 1.0) < ir.wrongCodeRate) {
        const auto truth = rd.codes;
        std::vector<size_t> others;
        for (size_t j = 0; j < w.emitters.size(); j++)
            if (w.emitters[j].codes != truth) others.push_back(j);
        std::vector<uint8_t> free;
        for (uint8_t c = 1; c <= 9; c++)
            if (std::find(truth.begin(), truth.end(), c) == truth.end())
                free.push_back(c);
        // Another emitter's ID, or one code misread; whichever exists when
        // the other cannot (one ID only, or all nine codes sent).
        const bool other = rng.drawUniform(0.0, 1.0) < ir.wrongCodeOtherId;
        if (!others.empty() && (other || free.empty()))
            rd.codes = w.emitters[others[rng.drawUniform32bit() % others.size()]].codes;
        else if (!free.empty()) {
            rd.codes[rng.drawUniform32bit() % rd.codes.size()] =
                free[rng.drawUniform32bit() % free.size()];
            std::sort(rd.codes.begin(), rd.codes.end());
        }
        if (rd.codes != truth)  // else nothing else to spell
            f.log->push_back("wrong_code " + at + rfir::ir::emitterIdFromCodes(truth) +
                             " " + rfir::ir::emitterIdFromCodes(rd.codes));
    }
    if (ir.voltOutlierRate > 0 && rng.drawUniform(0.0, 1.0) < ir.voltOutlierRate) {
        const double v = rng.drawUniform(0.0, ir.voltOutlierMax);
        f.log->push_back("volt_outlier " + at + faultNumber(rd.volts) + " " +
                         faultNumber(v));
        rd.volts = v;
    }
}
}  // namespace

rfir::obs::CObservationIRSignals::Ptr senseIR(const TSimConfig& cfg, const TWorld& w,
                                              const mrpt::poses::CPose2D& robot,
                                              rfir::sim::TSimRandom& rng,
                                              const TFaultContext& f) {
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
        // keeps two emitters from being in view at once with the thesis' values).
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
            if (f.rng) applyIRFaults(ir, w, rd, f);
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
    const auto sensor =
        rfir::models::sensorPoseInWorld(robot.asTPose(), {sp.x, sp.y, sp.yaw});
    for (size_t i = 0; i < w.landmarks.size(); i++) {
        const auto h =
            rfir::models::rangeBearingModel(sensor, {w.landmarks[i].x, w.landmarks[i].y});
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
