/* rfir: gating, emitter health and lost-track detection of the IR localizer. */
#include <rfir/ir/track_monitor.h>

namespace rfir::ir {
const char* statusName(TEmitterHealth::Status s) {
    switch (s) {
        case TEmitterHealth::Status::Ok:
            return "ok";
        case TEmitterHealth::Status::Failed:
            return "failed";
        case TEmitterHealth::Status::Inconsistent:
            return "inconsistent";
        default:
            return "unseen";
    }
}

CTrackMonitor::CTrackMonitor(const TRobustParams& p, size_t emitters)
    : m_p(p), m_health(emitters) {}

void CTrackMonitor::classify(TEmitterHealth& h) const {
    using S = TEmitterHealth::Status;
    if (h.checks >= m_p.emitterMinChecks && 10 * h.answered < h.checks)
        h.status = S::Failed;
    else if (h.recentReadings >= m_p.emitterMinChecks &&
             4 * h.recentGated >= h.recentReadings)
        h.status = S::Inconsistent;
    else if (h.readings == 0 && h.checks == 0)
        h.status = S::Unseen;
    else
        h.status = S::Ok;
    // A failed emitter sends nothing: weight 0 only matters if it answers
    // again, and then the answers first have to pass the gate.
    h.weight = h.status == S::Inconsistent ? m_p.inconsistentWeight
               : h.status == S::Failed     ? 0.0
                                           : 1.0;
}

bool CTrackMonitor::noteReading(size_t idx, const std::string& id, bool unique,
                                bool consistent) {
    auto& h = m_health.at(idx);
    h.readings++;
    h.recentReadings++;
    if (!consistent) {
        h.gated++;
        h.recentGated++;
    }
    classify(h);
    if (!unique) return false;
    if (consistent) {
        m_evidence.clear();
        return false;
    }
    m_evidence[id]++;
    size_t ids = 0;
    for (const auto& [k, n] : m_evidence)
        if (n >= m_p.lostMinReadings) ids++;
    return ids >= m_p.lostMinIds;
}

void CTrackMonitor::noteCheck(size_t idx, bool answered) {
    auto& h = m_health.at(idx);
    h.checks++;
    if (answered) h.answered++;
    classify(h);
}

void CTrackMonitor::clearAfterReset() {
    m_evidence.clear();
    for (auto& h : m_health) {
        h.recentReadings = h.recentGated = 0;
        classify(h);
    }
}

}  // namespace rfir::ir
