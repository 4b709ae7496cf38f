/* rfir: the IR localizer's particle set on MRPT's particle-filter machinery:
 * a CMonteCarloLocalization2D that CParticleFilter::executeOn drives. Its
 * prediction draws each particle's motion from the action's Gaussian with
 * the run's generator (MRPT's sampler draws from its global one); its
 * weighing asks the step's likelihood (TIRStepLikelihood), built once per
 * step from the observation: the readings' terms that the gate computed for
 * the predicted particles are reused, not evaluated again. Resampling
 * follows executeOn, with the same generator (rfir/models/robot_resampling.h). */
#pragma once

#include <rfir/maps/CIREmitterMap.h>
#include <rfir/models/random.h>

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
    /** M particles moved with `rng` and weighed by `step` (the localizer's,
     * both outliving this set). */
    CIRParticles(size_t M, rfir::models::TRandom& rng, const TIRStepLikelihood& step)
        : mrpt::slam::CMonteCarloLocalization2D(M), m_rng(&rng), m_step(&step) {}

  protected:
    /** The action's movement (a CPosePDFGaussian), one draw per particle;
     * then, with an observation, log_w += the step's log-likelihood. */
    void prediction_and_update_pfStandardProposal(
        const mrpt::obs::CActionCollection* action, const mrpt::obs::CSensoryFrame* sf,
        const mrpt::bayes::CParticleFilter::TParticleFilterOptions& o) override;

  private:
    rfir::models::TRandom* m_rng;
    const TIRStepLikelihood* m_step;
};

}  // namespace rfir::ir
