/* rfir-localize: the output files. */
#include <rfir/common/install_paths.h>
#include <rfir/localize/localize_output.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/json_text.h>
#include <rfir/common/map_io.h>
#include <rfir/common/output_set.h>
#include <rfir/eval/metrics.h>
#include <rfir/eval/plot.h>
#include <rfir/eval/report.h>

#include <filesystem>
#include <iomanip>
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
    if (!fs::exists(stem + ".gt.tum")) return ev;
    ev.gt = rfir::common::loadTUM(stem + ".gt.tum");
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

std::string lostJson(const TRunResult& res) {
    std::ostringstream o;
    o << std::setprecision(10) << "[";
    for (size_t i = 0; i < res.lost.size(); i++) {
        const auto& l = res.lost[i];
        o << (i ? ", " : "") << "{\"t\": " << l.t
          << ", \"emitter\": " << rfir::common::jsonString(l.id) << ", \"recovered_t\": ";
        if (l.settled)
            o << *l.settled;
        else
            o << "null";
        o << "}";
    }
    o << "]";
    return o.str();
}

std::string idsJson(const TConfig& cfg, const TRunResult& res, S status) {
    std::string o = "[";
    const auto& em = cfg.map->emitters().emitters();
    for (size_t i = 0; i < res.emitterHealth.size() && i < em.size(); i++)
        if (res.emitterHealth[i].status == status)
            o += std::string(o.size() > 1 ? ", " : "") +
                 rfir::common::jsonString(em[i].id);
    return o + "]";
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
    std::ostringstream o;
    o << std::setprecision(10) << "{\n"
      << "  \"rawlog\": " << rfir::common::jsonString(cfg.rawlogPath) << ",\n"
      << "  \"emitters\": " << rfir::common::jsonString(cfg.emitterPath) << ",\n"
      << "  \"mode\": \"" << (cfg.odometryOnly ? "odometry-only" : "monte-carlo")
      << "\",\n"
      << "  \"seed\": " << cfg.seed << ",\n"
      << "  \"num_particles\": " << cfg.params.numParticles << ",\n"
      << "  \"association\": \""
      << (cfg.map->likelihoodOptions.association ==
                  rfir::maps::CIREmitterMap::TAssociation::Estimate
              ? "estimate"
              : "particle")
      << "\",\n"
      << "  \"instants\": " << res.steps << ",\n"
      << "  \"ir_observations\": " << res.irObservations << ",\n"
      << "  \"readings\": " << res.readings << ",\n"
      << "  \"readings_used\": " << res.used << ",\n"
      << "  \"unknown_ids\": " << res.unknownIds << ",\n"
      << "  \"raw_windows_decoded\": " << res.decoded << ",\n"
      << "  \"first_unique_time\": "
      << (res.firstUniqueTime ? std::to_string(*res.firstUniqueTime) : "null") << ",\n"
      << "  \"poses\": " << res.path.size() << ",\n"
      << "  \"reset_events\": " << res.resetEvents << ",\n"
      << "  \"reset_particles\": " << res.resetParticles << ",\n"
      << "  \"gated_readings\": " << res.gated << ",\n"
      << "  \"lost_events\": " << lostJson(res) << ",\n"
      << "  \"emitters_failed\": " << idsJson(cfg, res, S::Failed) << ",\n"
      << "  \"emitters_inconsistent\": " << idsJson(cfg, res, S::Inconsistent) << ",\n"
      << "  \"odometry_start\": " << rfir::common::jsonString(res.odometryStart) << ",\n"
      << "  \"filter_seconds\": " << res.seconds << ",\n  \"run\": " << identity;
    for (size_t i = 0; i < ev.rows.size(); i++)
        o << ",\n  \"" << (i == 0 ? "path_errors" : "spot_errors")
          << "\": " << rfir::eval::toJson(ev.rows[i]);
    o << "\n}\n";
    return o.str();
}

void plot(const TConfig& cfg, const TRunResult& res, const TEvals& ev,
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
}
}  // namespace

std::string writeOutputs(const TConfig& cfg, const TRunResult& res,
                         const std::string& commandLine) {
    // One set per run: staged beside --out-dir and renamed into place, so a
    // stale errors.txt of a run with ground truth cannot outlive it.
    rfir::common::COutputFolder out(cfg.outDir,
                                    {"path.tum", "stats.json", "settings.ini",
                                     "errors.txt", "path.png", "emitter_health.txt"},
                                    "rfir-localize");
    const TEvals ev = evaluate(cfg, res);
    std::string table;
    if (!ev.rows.empty()) table = rfir::eval::formatErrorTable(ev.rows);
    rfir::common::saveTUM(out.file("path.tum"), res.path);
    if (!table.empty())
        rfir::common::writeFileAtomically(out.file("errors.txt"),
                                          [&](std::ostream& o) { o << table; });
    plot(cfg, res, ev, out.file("path.png"));
    if (!cfg.odometryOnly) writeEmitterReport(cfg, res, out.file("emitter_health.txt"));
    const std::string stats = out.file("stats.json"), settings = out.file("settings.ini");
    const auto files = out.files();
    std::string list;
    for (const auto& f : files) list += " " + f;
    const std::string id = rfir::common::runIdentityJson(cfg.seed, cfg.iniPath, files);
    rfir::common::writeFileAtomically(
        stats, [&](std::ostream& o) { o << statsJson(cfg, res, ev, id); });
    rfir::common::writeFileAtomically(settings, [&](std::ostream& o) {
        o << "# rfir-localize " << rfir::common::rfirVersion() << "; INI " << cfg.iniPath
          << " (md5 " << rfir::common::fileMD5(cfg.iniPath) << "); files:" << list << "\n"
          << settingsIni(cfg, commandLine);
    });
    out.commit();
    return table;
}

}  // namespace rfir::localize
