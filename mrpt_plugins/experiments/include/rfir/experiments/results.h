/* rfir-experiments: the raw results of a row and their aggregation over seeds. */
#pragma once

#include <rfir/experiments/experiment.h>
#include <rfir/experiments/runner.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rfir::experiments {
struct TRowResults {
    TRow row;
    std::vector<TRunResult> runs;  //!< every (point, sub-run, seed, method)
    /** First seed, point 0, sub-run 0: the data set and the runs with their
     * paths and maps (figures). */
    std::optional<TDataSet> firstData;
    std::vector<TRunResult> firstRuns;
};

/** What the whole invocation was. */
struct TMeta {
    std::vector<uint64_t> seeds;
    bool quick = false;
    std::string commandLine;
    std::string revision;           //!< source revision (--revision), for the record
    std::vector<std::string> sets;  //!< the --set edits, as given
    double wallSeconds = 0;
};

/** Mean and sample standard deviation over seeds. */
struct TStat {
    double mean = kNaN, sd = kNaN;
    size_t n = 0;
};
TStat statOf(const std::vector<double>& v);

using TGetter = std::function<double(const TRunResult&)>;

/** For each seed, `get` averaged over the sub-runs of (point, method); NaN
 * values are left out. */
std::vector<double> perSeed(const TRowResults& r, size_t point, const std::string& method,
                            const TGetter& get);
/** Largest value of `get` over every sub-run and seed of (point, method). */
double maxOver(const TRowResults& r, size_t point, const std::string& method,
               const TGetter& get);

/** Getters, SI units. */
double robotMeanDist(const TRunResult& r);
double tagMeanDist(const TRunResult& r);

}  // namespace rfir::experiments
