/* rfir-ir-experiments: runs and aggregation. */
#include <rfir/irexp/runs.h>

#include <rfir/localize/localize_config.h>
#include <rfir/localize/localize_output.h>
#include <rfir/localize/localize_run.h>

#include <rfir/common/ini_override.h>
#include <rfir/common/map_io.h>
#include <rfir/sim/simulator.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

namespace rfir::irexp {
namespace fs = std::filesystem;

namespace {
std::string join(const std::vector<std::string>& v, const char* sep) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
    return s;
}

std::vector<std::string> simSets(const TExperimentRun& s, const TRunSpec& spec) {
    std::vector<std::string> v = spec.simSets;
    v.insert(v.end(), s.simSets.begin(), s.simSets.end());
    return v;
}

/** The simulated data set of (ini, sets, seed), written once. */
std::string dataset(const TExperimentRun& s, const TRunSpec& spec, uint64_t seed) {
    // The INI's text is part of the key: an edited INI is simulated anew.
    std::ifstream ini(s.configDir + "/" + spec.simIni);
    std::stringstream text;
    text << ini.rdbuf();
    const std::vector<std::string> sets = simSets(s, spec);
    const std::string key = spec.simIni + "|" + text.str() + "|" + join(sets, ";") + "|" +
                            std::to_string(seed);
    const std::string dir =
        s.workDir + "/data/" + std::to_string(std::hash<std::string>()(key));
    if (!fs::exists(dir + "/run.rawlog")) {
        fs::create_directories(dir);
        const auto cfg = rfir::sim::loadSimConfig(s.configDir + "/" + spec.simIni, sets);
        rfir::sim::writeOutputs(rfir::sim::simulate(cfg, seed), dir, "run");
    }
    return dir;
}

/** The ground-truth emitters minus the absent IDs. */
std::string emitterFile(const std::string& dir, const std::vector<std::string>& absent) {
    if (absent.empty()) return dir + "/run.gt_map.txt";
    const std::string f = dir + "/emitters_without_" + join(absent, "_") + ".txt";
    if (fs::exists(f)) return f;
    rfir::common::TMapFile m;
    for (const auto& e : rfir::common::loadMapFile(dir + "/run.gt_map.txt"))
        if (e.kind == rfir::common::TMapEntry::Kind::Emitter &&
            std::find(absent.begin(), absent.end(), e.id) == absent.end())
            m.push_back(e);
    rfir::common::saveMapFile(f, m);
    return f;
}

void score(const rfir::localize::TRunResult& res, const std::string& dir,
           TRunMetrics& m) {
    const auto gt = rfir::common::loadTUM(dir + "/run.gt.tum");
    if (res.path.empty()) return;
    const double t0 = gt.front().t;
    m.started = true;
    m.tStart = res.path.front().t - t0;
    const auto e = rfir::eval::computeRobotErrors(res.path, gt);
    m.path = e.stats;
    std::vector<rfir::eval::TPoseError> late;
    for (const auto& q : e.perPose)
        if (q.t > res.path.front().t + 10) late.push_back(q);
    if (!late.empty()) m.settled = rfir::eval::statsOf(late);
    if (fs::exists(dir + "/run.spots.tum")) {
        const auto spots = rfir::common::loadTUM(dir + "/run.spots.tum");
        const auto est = rfir::localize::atSpots(res.path, spots);
        if (!est.empty()) {
            const auto se = rfir::eval::computeRobotErrors(est, spots);
            m.spots = se.stats;
            std::vector<rfir::eval::TPoseError> later;
            for (const auto& q : se.perPose)
                if (q.t > res.path.front().t + 10) later.push_back(q);
            if (!later.empty()) m.spotsSettled = rfir::eval::statsOf(later);
        }
    }
}
}  // namespace

