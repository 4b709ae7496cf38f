/* rfir-experiments: aggregation over seeds. */
#include <rfir/experiments/results.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace rfir::experiments {
TStat statOf(const std::vector<double>& v) {
    TStat s;
    double sum = 0;
    for (double x : v)
        if (std::isfinite(x)) sum += x, s.n++;
    if (!s.n) return s;
    s.mean = sum / double(s.n);
    double q = 0;
    for (double x : v)
        if (std::isfinite(x)) q += (x - s.mean) * (x - s.mean);
    s.sd = s.n > 1 ? std::sqrt(q / double(s.n - 1)) : 0.0;
    return s;
}

std::vector<double> perSeed(const TRowResults& r, size_t point, const std::string& method,
                            const TGetter& get) {
    std::map<uint64_t, std::pair<double, size_t>> acc;
    for (const auto& x : r.runs) {
        if (x.point != point || x.method != method) continue;
        const double v = get(x);
        auto& a = acc[x.seed];
        if (std::isfinite(v)) a.first += v, a.second++;
    }
    std::vector<double> out;
    for (const auto& [seed, a] : acc)
        out.push_back(a.second ? a.first / double(a.second) : kNaN);
    return out;
}

double maxOver(const TRowResults& r, size_t point, const std::string& method,
               const TGetter& get) {
    double m = kNaN;
    for (const auto& x : r.runs)
        if (x.point == point && x.method == method) {
            const double v = get(x);
            if (std::isfinite(v) && !(v <= m)) m = v;
        }
    return m;
}

double robotMeanDist(const TRunResult& r) {
    return r.eval.robot ? r.eval.robot->stats.mean_dist : kNaN;
}
double tagMeanDist(const TRunResult& r) {
    return r.eval.map && r.eval.map->stats.count ? r.eval.map->stats.mean_dist : kNaN;
}

}  // namespace rfir::experiments
