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
    double runSeconds = 0;         //!< wall time of its runs, summed
};

/** What the whole invocation was. */
struct TMeta {
    std::vector<uint64_t> seeds;
    bool quick = false;
    /** The options that decide the numbers (rows, seeds, --quick, --set), the
     * same however the sweep ran (sweepCommand). */
    std::string commandLine;
    std::string invocation;         //!< the command line as given (timings.json)
    std::string revision;           //!< source revision (--revision), for the record
    std::vector<std::string> sets;  //!< the --set edits, as given
    // Timings: timings.json and the results.md header only.
    unsigned jobs = 1;  //!< processes; 0: merged from run folders (--merge)
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
