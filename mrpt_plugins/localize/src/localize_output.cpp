/* rfir-localize: the output files. */
#include <rfir/common/ini_key_docs.h>
#include <rfir/common/install_paths.h>
#include <rfir/localize/localize_output.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/json.h>
#include <rfir/common/map_io.h>
#include <rfir/common/output_set.h>
#include <rfir/eval/compare.h>
#include <rfir/eval/metrics.h>
#include <rfir/eval/plot.h>
#include <rfir/eval/report.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace rfir::localize {
namespace fs = std::filesystem;
using rfir::common::TPath2D;

/** The path's pose at each spot time (the latest pose not after it). */
TPath2D atSpots(const TPath2D& path, const TPath2D& spots) {
    TPath2D out;
    size_t k = 0;
    for (const auto& s : spots) {
        while (k < path.size() && path[k].t <= s.t + 1e-6) k++;
        if (k > 0) out.push_back({s.t, path[k - 1].pose});
    }
    return out;
}

namespace {
struct TEvals {
    std::vector<rfir::eval::TEvalResult> rows;
    std::optional<TPath2D> gt;
    std::optional<TPath2D> odoAligned;
};

TEvals evaluate(const TConfig& cfg, const TRunResult& res) {
    TEvals ev;
    const std::string stem = rfir::common::rawlogStem(cfg.rawlogPath);
    if (cfg.gtPath.empty()) return ev;
    ev.gt = rfir::common::loadTUM(cfg.gtPath);
    const std::string label = cfg.odometryOnly ? "odometry only" : "IR MCL";
    rfir::eval::TEvalResult traj;
    traj.label = label + " (path)";
    if (!res.path.empty()) traj.robot = rfir::eval::computeRobotErrors(res.path, *ev.gt);
    ev.odoAligned = rfir::eval::alignOdometryAtStart(res.odometry, *ev.gt);
    if (!cfg.odometryOnly)
        traj.odometry = rfir::eval::computeRobotErrors(*ev.odoAligned, *ev.gt);
    ev.rows.push_back(traj);
    if (fs::exists(stem + ".spots.tum")) {
        const auto spots = rfir::common::loadTUM(stem + ".spots.tum");
        rfir::eval::TEvalResult sp;
        sp.label = label + " (spots)";
        const auto est = atSpots(res.path, spots);
        if (!est.empty()) sp.robot = rfir::eval::computeRobotErrors(est, spots);
        if (!cfg.odometryOnly)
            sp.odometry =
                rfir::eval::computeRobotErrors(atSpots(*ev.odoAligned, spots), spots);
        ev.rows.push_back(sp);
    }
    return ev;
}

using S = rfir::ir::TEmitterHealth::Status;

using rfir::common::printed;
using rfir::common::TJson;

TJson lostJson(const TRunResult& res) {
    TJson a = TJson::array();
    for (const auto& l : res.lost) {
        TJson e;
        e["t"] = printed(l.t, "%.10g");
        e["emitter"] = l.id;
        e["recovered_t"] = l.settled ? printed(*l.settled, "%.10g") : TJson();
        a.push_back(e);
    }
    return a;
}

TJson idsJson(const TConfig& cfg, const TRunResult& res, S status) {
    TJson a = TJson::array();
    const auto& em = cfg.map->emitters().emitters();
    for (size_t i = 0; i < res.emitterHealth.size() && i < em.size(); i++)
        if (res.emitterHealth[i].status == status) a.push_back(em[i].id);
    return a;
}

/** One line per emitter of the map: what the localizer made of it. */
void writeEmitterReport(const TConfig& cfg, const TRunResult& res,
                        const std::string& path) {
    rfir::common::writeFileAtomically(path, [&](std::ostream& o) {
        o << "# rfir-localize emitter report (docs/ir.md): id x y z readings gated "
             "checks answered status weight\n"
          << "# readings: attributed to it while the track was confident; gated: of "
             "which inconsistent with the motion prior (not used); checks: times the "
             "estimate put a receiver within emitter_check_radius of it; answered: of "
             "which that receiver read its ID\n"
          << std::setprecision(10);
        const auto& em = cfg.map->emitters().emitters();
        for (size_t i = 0; i < em.size(); i++) {
            const rfir::ir::TEmitterHealth h = i < res.emitterHealth.size()
                                                   ? res.emitterHealth[i]
                                                   : rfir::ir::TEmitterHealth{};
            o << em[i].id << " " << em[i].x << " " << em[i].y << " " << em[i].z << " "
              << h.readings << " " << h.gated << " " << h.checks << " " << h.answered
              << " " << rfir::ir::statusName(h.status) << " " << h.weight << "\n";
        }
    });
}

std::string statsJson(const TConfig& cfg, const TRunResult& res, const TEvals& ev,
                      const std::string& identity) {
    const bool estimate = cfg.map->likelihoodOptions.association ==
                          rfir::maps::CIREmitterMap::TAssociation::Estimate;
    TJson j;
    j["rawlog"] = cfg.rawlogPath;
    j["emitters"] = cfg.emitterPath;
    j["mode"] = cfg.odometryOnly ? "odometry-only" : "monte-carlo";
    j["seed"] = cfg.seed;
    j["num_particles"] = cfg.params.numParticles;
    j["association"] = estimate ? "estimate" : "particle";
    j["instants"] = res.steps;
    j["ir_observations"] = res.irObservations;
    j["readings"] = res.readings;
    j["readings_used"] = res.used;
    j["unknown_ids"] = res.unknownIds;
    j["raw_windows_decoded"] = res.decoded;
    j["first_unique_time"] =
        res.firstUniqueTime ? printed(*res.firstUniqueTime, "%f") : TJson();
    j["start_history_readings"] = res.startHistoryReadings;
    j["start_pose"] = cfg.params.startFromLog ? "log" : "unknown";
    j["poses"] = res.path.size();
    j["reset_events"] = res.resetEvents;
    j["reset_particles"] = res.resetParticles;
    j["gated_readings"] = res.gated;
    j["lost_events"] = lostJson(res);
    j["emitters_failed"] = idsJson(cfg, res, S::Failed);
    j["emitters_inconsistent"] = idsJson(cfg, res, S::Inconsistent);
    j["odometry_start"] = res.odometryStart;
    j["filter_seconds"] = printed(res.seconds, "%.10g");
    j["run"] = TJson::parse(identity);
    // The error rows as rfir_eval writes them (errors*.json, rfir-eval --json-file).
    for (size_t i = 0; i < ev.rows.size(); i++)
        j[i == 0 ? "path_errors" : "spot_errors"] =
            TJson::parse(rfir::eval::toJson(ev.rows[i]));
    return rfir::common::dumpJson(j) + "\n";
}

/** path_map.png; returns its title. */
std::string plot(const TConfig& cfg, const TRunResult& res, const TEvals& ev,
                 const std::string& png) {
    rfir::eval::TMapFigure fig;
    fig.title =
        std::string(cfg.odometryOnly ? "Odometry only" : "IR Monte Carlo localization") +
        ": " + fs::path(cfg.rawlogPath).filename().string();
    fig.gtPath = ev.gt;
    if (!res.path.empty()) fig.estPath = res.path;
    if (!cfg.odometryOnly) fig.odomPath = ev.odoAligned ? *ev.odoAligned : res.odometry;
    const auto em = rfir::common::emitterEntries(cfg.map->emitters().emitters());
    fig.gtMap.insert(fig.gtMap.end(), em.begin(), em.end());
    rfir::eval::plotMapFigure(png, fig);
    return fig.title;
}
}  // namespace

