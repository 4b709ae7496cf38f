/* rfir: Monte Carlo localization on the IR emitter map (thesis Algorithm 3). */
#include <rfir/ir/ir_localizer.h>
#include <rfir/models/read_model.h>
#include <rfir/models/robot_resampling.h>
#include <rfir/obs/ir_codes.h>
#include <rfir/obs/ir_decoder.h>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>

namespace rfir::ir {
using rfir::obs::CObservationIRSignals;

mrpt::math::CMatrixDouble33 TMotionNoise::covariance(
    const mrpt::poses::CPose2D& in) const {
    const double d = std::hypot(in.x(), in.y()), a = std::abs(in.phi());
    const double vxy =
        kXY * kXY * d + (scaleSigma * d) * (scaleSigma * d) + minStdXY * minStdXY;
    const double vphi = kPhiRot * kPhiRot * a + kPhiXY * kPhiXY * d +
                        (rotScaleSigma * a) * (rotScaleSigma * a) +
                        (headingDrift * d) * (headingDrift * d) + minStdPhi * minStdPhi;
    mrpt::math::CMatrixDouble33 c;
    c.setZero();
    c(0, 0) = c(1, 1) = vxy;
    c(2, 2) = vphi;
    return c;
}

CIRLocalizer::CIRLocalizer(std::shared_ptr<rfir::maps::CIREmitterMap> map,
                           const TLocalizerParams& p, uint64_t seed)
    : m_map(std::move(map)),
      m_params(p),
      m_pdf(p.numParticles, m_rng, m_step),
      m_monitor(p.robust, m_map ? m_map->emitters().emitters().size() : 0) {
    if (!m_map || m_map->isEmpty())
        throw std::invalid_argument("CIRLocalizer: the emitter map is empty");
    m_step.map = m_map.get();
    // The run's one generator: initialisation, motion, resampling, resetting.
    m_rng.randomize(seed);
    auto& o = m_pfOptions;
    o.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
    o.resamplingMethod = p.resampling;
    o.BETA = p.essThreshold;
    o.adaptiveSampleSize = false;
    m_pf.m_options = rfir::models::withoutMrptResampling(o);
    m_pdf.options.metricMap = m_map;
    double x0 = p.initX0, y0 = p.initY0, x1 = p.initX1, y1 = p.initY1;
    if (!p.initAreaSet) {
        m_map->emitters().bounds(x0, y0, x1, y1);
        x0 -= p.initMargin;
        y0 -= p.initMargin;
        x1 += p.initMargin;
        y1 += p.initMargin;
    }
    // Unknown start: uniform over the area and every heading.
    for (auto& part : m_pdf.m_particles) {
        part.d = mrpt::math::TPose2D(m_rng.drawUniform(x0, x1), m_rng.drawUniform(y0, y1),
                                     m_rng.drawUniform(-M_PI, M_PI));
        part.log_w = 0;
    }
}

void CIRLocalizer::startAt(const mrpt::math::TPose2D& p) {
    for (auto& part : m_pdf.m_particles) {
        part.d = mrpt::math::TPose2D(
            p.x + m_rng.drawGaussian1D(0, m_params.startStdXY),
            p.y + m_rng.drawGaussian1D(0, m_params.startStdXY),
            mrpt::math::wrapToPi(p.phi + m_rng.drawGaussian1D(0, m_params.startStdPhi)));
        part.log_w = 0;
    }
    m_started = true;
    m_history.clear();
}

double CIRLocalizer::positionStd() const {
    const auto [cov, mean] = m_pdf.getCovarianceAndMean();
    // Largest standard deviation of the position (2x2 block eigenvalue).
    const double a = cov(0, 0), b = cov(0, 1), c = cov(1, 1);
    const double lmax = 0.5 * (a + c) + std::sqrt(0.25 * (a - c) * (a - c) + b * b);
    return std::sqrt(std::max(0.0, lmax));
}

std::optional<mrpt::math::TPose2D> CIRLocalizer::associationReference() const {
    const auto [cov, mean] = m_pdf.getCovarianceAndMean();
    // Largest standard deviation of the position (2x2 block eigenvalue).
    const double a = cov(0, 0), b = cov(0, 1), c = cov(1, 1);
    const double lmax = 0.5 * (a + c) + std::sqrt(0.25 * (a - c) * (a - c) + b * b);
    if (m_params.associationMaxStd > 0 &&
        std::sqrt(std::max(0.0, lmax)) > m_params.associationMaxStd)
        return std::nullopt;
    return mean.asTPose();
}

mrpt::poses::CPose2D CIRLocalizer::estimate() const {
    mrpt::poses::CPose2D m;
    m_pdf.getMean(m);
    return m;
}

CObservationIRSignals::Ptr CIRLocalizer::prepare(const CObservationIRSignals& in,
                                                 TLocalizerStep& info, TSeen& seen,
                                                 CObservationIRSignals& early) const {
    auto out = CObservationIRSignals::Create();
    out->timestamp = in.timestamp;
    out->sensorLabel = in.sensorLabel;
    const bool earlyRepeated = m_params.repeatedBeforeUnique &&
                               m_map->likelihoodOptions.association ==
                                   rfir::maps::CIREmitterMap::TAssociation::Particle;
    for (const auto& r0 : in.readings) {
        CObservationIRSignals::TReading r = r0;
        if (r.codes.empty() && r.hasRaw() && m_params.decodeRaw) {
            const auto d = decodeIRWindow(r.raw, r.rateHz);
            r.codes = d.codes;
            r.volts = d.volts;
            info.decoded++;
        }
        const bool undecoded = r.codes.empty() && r.hasRaw();
        r.raw.clear();
        r.rateHz = 0;
        seen.emplace_back(r.receiver, r.codes.empty() ? "" : emitterIdFromCodes(r.codes));
        if (undecoded) continue;
        if (r.codes.empty()) {
            // Nothing in view: negative information, once estimating.
            if ((m_started || earlyRepeated) &&
                m_map->likelihoodOptions.params.missLogLik != 0)
                out->readings.push_back(r);
            continue;
        }
        info.readings++;
        const std::string id = emitterIdFromCodes(r.codes);
        if (!m_map->emitters().candidates(id)) {
            info.unknownIds++;
            continue;
        }
        // Before the first unique ID the thesis cannot attribute repeated IDs.
        if (!m_started && !m_map->emitters().isUnambiguous(id) && !earlyRepeated) {
            early.readings.push_back(r);
            continue;
        }
        out->readings.push_back(r);
    }
    return out;
}

void CIRLocalizer::predict(const mrpt::poses::CPose2D& incr) {
    mrpt::obs::CActionRobotMovement2D mv;
    mv.estimationMethod = mrpt::obs::CActionRobotMovement2D::emOdometry;
    mv.rawOdometryIncrementReading = incr;
    mv.poseChange =
        mrpt::poses::CPosePDFGaussian::Create(incr, m_params.motion.covariance(incr));
    mrpt::obs::CActionCollection acts;
    acts.insert(mv);
    m_pf.executeOn(m_pdf, &acts, nullptr);
    rfir::models::resampleIfNeeded(m_pdf, m_pfOptions, m_rng);
}

TLocalizerStep CIRLocalizer::step(const std::optional<mrpt::poses::CPose2D>& incr,
                                  const CObservationIRSignals* ir,
                                  std::optional<double> t) {
    TLocalizerStep info;
    CObservationIRSignals::Ptr obs;
    TSeen seen;
    auto early = CObservationIRSignals::Create();
    if (ir) obs = prepare(*ir, info, seen, *early);
    if (incr) {
        predict(*incr);
        m_odometry = m_odometry + *incr;
        m_path += std::hypot(incr->x(), incr->y());
    }
    const bool byEstimate = m_map->likelihoodOptions.association ==
                            rfir::maps::CIREmitterMap::TAssociation::Estimate;
    // Eq. 5.1 is evaluated against the predicted estimate, once per step.
    m_map->setAssociationReference(byEstimate && m_started ? associationReference()
                                                           : std::nullopt);
    // Readings that contradict the predicted particles are outliers, unless
    // enough unique IDs agree that the track is lost.
    m_step.terms.clear();
    const auto lostAt = obs ? gate(*obs, info) : std::nullopt;
    bool unique = false;
    if (obs)
        for (const auto& r : obs->readings)
            unique = unique || (!r.codes.empty() && m_map->emitters().isUnambiguous(
                                                        emitterIdFromCodes(r.codes)));
    // The first unique ID starts the estimation: the uniform prior is then
    // replaced by poses drawn from the reading. Later, sensor resetting.
    if (lostAt) {
        // Redraw every particle from the reading that declared it.
        auto& rs = obs->readings;
        std::rotate(rs.begin(), rs.begin() + long(*lostAt), rs.end());
        auto& ts = m_step.terms;  // parallel to the readings
        std::rotate(ts.begin(), ts.begin() + long(*lostAt), ts.end());
        info.lost = true;
        info.lostId = emitterIdFromCodes(rs.front().codes);
        info.resetParticles = sensorReset(*obs, true);
        m_monitor.clearAfterReset();
        m_recovering = true;
    } else if (unique && !m_started && m_params.startFromReading) {
        info.resetParticles = sensorReset(*obs, true);
        // This instant's repeated IDs too (the other receiver may be under a
        // repeated emitter now): at the current pose.
        remember(early);
        info.historyReadings = weighByHistory();
    } else if (unique && m_params.sensorResetting)
        info.resetParticles = sensorReset(*obs, false);
    if (obs && !obs->readings.empty()) {
        mrpt::obs::CSensoryFrame sf;
        sf.insert(obs);
        m_step.obs = obs.get();
        m_pf.executeOn(m_pdf, nullptr, &sf);
        m_step.obs = nullptr;
        rfir::models::resampleIfNeeded(m_pdf, m_pfOptions, m_rng);
        info.used = obs->readings.size();
    }
    info.uniqueRead = unique;
    info.justStarted = unique && !m_started;
    m_started = m_started || unique;
    if (!m_started) remember(early);
    info.started = m_started;
    noteSilence(ir, t, seen);
    if (m_started && !seen.empty()) checkEmitters(seen);
    if (m_recovering && positionStd() < m_params.robust.gateMaxStd) {
        m_recovering = false;
        info.settled = true;
    }
    return info;
}

double CIRLocalizer::fractionInView(const CObservationIRSignals::TReading& r,
                                    const TEmitter& e) const {
    const double R = m_map->likelihoodOptions.params.curve.visibleRadius(
                         m_map->verticalDistance(e, r.receiver)) +
                     m_params.resetViewMargin;
    double maxLw = -1e300, in = 0, all = 0;
    for (const auto& p : m_pdf.m_particles) maxLw = std::max(maxLw, p.log_w);
    for (const auto& p : m_pdf.m_particles) {
        const double w = std::exp(p.log_w - maxLw);
        const auto q = receiverInWorld(p.d, r.receiver);
        all += w;
        if (std::hypot(q.x - e.x, q.y - e.y) <= R) in += w;
    }
    return all > 0 ? in / all : 0;
}

size_t CIRLocalizer::sensorReset(const CObservationIRSignals& obs, bool all) {
    for (const auto& r : obs.readings) {
        if (r.codes.empty()) continue;
        const auto* c = m_map->emitters().candidates(emitterIdFromCodes(r.codes));
        if (!c || c->size() != 1) continue;
        const auto& e = m_map->emitters().emitters()[(*c)[0]];
        if (!all && fractionInView(r, e) >= m_params.resetMinFraction) return 0;
        // The other receivers that see the same emitter fix the heading.
        std::vector<const CObservationIRSignals::TReading*> same{&r};
        for (const auto& o : obs.readings)
            if (&o != &r && o.codes == r.codes) same.push_back(&o);
        // Redraw particles that do not see it (all of them at the start), in a
        // random order: Fisher-Yates with our generator (MRPT's shuffle seeds
        // itself from std::random_device: not reproducible).
        const double R = m_map->likelihoodOptions.params.curve.visibleRadius(
                             m_map->verticalDistance(e, r.receiver)) +
                         m_params.resetViewMargin;
        std::vector<size_t> perm;
        double maxLw = -1e300;
        for (size_t i = 0; i < m_pdf.m_particles.size(); i++) {
            const auto& p = m_pdf.m_particles[i];
            maxLw = std::max(maxLw, p.log_w);
            const auto q = receiverInWorld(p.d, r.receiver);
            if (all || std::hypot(q.x - e.x, q.y - e.y) > R) perm.push_back(i);
        }
        for (size_t k = perm.size(); k > 1; k--)
            std::swap(perm[k - 1], perm[size_t(m_rng.drawUniform(0.0, 1.0) * k) % k]);
        const double ratio = all ? 1.0 : m_params.resetRatio;
        const size_t n =
            std::min(perm.size(), size_t(std::lround(ratio * m_pdf.m_particles.size())));
        for (size_t k = 0; k < n; k++) {
            auto& p = m_pdf.m_particles[perm[k]];
            drawFromReadings(same, e, p.d);
            m_step.forget(perm[k]);
            p.log_w = all ? 0.0 : maxLw;
        }
        return n;
    }
    return 0;
}

double CIRLocalizer::drawDistance(const CObservationIRSignals::TReading& r,
                                  const TEmitter& e) {
    const auto& curve = m_map->likelihoodOptions.params.curve;
    const double h = m_map->verticalDistance(e, r.receiver);
    const auto roots = distancesForVoltage(curve, r.volts, h);
    const double d =
        roots.empty()
            ? m_rng.drawUniform(0.0, curve.visibleRadius(h))
            : roots[size_t(m_rng.drawUniform(0.0, 1.0) * roots.size()) % roots.size()];
    return std::max(0.0, d + m_rng.drawGaussian1D(0, m_params.resetDistanceSigma));
}

void CIRLocalizer::drawFromReadings(
    const std::vector<const CObservationIRSignals::TReading*>& rs, const TEmitter& e,
    mrpt::math::TPose2D& out) {
    // Receiver 0 on the circle of radius d0 (eq. 5.3 inverted) around the
    // emitter, at a random bearing. One reading leaves the heading free: any
    // rotation about the emitter explains it equally.
    const auto& r0 = rs[0]->receiver;
    const double d0 = drawDistance(*rs[0], e);
    const double b0 = m_rng.drawUniform(-M_PI, M_PI);
    const double q0x = e.x + d0 * std::cos(b0), q0y = e.y + d0 * std::sin(b0);
    double phi = m_rng.drawUniform(-M_PI, M_PI);
    if (rs.size() > 1) {
        // A second receiver at distance d1 from the emitter and at the baseline
        // length from receiver 0: intersect the two circles (nearest point if
        // they do not meet), pick one of the two mirror solutions.
        const auto& r1 = rs[1]->receiver;
        const double base = std::hypot(r1.x - r0.x, r1.y - r0.y);
        const double d1 = drawDistance(*rs[1], e);
        const double ux = (e.x - q0x), uy = (e.y - q0y), D = std::hypot(ux, uy);
        if (base > 1e-6 && D > 1e-9) {
            const double a =
                std::clamp((base * base - d1 * d1 + D * D) / (2 * D), -base, base);
            const double hh = std::sqrt(std::max(0.0, base * base - a * a));
            const double sgn = m_rng.drawUniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
            const double q1x = q0x + (a * ux - sgn * hh * uy) / D;
            const double q1y = q0y + (a * uy + sgn * hh * ux) / D;
            phi = std::atan2(q1y - q0y, q1x - q0x) - std::atan2(r1.y - r0.y, r1.x - r0.x);
        }
    }
    // Receiver 0 at q0: the robot position from the read model's inverse.
    const auto t = rfir::models::robotPositionFromRead({q0x, q0y}, std::cos(phi),
                                                       std::sin(phi), r0.x, r0.y);
    out = mrpt::math::TPose2D(t.x, t.y, mrpt::math::wrapToPi(phi));
}

}  // namespace rfir::ir
