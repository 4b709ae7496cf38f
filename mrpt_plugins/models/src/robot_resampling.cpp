/* rfir: resampling of the robot filters with the run's generator. */
#include <rfir/models/resampling.h>
#include <rfir/models/robot_resampling.h>

#include <algorithm>
#include <cmath>

namespace rfir::models {
using PF = mrpt::bayes::CParticleFilter;

PF::TParticleFilterOptions withoutMrptResampling(PF::TParticleFilterOptions o) {
    o.BETA = 0;  // executeOn resamples when ESS < BETA: never
    return o;
}

namespace {
/** Residual resampling: floor(n w_i) copies of each, the rest multinomial
 * on the residual weights. */
std::vector<size_t> residual(const std::vector<double>& logW,
                             rfir::models::TRandom& rng) {
    const size_t n = logW.size();
    const double mx = *std::max_element(logW.begin(), logW.end());
    std::vector<double> w(n);
    double sum = 0;
    for (size_t i = 0; i < n; i++) sum += (w[i] = std::exp(logW[i] - mx));
    std::vector<size_t> idx;
    idx.reserve(n);
    std::vector<double> rest(n);
    for (size_t i = 0; i < n; i++) {
        const double c = std::floor(double(n) * w[i] / sum);
        idx.insert(idx.end(), size_t(c), i);
        rest[i] = double(n) * w[i] / sum - c;
    }
    if (idx.size() < n) {
        std::vector<double> lr(n);
        for (size_t i = 0; i < n; i++) lr[i] = rest[i] > 0 ? std::log(rest[i]) : -1e300;
        const auto more = rfir::models::resampleIndices(
            lr, n - idx.size(), rfir::models::ResamplingScheme::Multinomial, rng);
        idx.insert(idx.end(), more.begin(), more.end());
    }
    std::sort(idx.begin(), idx.end());
    return idx;
}
}  // namespace

namespace {
/** Resampling indices of n log-weights by MRPT's scheme (multinomial,
 * residual, stratified, systematic), drawn from `rng`; sorted. */
std::vector<size_t> robotResampleIndices(const std::vector<double>& logW,
                                         PF::TParticleResamplingAlgorithm scheme,
                                         rfir::models::TRandom& rng) {
    using S = rfir::models::ResamplingScheme;
    switch (scheme) {
        case PF::prResidual:
            return residual(logW, rng);
        case PF::prMultinomial:
            return rfir::models::resampleIndices(logW, logW.size(), S::Multinomial, rng);
        case PF::prStratified:
            return rfir::models::resampleIndices(logW, logW.size(), S::Stratified, rng);
        default:
            return rfir::models::resampleIndices(logW, logW.size(), S::Systematic, rng);
    }
}
}  // namespace

bool resampleIfNeeded(mrpt::bayes::CParticleFilterCapable& pf,
                      const PF::TParticleFilterOptions& o, rfir::models::TRandom& rng) {
    const size_t n = pf.particlesCount();
    if (n == 0 || !(pf.ESS() < o.BETA)) return false;
    std::vector<double> lw(n);
    for (size_t i = 0; i < n; i++) lw[i] = pf.getW(i);
    pf.performSubstitution(robotResampleIndices(lw, o.resamplingMethod, rng));
    // MRPT's performResampling leaves equal weights after the substitution.
    for (size_t i = 0; i < n; i++) pf.setW(i, 0.0);
    return true;
}

}  // namespace rfir::models