namespace {
TRunSummary summaryOf(const TConfig& cfg, const TRunResult& res, const TEvals& ev,
                      const std::vector<std::string>& files) {
    TRunSummary s;
    if (!ev.rows.empty()) {
        s.errorTable = rfir::eval::formatErrorTable(ev.rows);
        s.errorsJson = rfir::eval::toJson(ev.rows[0]);
    }
    s.statsJson = statsJson(cfg, res, ev,
                            rfir::common::runIdentityJson(cfg.seed, cfg.iniPath, files));
    return s;
}
}  // namespace

TRunSummary writeOutputs(const TConfig& cfg, const TRunResult& res,
                         const std::string& commandLine) {
    // One set per run: staged beside --out-dir and renamed into place, so a
    // stale errors.json of a run with ground truth cannot outlive it. The
    // names are rfir-slam's where the files are the same.
    rfir::common::COutputFolder out(
        cfg.outDir,
        {"path.tum", "stats.json", "settings.ini", "errors.json", "errors_spots.json",
         "path_map.png", "error_time.png", "emitter_health.txt"},
        "rfir-localize");
    const TEvals ev = evaluate(cfg, res);
    rfir::common::saveTUM(out.file("path.tum"), res.path);
    for (size_t i = 0; i < ev.rows.size(); i++)
        rfir::common::writeFileAtomically(
            out.file(i == 0 ? "errors.json" : "errors_spots.json"),
            [&](std::ostream& o) { o << rfir::eval::toJson(ev.rows[i]) << "\n"; });
    const std::string title = plot(cfg, res, ev, out.file("path_map.png"));
    if (!ev.rows.empty() && ev.rows[0].robot)
        rfir::eval::plotErrorsOverTime(out.file("error_time.png"), ev.rows[0], title);
    if (!cfg.odometryOnly) writeEmitterReport(cfg, res, out.file("emitter_health.txt"));
    const std::string stats = out.file("stats.json"), settings = out.file("settings.ini");
    const auto files = out.files();
    std::string list;
    for (const auto& f : files) list += " " + f;
    const TRunSummary s = summaryOf(cfg, res, ev, files);
    rfir::common::writeFileAtomically(stats, [&](std::ostream& o) { o << s.statsJson; });
    rfir::common::writeFileAtomically(settings, [&](std::ostream& o) {
        o << "# rfir-localize " << rfir::common::rfirVersion() << "; INI " << cfg.iniPath
          << " (md5 " << rfir::common::fileMD5(cfg.iniPath) << "); files:" << list << "\n"
          << rfir::common::annotateIni(settingsIni(cfg, commandLine), "rfir-localize");
    });
    out.commit();
    return s;
}

