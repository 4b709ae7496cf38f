/* rfir: the IR localizer's gate by the motion prior and its emitter checks
 * (CTrackMonitor holds the bookkeeping). */
#include <rfir/ir/ir_localizer.h>
#include <rfir/obs/ir_codes.h>

#include <algorithm>
#include <cmath>

namespace rfir::ir {
using rfir::obs::CObservationIRSignals;

std::optional<size_t> CIRLocalizer::gate(CObservationIRSignals& obs,
                                         TLocalizerStep& info) {
    const auto& rp = m_params.robust;
    if (!m_started || rp.gateMaxStd <= 0 || m_recovering || obs.readings.empty())
        return std::nullopt;
    const auto est = estimate().asTPose();
    const auto& parts = m_pdf.m_particles;
    double maxLw = -1e300, sum = 0;
    for (const auto& p : parts) maxLw = std::max(maxLw, p.log_w);
    std::vector<double> w(parts.size());
    for (size_t i = 0; i < parts.size(); i++)
        sum += (w[i] = std::exp(parts[i].log_w - maxLw));
    const auto& ems = m_map->emitters();
    std::vector<CObservationIRSignals::TReading> kept;
    std::vector<std::vector<TIRStepLikelihood::TKnownTerm>> keptTerms;
    std::optional<size_t> lost;
    for (auto& r : obs.readings) {
        const auto idx = r.codes.empty() ? std::nullopt : m_map->associate(r, est);
        if (!idx) {
            kept.push_back(std::move(r));
            keptTerms.emplace_back();
            continue;
        }
        // Share of the predicted particles (by weight) that explain the
        // reading; each term is kept: the weighing adds the same ones.
        std::vector<TIRStepLikelihood::TKnownTerm> terms(parts.size());
        double good = 0;
        for (size_t i = 0; i < parts.size(); i++) {
            const auto t = m_map->readingTerm(r, parts[i].d);
            terms[i] = {true, t};
            if (t && t->logLik > rp.gateLogLik) good += w[i];
        }
        const bool consistent = sum > 0 && good >= rp.gateMinFraction * sum;
        const std::string id = emitterIdFromCodes(r.codes);
        const bool isLost =
            m_monitor.noteReading(*idx, id, ems.isUnambiguous(id), consistent);
        if (isLost && !lost) lost = kept.size();
        if (consistent || isLost) {
            kept.push_back(std::move(r));
            keptTerms.push_back(std::move(terms));
        } else
            info.gated++;
    }
    obs.readings = std::move(kept);
    m_step.terms = std::move(keptTerms);
    std::vector<double> weights;
    for (const auto& h : m_monitor.health()) weights.push_back(h.weight);
    m_map->setEmitterWeights(std::move(weights));
    return lost;
}

void CIRLocalizer::noteSilence(const CObservationIRSignals* ir, std::optional<double> t,
                               TSeen& seen) {
    if (ir) {
        if (ir->readings.size() > m_receivers.size()) {
            m_receivers.clear();
            for (const auto& r : ir->readings) m_receivers.push_back(r.receiver);
        }
        if (t && m_lastIrT && *t > *m_lastIrT)
            m_irPeriod =
                m_irPeriod > 0 ? std::min(m_irPeriod, *t - *m_lastIrT) : *t - *m_lastIrT;
        if (t) m_lastIrT = m_lastCheckT = t;
        return;
    }
    // No observation where one was due: every receiver saw nothing.
    if (!t || m_irPeriod <= 0 || !m_lastCheckT ||
        *t - *m_lastCheckT < m_irPeriod * (1 - 1e-6))
        return;
    m_lastCheckT = t;
    for (const auto& r : m_receivers) seen.emplace_back(r, "");
}

void CIRLocalizer::checkEmitters(const TSeen& seen) {
    const auto& rp = m_params.robust;
    if (rp.gateMaxStd <= 0 || m_recovering || positionStd() > rp.gateMaxStd) return;
    const auto est = estimate().asTPose();
    const auto& ems = m_map->emitters();
    for (const auto& [rcv, id] : seen) {
        const auto q = receiverInWorld(est, rcv);
        const auto k = ems.nearestIndexWithin(q.x, q.y, rp.emitterCheckRadius);
        if (k) m_monitor.noteCheck(*k, ems.emitters()[*k].id == id);
    }
}

}  // namespace rfir::ir
