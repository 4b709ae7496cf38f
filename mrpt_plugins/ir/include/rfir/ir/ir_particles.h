/* rfir: the IR localizer's particle set on MRPT's particle-filter machinery:
 * a CMonteCarloLocalization2D that CParticleFilter::executeOn drives, weighed
 * by the step's likelihood (TIRStepLikelihood), built once per step from the
 * observation: the readings' terms that the gate computed for the predicted
 * particles are reused, not evaluated again. */
#pragma once

#include <rfir/maps/CIREmitterMap.h>

#include <mrpt/slam/CMonteCarloLocalization2D.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace rfir::ir {
/** One step's observation log-likelihood per particle: the emitter map's
 * observationLogLikelihood, with the readings' terms known so far. */
struct TIRStepLikelihood {
    using TTerm = std::optional<rfir::maps::CIREmitterMap::TReadingTerm>;
    /** A reading's term at one particle's pose, if it was computed. */
    struct TKnownTerm {
        bool known = false;
        TTerm term;
    };

    const rfir::maps::CIREmitterMap* map = nullptr;
    /** The step's observation while it weighs (null otherwise). */
    const rfir::obs::CObservationIRSignals* obs = nullptr;
    /** terms[k][i]: reading k's term for particle i at its current pose; an
     * empty terms[k] (or k past the end): none known. */
    std::vector<std::vector<TKnownTerm>> terms;

    /** Particle i was redrawn: the terms computed at its old pose no longer
     * hold. */
    void forget(size_t i) {
        for (auto& t : terms)
            if (i < t.size()) t[i].known = false;
    }
    /** The observation's log-likelihood for particle i at pose p (0 when the
     * map's enableObservationLikelihood is off, as MRPT's maps do). */
    double logLikelihood(size_t i, const mrpt::math::TPose2D& p) const;
};

class CIRParticles : public mrpt::slam::CMonteCarloLocalization2D {
  public:
    /** M particles weighed by `step` (the localizer's, outliving this set). */
    CIRParticles(size_t M, const TIRStepLikelihood& step)
        : mrpt::slam::CMonteCarloLocalization2D(M), m_step(&step) {}

  protected:
    /** MRPT's sum (CMonteCarloLocalization2D's, which starts at 1) over the
     * step's one observation. */
    double PF_SLAM_computeObservationLikelihoodForParticle(
        const mrpt::bayes::CParticleFilter::TParticleFilterOptions& o, size_t i,
        const mrpt::obs::CSensoryFrame& sf, const mrpt::poses::CPose3D& x) const override;

  private:
    const TIRStepLikelihood* m_step;
};

}  // namespace rfir::ir
