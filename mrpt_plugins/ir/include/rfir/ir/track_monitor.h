/* rfir: what keeps the IR localization from being lost (docs/ir.md, "Faults"):
 * readings gated by the motion prior, per-emitter health (emitters that never
 * answer, emitters whose readings contradict the map) and lost-track
 * detection from unique IDs that keep contradicting the track. The localizer
 * (CIRLocalizer) feeds it; it holds no particles. See docs/ir.md. */
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace rfir::ir {
/** [localization] keys of the robustness layer. */
struct TRobustParams {
    /** gate_max_std (m): readings are gated only while the particles' position
     * spread (largest std) is below this; 0: no gate, no lost-track detection,
     * no emitter health (the filter as before). */
    double gateMaxStd = 0.1;
    /** gate_loglik, gate_min_fraction: a reading is inconsistent with the
     * motion prior when less than gate_min_fraction of the predicted particles
     * (by weight) give it a log-likelihood above gate_loglik. It is then not
     * used: an outlier, not a jump. */
    double gateLogLik = -6;
    double gateMinFraction = 0.01;
    /** lost_min_readings, lost_min_ids: the track is lost when at least
     * lost_min_ids unique IDs have each given lost_min_readings inconsistent
     * readings since the last consistent unique reading; the particles are then
     * redrawn from the reading (a single wrong code or a moved emitter is one
     * ID; a kidnapping shows up in every emitter that follows). */
    size_t lostMinReadings = 3;
    size_t lostMinIds = 2;
    /** emitter_check_radius (m): an emitter is expected to answer when the
     * estimate puts a receiver this close to it (its voltage there is far
     * above any detection threshold). */
    double emitterCheckRadius = 0.2;
    /** emitter_min_checks: expected answers (or readings) before an emitter
     * is classified failed (answered under 10 % of them) or inconsistent
     * (a quarter or more of its readings gated). */
    size_t emitterMinChecks = 10;
    /** inconsistent_weight: factor on the log-likelihood of the readings of
     * an emitter classified inconsistent (readings that pass the gate). */
    double inconsistentWeight = 0.1;
};

/** One emitter's record over the run. */
struct TEmitterHealth {
    enum class Status { Ok, Failed, Inconsistent, Unseen };
    size_t readings = 0;  //!< readings attributed to it while gating
    size_t gated = 0;     //!< of which inconsistent with the motion prior
    size_t checks = 0;    //!< times a receiver was put under it
    size_t answered = 0;  //!< of which that receiver read its ID
    /** readings and gated since the last lost-track reset (they classify). */
    size_t recentReadings = 0, recentGated = 0;
    Status status = Status::Unseen;
    double weight = 1.0;  //!< factor on its readings' log-likelihood
};

const char* statusName(TEmitterHealth::Status s);

class CTrackMonitor {
  public:
    CTrackMonitor(const TRobustParams& p, size_t emitters);

    /** A reading attributed to emitter `idx` (at the estimate) while gating.
     * Returns true when this reading declares the track lost. */
    bool noteReading(size_t idx, const std::string& id, bool unique, bool consistent);
    /** Whether the estimate put a receiver under emitter `idx` and whether
     * that receiver read its ID. */
    void noteCheck(size_t idx, bool answered);
    /** After a lost-track reset: the evidence gathered on the wrong track is
     * dropped (counts are kept). */
    void clearAfterReset();

    const std::vector<TEmitterHealth>& health() const { return m_health; }

  private:
    void classify(TEmitterHealth& h) const;

    TRobustParams m_p;
    std::vector<TEmitterHealth> m_health;
    /** Inconsistent readings per unique ID since the last consistent one. */
    std::map<std::string, size_t> m_evidence;
};

}  // namespace rfir::ir
