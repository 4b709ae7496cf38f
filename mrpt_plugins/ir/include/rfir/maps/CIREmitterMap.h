/* rfir: the known map of ceiling IR emitters as an MRPT metric map (thesis
 * chapter 5): computeObservationLikelihood weighs a robot pose with the IR
 * readings of a rfir::obs::CObservationIRSignals (eqs. 5.1-5.3). INI-creatable
 * like MRPT's own maps (short name `irEmitterMap`). See docs/ir.md. */
#pragma once

#include <rfir/ir/emitter_set.h>
#include <rfir/ir/sensor_model.h>
#include <rfir/obs/CObservationIRSignals.h>

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/math/TPose2D.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace rfir::maps {
class CIREmitterMap : public mrpt::maps::CMetricMap {
    DEFINE_SERIALIZABLE(CIREmitterMap, rfir::maps)

  public:
    /** Which emitter a reading of a repeated ID is attributed to. */
    enum class TAssociation {
        /** INI "estimate": the thesis' belief (eq. 5.1) against the current
         * robot estimate (setAssociationReference); one emitter for every
         * particle. Without a reference, repeated readings are skipped. */
        Estimate,
        /** INI "particle": each particle picks the emitter with the largest
         * belief against its own pose. */
        Particle
    };

    CIREmitterMap() = default;

    void setEmitters(const rfir::ir::TEmitterSet& e) {
        m_emitters = e;
        m_weights.clear();
    }
    /** TEmitterSet::load (throws "FILE:LINE: ..."). */
    void loadEmitterFile(const std::string& path);
    const rfir::ir::TEmitterSet& emitters() const { return m_emitters; }

    /** Robot estimate for the Estimate association (nullopt: none yet). */
    void setAssociationReference(const std::optional<mrpt::math::TPose2D>& p) {
        m_reference = p;
    }
    const std::optional<mrpt::math::TPose2D>& associationReference() const {
        return m_reference;
    }

    /** Per-emitter factors on the readings' log-likelihood (index as
     * emitters(); empty: all 1). Set by the localizer from its emitter health
     * (down-weights emitters whose readings contradict the map); run state,
     * not serialized. */
    void setEmitterWeights(std::vector<double> w) { m_weights = std::move(w); }

    /** The emitter (index into emitters()) a reading is attributed to for a
     * robot pose; nullopt if the reading is skipped (no code, an ID absent from
     * the map, or a repeated ID without a reference under Estimate). */
    std::optional<size_t> associate(const rfir::obs::CObservationIRSignals::TReading& r,
                                    const mrpt::math::TPose2D& robot) const {
        return associate(r, robot, likelihoodOptions.association);
    }
    /** The same with the association given (not the INI's). */
    std::optional<size_t> associate(const rfir::obs::CObservationIRSignals::TReading& r,
                                    const mrpt::math::TPose2D& robot,
                                    TAssociation how) const;

    /** Vertical emitter-receiver distance used for a reading. */
    double verticalDistance(const rfir::ir::TEmitter& e,
                            const rfir::obs::TIRReceiver& r) const;

    /** A reading's term for a robot pose: the emitter it is attributed to
     * (associate) and its log-likelihood before that emitter's weight. */
    struct TReadingTerm {
        size_t emitter;
        double logLik;
    };
    /** The term of reading r at `robot`; nullopt when it is not attributed. */
    std::optional<TReadingTerm> readingTerm(
        const rfir::obs::CObservationIRSignals::TReading& r,
        const mrpt::math::TPose2D& robot) const {
        return readingTerm(r, robot, likelihoodOptions.association);
    }
    /** The same with the association given (not the INI's). */
    std::optional<TReadingTerm> readingTerm(
        const rfir::obs::CObservationIRSignals::TReading& r,
        const mrpt::math::TPose2D& robot, TAssociation how) const;

    /** Sum over the readings of the log-likelihood (eq. 5.2 with 5.3). Readings
     * with no code (raw windows not decoded yet) are skipped. */
    double observationLogLikelihood(const rfir::obs::CObservationIRSignals& obs,
                                    const mrpt::math::TPose2D& robot) const;
    /** The same sum with the readings' terms from `termOf(k)` (reading k's
     * readingTerm at `robot`): a caller that already evaluated them (the
     * localizer's gate) passes them instead of evaluating them again. */
    template <class TermOf>
    double observationLogLikelihood(const rfir::obs::CObservationIRSignals& obs,
                                    const mrpt::math::TPose2D& robot,
                                    TermOf&& termOf) const;

    struct TLikelihoodOptions : public mrpt::config::CLoadableOptions {
        rfir::ir::TIRLikelihoodParams params;
        TAssociation association = TAssociation::Estimate;
        /** vertical_distance: > 0 forces this emitter-receiver distance (m);
         * 0 takes emitter z minus receiver z (the fit height if not positive). */
        double verticalDistance = 0;

        void loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
                                const std::string& section) override;
        void dumpToTextStream(std::ostream& out) const override;
    } likelihoodOptions;

    // CMetricMap interface
    bool isEmpty() const override { return m_emitters.empty(); }
    /** Writes "<prefix>_emitters.txt" (textlog emitter records). */
    void saveMetricMapRepresentationToFile(const std::string& prefix) const override;
    void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;
    std::string asString() const override;

    MAP_DEFINITION_START(CIREmitterMap)
    /** [<prefix>_creationOpts] emitter_file: path (relative: to the INI's
     * folder, when the INI is a file); empty: set later by the program. */
    std::string emitterFile;
    rfir::maps::CIREmitterMap::TLikelihoodOptions likelihoodOpts;
    /** A refused INI value, raised when the map is created (see
     * loadFromConfigFile_map_specific). */
    std::exception_ptr loadError;
    MAP_DEFINITION_END(CIREmitterMap)

  protected:
    void internal_clear() override;
    bool internal_insertObservation(const mrpt::obs::CObservation& obs,
                                    const std::optional<const mrpt::poses::CPose3D>&
                                        robotPose = std::nullopt) override;
    double internal_computeObservationLikelihood(
        const mrpt::obs::CObservation& obs,
        const mrpt::poses::CPose3D& takenFrom) const override;
    bool internal_canComputeObservationLikelihood(
        const mrpt::obs::CObservation& obs) const override;

  private:
    /** The area term (outOfAreaLogLik) applies to `robot`. */
    bool outOfArea(const rfir::obs::CObservationIRSignals& obs,
                   const mrpt::math::TPose2D& robot) const;
    /** A receiver that saw nothing counts as a miss (missLogLik) at `robot`. */
    bool countsAsMiss(const rfir::obs::CObservationIRSignals::TReading& r,
                      const mrpt::math::TPose2D& robot) const;
    double emitterWeight(size_t i) const {
        return i < m_weights.size() ? m_weights[i] : 1.0;
    }

    rfir::ir::TEmitterSet m_emitters;
    std::optional<mrpt::math::TPose2D> m_reference;
    std::vector<double> m_weights;
};

template <class TermOf>
double CIREmitterMap::observationLogLikelihood(
    const rfir::obs::CObservationIRSignals& obs, const mrpt::math::TPose2D& robot,
    TermOf&& termOf) const {
    const auto& lp = likelihoodOptions.params;
    double ll = 0;
    if (outOfArea(obs, robot)) ll += lp.outOfAreaLogLik;
    for (size_t k = 0; k < obs.readings.size(); k++) {
        const auto& r = obs.readings[k];
        // No code: a receiver that saw nothing, or an undecoded raw window.
        if (r.codes.empty()) {
            if (countsAsMiss(r, robot)) ll += lp.missLogLik;
            continue;
        }
        const std::optional<TReadingTerm> t = termOf(k);
        if (t) ll += emitterWeight(t->emitter) * t->logLik;
    }
    return ll;
}

/** Registers the library's classes with MRPT (also done at load time; calling
 * it keeps the library linked under --as-needed). Idempotent. */
void registerIRClasses();

}  // namespace rfir::maps