TRunMetrics runOne(const TExperimentRun& s, const TRunSpec& spec, uint64_t seed,
                   const std::string& outDir) {
    const std::string dir = dataset(s, spec, seed);
    rfir::localize::TConfig cfg;
    cfg.iniPath = s.configDir + "/ir_localize.ini";
    cfg.rawlogPath = dir + "/run.rawlog";
    cfg.seed = seed;
    cfg.odometryOnly = spec.odometryOnly;
    cfg.quiet = true;
    cfg.overrides = spec.locSets;
    cfg.overrides.insert(cfg.overrides.end(), s.locSets.begin(), s.locSets.end());
    cfg.outDir = outDir;
    rfir::localize::loadConfig(cfg, emitterFile(dir, spec.absentIds));
    const auto gt = rfir::common::loadTUM(dir + "/run.gt.tum");
    const auto res = rfir::localize::runLocalization(cfg, gt.front().pose);
    TRunMetrics m;
    m.resetEvents = res.resetEvents;
    m.seconds = res.seconds;
    score(res, dir, m);
    if (!outDir.empty()) {
        fs::create_directories(outDir);
        rfir::localize::writeOutputs(cfg, res, "rfir-ir-experiments");
    }
    return m;
}

std::vector<TRunMetrics> runSeeds(const TExperimentRun& s, const TRunSpec& spec, int n,
                                  uint64_t offset) {
    std::vector<TRunMetrics> out;
    for (int k = 0; k < n; k++)
        out.push_back(runOne(s, spec, s.firstSeed + offset + uint64_t(k)));
    return out;
}

namespace {
void accumulate(rfir::eval::TErrorStats& a, const rfir::eval::TErrorStats& b, size_t n) {
    a.count += b.count;
    a.mean_dx += b.mean_dx / n;
    a.mean_dy += b.mean_dy / n;
    a.mean_dtheta += b.mean_dtheta / n;
    a.mean_dist += b.mean_dist / n;
    a.max_dx = std::max(a.max_dx, b.max_dx);
    a.max_dy = std::max(a.max_dy, b.max_dy);
    a.max_dtheta = std::max(a.max_dtheta, b.max_dtheta);
    a.max_dist = std::max(a.max_dist, b.max_dist);
}
}  // namespace

TAggregate aggregate(const std::vector<TRunMetrics>& runs) {
    TAggregate a;
    a.runs = runs.size();
    for (const auto& r : runs) a.started += r.started;
    size_t np = 0, ns = 0, nq = 0, nqs = 0;
    for (const auto& r : runs) {
        np += bool(r.path);
        ns += bool(r.settled);
        nq += bool(r.spots);
        nqs += bool(r.spotsSettled);
    }
    for (const auto& r : runs) {
        if (r.path) accumulate(a.path, *r.path, np);
        if (r.settled) accumulate(a.settled, *r.settled, ns);
        if (r.spots) accumulate(a.spots, *r.spots, nq);
        if (r.spotsSettled) accumulate(a.spotsSettled, *r.spotsSettled, nqs);
        if (r.started) a.meanStart += r.tStart / double(a.started);
    }
    a.hasPath = np > 0;
    a.hasSpots = nq > 0;
    return a;
}

void setEdits(TExperimentRun& s, const std::vector<std::string>& sets) {
    const auto split = rfir::common::routeIniEdits(
        {{"sim", "simulation INIs", rfir::sim::simConfigSections()},
         {"localize", "localization INI", rfir::localize::configSections()}},
        sets);
    s.simSets = split[0];
    s.locSets = split[1];
    // The simulation INIs the experiments use (tables.cpp, tables2.cpp).
    static const char* kSimInis[] = {"sim_ir_loop.ini",        "sim_ir_exp_strip.ini",
                                     "sim_ir_unique_only.ini", "sim_ir_rotation.ini",
                                     "sim_ir_failed.ini",      "sim_ir_raw.ini"};
    // An edit an INI refuses is a command-line error naming it; an INI's own
    // error names the file.
    rfir::common::loadWithIniEdits(s.simSets, [&](const std::vector<std::string>& e) {
        for (const char* f : kSimInis) rfir::sim::loadSimConfig(s.configDir + "/" + f, e);
    });
    rfir::common::loadWithIniEdits(s.locSets, [&](const std::vector<std::string>& e) {
        rfir::localize::TConfig cfg;
        cfg.iniPath = s.configDir + "/ir_localize.ini";
        cfg.overrides = e;
        rfir::localize::loadConfig(cfg, "", false);
    });
}

void progress(const TExperimentRun& s, const std::string& what) {
    if (s.verbose) std::cerr << "rfir-ir-experiments: " << what << "\n";
}

}  // namespace rfir::irexp
