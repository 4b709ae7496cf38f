/* rfir: resampling schemes with an explicit generator. */
#include <rfir/models/resampling.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rfir::models {
const char* toString(ResamplingScheme s) {
    switch (s) {
        case ResamplingScheme::Systematic:
            return "systematic";
        case ResamplingScheme::Stratified:
            return "stratified";
        case ResamplingScheme::Multinomial:
            return "multinomial";
    }
    return "?";
}

std::vector<double> normalisedWeights(const std::vector<double>& logWeights) {
    if (logWeights.empty()) throw std::invalid_argument("normalisedWeights: empty");
    double mx = -std::numeric_limits<double>::infinity();
    for (double l : logWeights) {
        if (std::isnan(l) || l == std::numeric_limits<double>::infinity())
            throw std::invalid_argument("normalisedWeights: NaN or +inf log-weight");
        mx = std::max(mx, l);
    }
    if (!std::isfinite(mx))
        throw std::invalid_argument("normalisedWeights: no finite log-weight");
    std::vector<double> w(logWeights.size());
    double sum = 0;
    for (size_t i = 0; i < w.size(); i++) {
        w[i] = std::exp(logWeights[i] - mx);
        sum += w[i];
    }
    for (double& x : w) x /= sum;
    return w;
}

double effectiveSampleSize(const std::vector<double>& logWeights) {
    double s2 = 0;
    for (double w : normalisedWeights(logWeights)) s2 += w * w;
    return 1.0 / s2;
}

std::vector<size_t> resampleIndices(const std::vector<double>& logWeights, size_t n,
                                    ResamplingScheme scheme, rfir::models::TRandom& rng) {
    const std::vector<double> w = normalisedWeights(logWeights);
    std::vector<double> cdf(w.size());
    double acc = 0;
    for (size_t i = 0; i < w.size(); i++) cdf[i] = (acc += w[i]);
    cdf.back() = 1.0;  // guard against rounding

    std::vector<double> u(n);
    if (scheme == ResamplingScheme::Multinomial) {
        for (double& x : u) x = rng.drawUniform(0.0, 1.0);
        std::sort(u.begin(), u.end());
    } else {
        const double u0 = rng.drawUniform(0.0, 1.0);
        for (size_t k = 0; k < n; k++) {
            const double r =
                scheme == ResamplingScheme::Systematic ? u0 : rng.drawUniform(0.0, 1.0);
            u[k] = (k + r) / n;
        }
    }
    std::vector<size_t> idx(n);
    size_t j = 0;
    for (size_t k = 0; k < n; k++) {
        while (j + 1 < cdf.size() && cdf[j] < u[k]) j++;
        idx[k] = j;
    }
    return idx;
}

}  // namespace rfir::models
