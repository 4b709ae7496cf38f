/* rfir-experiments: results.json, every raw number (SI units: m, rad, s), and
 * timings.json, the times of the same runs. */
#include <rfir/experiments/report.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/json.h>

#include <cmath>
#include <ostream>

namespace rfir::experiments {
namespace {
using rfir::common::printed;
using rfir::common::TJson;

TJson rowJson(const TRowResults& rr) {
    const TRow& row = rr.row;
    TJson j;
    j["id"] = row.id;
    j["title"] = row.title;
    j["source"] = row.source;
    j["paper_claim"] = row.paperClaim;
    TJson paper = TJson::array();
    for (const auto& s : row.paperNumbers) {
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
        paper.push_back(e);
    }
    j["paper_numbers_mm"] = paper;
    j["runs"] = TJson::array();
    for (const auto& r : rr.runs) j["runs"].push_back(TJson::parse(r.entry));
    return j;
}

TJson timingJson(const TRow& row, const TRunResult& r) {
    TJson j;
    j["point"] = row.points[r.point].label;
    j["run"] = row.runs[r.run].label;
    j["method"] = r.method;
    j["seed"] = r.seed;
    j["ms_per_step"] = printed(r.msPerStep);
    j["max_step_ms"] = printed(r.maxStepMs);
    j["total_s"] = printed(r.totalSeconds);
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
    j["rows"] = TJson::array();
    for (const auto& r : rows) j["rows"].push_back(rowJson(r));
    rfir::common::writeFileAtomically(
        path, [&](std::ostream& o) { o << rfir::common::dumpJson(j) << "\n"; });
}

void writeTimings(const std::string& path, const std::vector<TRowResults>& rows,
                  const TMeta& meta) {
    TJson j;
    j["generator"] = "rfir-experiments";
    j["command"] = meta.invocation;
    j["processes"] = meta.jobs;  // 0: merged (--merge)
    j["wall_seconds"] = printed(meta.wallSeconds);
    double runs = 0;
    for (const auto& r : rows) runs += r.runSeconds;
    j["runs_seconds"] = printed(runs);
    j["rows"] = TJson::array();
    for (const auto& r : rows) {
        TJson row;
        row["id"] = r.row.id;
        row["runs_seconds"] = printed(r.runSeconds);
        row["runs"] = TJson::array();
        for (const auto& x : r.runs) row["runs"].push_back(timingJson(r.row, x));
        j["rows"].push_back(row);
    }
    rfir::common::writeFileAtomically(
        path, [&](std::ostream& o) { o << rfir::common::dumpJson(j) << "\n"; });
}

}  // namespace rfir::experiments