TRunSummary summarize(const TConfig& cfg, const TRunResult& res) {
    return summaryOf(cfg, res, evaluate(cfg, res), {});
}

TLocalizeJob runLocalizeJob(TConfig& cfg, const std::string& emitters,
                            const std::string& commandLine, const TStepObserver& onStep) {
    const auto gtStart = prepareRun(cfg, emitters);
    if (!cfg.outDir.empty()) {
        std::error_code ec;
        fs::create_directories(cfg.outDir, ec);
        if (!fs::is_directory(cfg.outDir))
            throw std::runtime_error(cfg.outDir + ": cannot create the output directory");
    }
    if (!cfg.quiet)
        std::cerr << "rfir-localize: " << cfg.rawlogPath << ", " << cfg.map->asString()
                  << ", " << (cfg.odometryOnly ? "odometry only" : "M = ")
                  << (cfg.odometryOnly ? "" : std::to_string(cfg.params.numParticles))
                  << ", seed " << cfg.seed << "\n";
    TLocalizeJob job;
    job.run = runLocalization(cfg, gtStart, onStep);
    const TRunResult& res = job.run;
    job.summary =
        cfg.outDir.empty() ? summarize(cfg, res) : writeOutputs(cfg, res, commandLine);
    if (!cfg.quiet)
        std::cerr << "rfir-localize: " << res.steps << " instants, " << res.used << " of "
                  << res.readings << " readings used, " << res.unknownIds
                  << " unknown IDs, first unique ID at "
                  << (res.firstUniqueTime ? std::to_string(*res.firstUniqueTime) + " s"
                                          : "never")
                  << ", " << res.resetEvents << " sensor resets\n";
    // A warning, also under --quiet.
    if (!cfg.odometryOnly && res.path.empty())
        std::cerr << "rfir-localize: warning: no unique-ID reading: no estimate\n";
    return job;
}

}  // namespace rfir::localize
