/* rfir: resampling with a caller-provided generator. MRPT's
 * CParticleFilterCapable::computeResampling draws from the global generator
 * (mrpt::random::getRandomGenerator()), which is neither per-map seedable nor
 * safe to share across threads; these take the generator explicitly. */
#pragma once

#include <mrpt/random/RandomGenerators.h>
#include <rfir/models/random.h>

#include <string>
#include <vector>

namespace rfir::models {
enum class ResamplingScheme {
    Systematic,  //!< low-variance (one uniform draw, L evenly spaced pointers)
    Stratified,  //!< one uniform draw per stratum
    Multinomial  //!< L independent draws
};

const char* toString(ResamplingScheme s);

/** Indices of the n resampled particles, drawn proportionally to
 * exp(logWeights). Output sorted ascending (systematic / stratified) so that
 * copies of one particle are adjacent. Throws if logWeights is empty or all
 * -inf / NaN. */
std::vector<size_t> resampleIndices(const std::vector<double>& logWeights, size_t n,
                                    ResamplingScheme scheme, rfir::models::TRandom& rng);

/** Normalised linear weights from log-weights (max-shifted, sum 1). */
std::vector<double> normalisedWeights(const std::vector<double>& logWeights);

/** Effective sample size 1 / sum(w_i^2) of normalised weights. */
double effectiveSampleSize(const std::vector<double>& logWeights);

}  // namespace rfir::models
