/* rfir-experiments: the runs of a sweep read back from their folders, checked
 * against the sweep (fingerprint) before any of them is used. */
#include <rfir/experiments/sweep.h>

#include <rfir/common/install_paths.h>
#include <rfir/common/json.h>
#include <rfir/common/output_set.h>
#include <rfir/common/text_input.h>

#include <mrpt/system/filesystem.h>
#include <mrpt/system/md5.h>

#include <fstream>
#include <set>
#include <stdexcept>

namespace rfir::experiments {
namespace {
using rfir::common::TJson;
using TKind = rfir::common::TMapEntry::Kind;

/** A number as printed() wrote it: null (NaN, infinity) or absent is NaN. */
double num(const TJson& j, const char* key) {
    const auto it = j.find(key);
    return it == j.end() || it->is_null() ? kNaN : it->get<double>();
}

rfir::eval::TErrorStats statsOf(const TJson& j, const char* countKey) {
    rfir::eval::TErrorStats s;
    s.count = j.at(countKey).get<size_t>();
    s.mean_dx = num(j, "mean_dx"), s.mean_dy = num(j, "mean_dy");
    s.mean_dtheta = num(j, "mean_dtheta"), s.mean_dist = num(j, "mean_dist");
    s.max_dx = num(j, "max_dx"), s.max_dy = num(j, "max_dy");
    s.max_dtheta = num(j, "max_dtheta"), s.max_dist = num(j, "max_dist");
    s.rmse_dist = num(j, "rmse_dist"), s.rmse_dtheta = num(j, "rmse_dtheta");
    return s;
}

/** The numbers results.md and the plots use, from a run's entry (errors as
 * rfir::eval::toJson writes them) and its timings. */
TRunResult runOf(const TJson& x) {
    const TJson& e = x.at("result");
    TRunResult r;
    r.point = x.at("point").get<size_t>();
    r.run = x.at("run").get<size_t>();
    r.method = e.at("method").get<std::string>();
    r.seed = e.at("seed").get<uint64_t>();
    r.steps = e.at("steps").get<size_t>();
    r.resets = e.at("resets").get<size_t>();
    r.beforeKidnap = num(e, "before_kidnap_mean_dist");
    r.afterKidnap = num(e, "after_kidnap_mean_dist");
    r.recoveryTime = num(e, "recovery_time");
    const TJson& t = x.at("timing");
    r.msPerStep = num(t, "ms_per_step"), r.maxStepMs = num(t, "max_step_ms");
    r.totalSeconds = num(t, "total_s");
    const TJson& err = e.at("errors");
    r.eval.label = err.at("label").get<std::string>();
    r.eval.robot.emplace().stats = statsOf(err.at("robot"), "poses");
    for (const auto& [key, kind] : {std::pair{"tags", TKind::Tag},
                                    {"landmarks", TKind::Landmark},
                                    {"emitters", TKind::Emitter}}) {
        if (!err.contains(key)) continue;
        const std::string k = key;
        auto& m = r.eval.map.emplace();
        m.kind = kind;
        m.stats = statsOf(err.at(k), "count");
        m.mapped = err.at(k + "_mapped").get<size_t>();
        m.total = err.at(k + "_total").get<size_t>();
        if (!err.at(k + "_passed_over").is_null())
            m.passedOver = err.at(k + "_passed_over").get<size_t>();
        if (!err.at(k + "_mapped_of_passed_over").is_null())
            m.mappedOfPassedOver = err.at(k + "_mapped_of_passed_over").get<size_t>();
    }
    if (!r.eval.map) throw std::runtime_error("a run without map errors");
    r.entry = rfir::common::dumpJson(e);
    return r;
}

/** One run's folder: its run.json checked against the sweep. */
TJson readRun(const std::string& dir, const TSweepRun& run, const TSetup& setup,
              const TMeta& meta) {
    const std::string path = runFolder(dir, run) + "/run.json";
    const std::string what = "run " + runName(run) + " (" + path + ")";
    TJson j;
    try {
        std::ifstream in;
        rfir::common::openTextInput(in, path, "run.json");
        j = TJson::parse(in);
    } catch (const std::exception& e) {
        throw std::runtime_error(what + ": cannot read it: " + e.what());
    }
    const std::string want = runFingerprint(setup, meta, *run.row, run.seed);
    if (!j.is_object() || j.value("row", "") != run.row->id ||
        j.value("seed", uint64_t(0)) != run.seed || j.value("fingerprint", "") != want)
        throw std::runtime_error(
            what +
            " comes from another sweep (other INIs, --set edits, --quick or "
            "rfir version): fingerprint " +
            j.value("fingerprint", "?") + ", this sweep's " + want);
    return j;
}
}  // namespace

std::string runFingerprint(const TSetup& setup, const TMeta& meta, const TRow& row,
                           uint64_t seed) {
    std::set<std::string> inis;
    for (const auto& k : row.runs) inis.insert(setup.configDir + "/" + k.simIni);
    for (const auto& m : row.methods)
        inis.insert(rfir::common::slamIniPath(setup.configDir, m.method));
    std::string text = "rfir " + rfir::common::rfirVersion() + "\nrow " + row.id +
                       "\nseed " + std::to_string(seed) + "\nquick " +
                       (meta.quick ? "1" : "0") + "\n";
    for (const auto& s : meta.sets) text += "set " + s + "\n";
    for (const auto& f : inis)
        text += "ini " + mrpt::system::extractFileName(f) + " " +
                rfir::common::fileMD5(f) + "\n";
    return mrpt::system::md5(text);
}

std::vector<TRowResults> loadRuns(const std::string& dir, const std::vector<TRow>& rows,
                                  const TSetup& setup, const TMeta& meta) {
    const auto all = sweepRuns(rows, meta.seeds);
    std::string missing;
    size_t nMissing = 0;
    for (const auto& run : all)
        if (!mrpt::system::fileExists(runFolder(dir, run) + "/run.json") &&
            nMissing++ < 5)
            missing += "\n  " + runName(run) + ": " + runFolder(dir, run) + "/run.json";
    if (nMissing)
        throw std::runtime_error(
            std::to_string(nMissing) + " of the sweep's " + std::to_string(all.size()) +
            " runs " + (nMissing == 1 ? "has" : "have") + " no output in " + dir +
            " (run their commands of the manifest):" + missing +
            (nMissing > 5 ? "\n  ..." : ""));
    std::vector<TJson> files;
    for (const auto& run : all) files.push_back(readRun(dir, run, setup, meta));
    std::vector<TRowResults> out;
    size_t f = 0;
    for (const auto& row : rows) {
        TRowResults rr;
        rr.row = row;
        // This row's runs, then in a sweep's order: point, sub-run, seed, method.
        std::vector<std::vector<TRunResult>> bySeed;
        for (; f < all.size() && all[f].row->id == row.id; f++) {
            const auto what =
                "run " + runName(all[f]) + " (" + runFolder(dir, all[f]) + "/run.json)";
            rr.runSeconds += files[f].value("seconds", 0.0);
            bySeed.emplace_back();
            try {
                for (const auto& x : files[f].at("runs")) {
                    bySeed.back().push_back(runOf(x));
                    const auto& r = bySeed.back().back();
                    if (r.point >= row.points.size() || r.run >= row.runs.size() ||
                        r.seed != all[f].seed)
                        throw std::runtime_error(
                            "a run of another point, sub-run or seed");
                }
                const size_t n = row.points.size() * row.runs.size() * row.methods.size();
                if (bySeed.back().size() != n)
                    throw std::runtime_error(std::to_string(bySeed.back().size()) +
                                             " runs, expected " + std::to_string(n));
            } catch (const std::exception& e) {
                throw std::runtime_error(what + ": malformed: " + e.what());
            }
        }
        for (size_t p = 0; p < row.points.size(); p++)
            for (size_t k = 0; k < row.runs.size(); k++)
                for (const auto& runs : bySeed)
                    for (const auto& r : runs)
                        if (r.point == p && r.run == k) rr.runs.push_back(r);
        out.push_back(std::move(rr));
    }
    return out;
}

}  // namespace rfir::experiments
