/* rfir-experiments: results.json, every raw number (SI units: m, rad, s). */
#include <rfir/experiments/report.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/json.h>

#include <cmath>
#include <ostream>

namespace rfir::experiments {
namespace {
using rfir::common::printed;
using rfir::common::TJson;

TJson runJson(const TRow& row, const TRunResult& r) {
    TJson j;
    j["point"] = row.points[r.point].label;
    j["x"] = printed(row.points[r.point].x);
    j["run"] = row.runs[r.run].label;
    j["method"] = r.method;
    j["seed"] = r.seed;
    j["steps"] = r.steps;
    j["ms_per_step"] = printed(r.msPerStep);
    j["max_step_ms"] = printed(r.maxStepMs);
    j["total_s"] = printed(r.totalSeconds);
    j["resets"] = r.resets;
    if (std::isfinite(r.beforeKidnap) || std::isfinite(r.afterKidnap)) {
        j["before_kidnap_mean_dist"] = printed(r.beforeKidnap);
        j["after_kidnap_mean_dist"] = printed(r.afterKidnap);
        j["recovery_time"] = printed(r.recoveryTime);
    }
    j["errors"] = TJson::parse(rfir::eval::toJson(r.eval));  // as errors.json has it
    return j;
}

TJson rowJson(const TRowResults& rr) {
    const TRow& row = rr.row;
    TJson j;
    j["id"] = row.id;
    j["title"] = row.title;
    j["source"] = row.source;
    j["seed_claim"] = row.seedClaim;
    TJson seeds = TJson::array();
    for (const auto& s : row.seedNumbers) {
        TJson e;
        e["method"] = s.label;
        e["x"] = printed(s.x);
        e["y"] = printed(s.y);
        e["theta_rad"] = printed(s.theta);
        e["dr"] = printed(s.dr);
        e["tx"] = printed(s.tx);
        e["ty"] = printed(s.ty);
        e["dt"] = printed(s.dt);
        e["note"] = s.note;
        seeds.push_back(e);
    }
    j["seed_numbers_mm"] = seeds;
    j["runs"] = TJson::array();
    for (const auto& r : rr.runs) j["runs"].push_back(runJson(row, r));
    return j;
}
}  // namespace

void writeJson(const std::string& path, const std::vector<TRowResults>& rows,
               const TMeta& meta) {
    TJson j;
    j["generator"] = "rfir-experiments";
    j["command"] = meta.commandLine;
    j["quick"] = meta.quick;
    j["seeds"] = meta.seeds;
    j["ini_edits"] = meta.sets;
    j["wall_seconds"] = printed(meta.wallSeconds);
    j["rows"] = TJson::array();
    for (const auto& r : rows) j["rows"].push_back(rowJson(r));
    rfir::common::writeFileAtomically(
        path, [&](std::ostream& o) { o << rfir::common::dumpJson(j) << "\n"; });
}

}  // namespace rfir::experiments
