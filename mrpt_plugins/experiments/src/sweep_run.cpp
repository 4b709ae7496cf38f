/* rfir-experiments: one run of a sweep (a row on one seed) into its folder:
 * run.json holds each method's results.json entry and its timings apart. */
#include <rfir/experiments/report.h>
#include <rfir/experiments/sweep.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/json.h>
#include <rfir/common/output_set.h>

#include <chrono>
#include <cmath>
#include <ostream>

namespace rfir::experiments {
namespace {
using rfir::common::printed;
using rfir::common::TJson;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/** The run's entry of results.json: every number but the timings. */
TJson entryJson(const TRow& row, const TRunResult& r) {
    TJson j;
    j["point"] = row.points[r.point].label;
    j["x"] = printed(row.points[r.point].x);
    j["run"] = row.runs[r.run].label;
    j["method"] = r.method;
    j["seed"] = r.seed;
    j["steps"] = r.steps;
    j["resets"] = r.resets;
    if (std::isfinite(r.beforeKidnap) || std::isfinite(r.afterKidnap)) {
        j["before_kidnap_mean_dist"] = printed(r.beforeKidnap);
        j["after_kidnap_mean_dist"] = printed(r.afterKidnap);
        j["recovery_time"] = printed(r.recoveryTime);
    }
    j["errors"] = TJson::parse(rfir::eval::toJson(r.eval));  // as errors.json has it
    return j;
}

TJson runFileJson(const TRow& row, uint64_t seed, const std::string& fingerprint,
                  const std::vector<TRunResult>& runs, double seconds) {
    TJson j;
    j["generator"] = "rfir-experiments --run";
    j["row"] = row.id;
    j["seed"] = seed;
    j["fingerprint"] = fingerprint;
    j["seconds"] = printed(seconds);
    j["runs"] = TJson::array();
    for (const auto& r : runs) {
        TJson t;
        t["ms_per_step"] = printed(r.msPerStep);
        t["max_step_ms"] = printed(r.maxStepMs);
        t["total_s"] = printed(r.totalSeconds);
        j["runs"].push_back({{"point", r.point},
                             {"run", r.run},
                             {"result", entryJson(row, r)},
                             {"timing", t}});
    }
    return j;
}
}  // namespace

void runToFolder(const TSetup& setup, const TMeta& meta, const TRow& row, uint64_t seed,
                 bool figures, const std::string& folder, FILE* log) {
    rfir::common::COutputFolder out(folder, {"run.json", "exp_*.png"},
                                    "rfir-experiments --run");
    const auto t0 = Clock::now();
    std::vector<TRunResult> runs;
    for (size_t p = 0; p < row.points.size(); p++)
        for (size_t k = 0; k < row.runs.size(); k++) {
            const auto t1 = Clock::now();
            const auto data = simulateDataSet(setup, row.runs[k], row.points[p], seed);
            const bool first = figures && p == 0 && k == 0;  // what the figures show
            if (log) {
                std::string name = row.id;
                for (const auto* l : {&row.points[p].label, &row.runs[k].label})
                    if (!l->empty()) name += " " + *l;
                std::fprintf(log, "%s seed %llu (%zu steps):", name.c_str(),
                             (unsigned long long)seed, data.sim.steps.size());
            }
            std::vector<TRunResult> shown;
            for (const auto& m : row.methods) {
                auto r = runMethod(setup, data, m, row.points[p], seed, first);
                r.point = p;
                r.run = k;
                if (log)
                    std::fprintf(log, " %s %.0f/%.0f mm", m.label.c_str(),
                                 1e3 * robotMeanDist(r), 1e3 * tagMeanDist(r));
                if (first) shown.push_back(r);
                r.estPath.clear();
                r.estMap.clear();
                r.eval.robot->perPose.clear();
                runs.push_back(std::move(r));
            }
            if (log) std::fprintf(log, " (%.1f s)\n", since(t1));
            if (first)
                writeFirstSeedFigures([&](const std::string& n) { return out.file(n); },
                                      row, data, shown);
        }
    const TJson j =
        runFileJson(row, seed, runFingerprint(setup, meta, row, seed), runs, since(t0));
    rfir::common::writeFileAtomically(out.file("run.json"), [&](std::ostream& o) {
        o << rfir::common::dumpJson(j) << "\n";
    });
    out.commit();
}

}  // namespace rfir::experiments
