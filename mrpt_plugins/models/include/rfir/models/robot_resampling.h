/* rfir: the robot filters' resampling stage with the run's generator. MRPT's
 * CParticleFilterCapable::performResampling (not virtual) draws from MRPT's
 * global generator, so the engines (rfir-slam's robot filters, the IR
 * localizer) give CParticleFilter a BETA of 0 (its own stage never fires) and
 * call this right after executeOn, with MRPT's own options: the same ESS test
 * and scheme, the engine's generator. */
#pragma once

#include <rfir/models/random.h>

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/bayes/CParticleFilterCapable.h>

#include <vector>

namespace rfir::models {
/** The options CParticleFilter runs with: `o` with its resampling stage off. */
mrpt::bayes::CParticleFilter::TParticleFilterOptions withoutMrptResampling(
    mrpt::bayes::CParticleFilter::TParticleFilterOptions o);

/** ESS < o.BETA: resample `pf` (performSubstitution) by o.resamplingMethod.
 * Returns whether it did. */
bool resampleIfNeeded(mrpt::bayes::CParticleFilterCapable& pf,
                      const mrpt::bayes::CParticleFilter::TParticleFilterOptions& o,
                      rfir::models::TRandom& rng);

}  // namespace rfir::models
