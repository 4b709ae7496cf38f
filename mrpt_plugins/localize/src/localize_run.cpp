/* rfir-localize: one pass over a rawlog. */
#include <rfir/localize/localize_run.h>

#include <rfir/common/ini_override.h>
#include <rfir/common/install_paths.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/eval/input_formats.h>

#include <filesystem>

#include <chrono>
#include <iostream>

namespace rfir::localize {
namespace {
/** A lost track is worth a line on the console whatever -q says: the path
 * around it is not to be trusted. */
void reportLost(const rfir::ir::TLocalizerStep& info, double t, TRunResult& res) {
    if (info.lost) {
        res.lost.push_back({t, info.lostId, std::nullopt});
        std::cerr << "rfir-localize: t = " << t
                  << " s: track lost (unique IDs contradict it); particles redrawn "
                     "from emitter "
                  << info.lostId << "\n";
    }
    if (info.settled && !res.lost.empty() && !res.lost.back().settled) {
        res.lost.back().settled = t;
        std::cerr << "rfir-localize: t = " << t << " s: track recovered ("
                  << t - res.lost.back().t << " s after it was lost)\n";
    }
}
}  // namespace

std::optional<mrpt::poses::CPose2D> prepareRun(TConfig& cfg,
                                               const std::string& emitters) {
    namespace fs = std::filesystem;
    // A --set edit the INI refuses is a command-line error naming it (checked
    // before the emitter file is required), then the whole configuration.
    rfir::common::loadWithIniEdits(cfg.overrides, [&](const std::vector<std::string>& e) {
        auto c = cfg;
        c.overrides = e;
        loadConfig(c, emitters, false);
    });
    loadConfig(cfg, emitters);
    if (fs::is_directory(cfg.rawlogPath))
        throw std::runtime_error(cfg.rawlogPath + ": is a directory, not a rawlog file");
    if (!fs::is_regular_file(cfg.rawlogPath))
        throw std::runtime_error(cfg.rawlogPath + ": rawlog not found");
    // The ground truth is read before anything is written, so that a bad
    // file fails first; its first pose starts the dead reckoning without a
    // known start.
    const std::string gt = rfir::common::rawlogStem(cfg.rawlogPath) + ".gt.tum";
    if (cfg.gtPath.empty() && fs::exists(gt)) cfg.gtPath = gt;
    if (cfg.gtPath.empty()) return std::nullopt;
    const auto p = rfir::eval::loadTumChecked(cfg.gtPath);
    if (p.empty()) return std::nullopt;
    return p.front().pose;
}

TRunResult runLocalization(const TConfig& cfg,
                           const std::optional<mrpt::poses::CPose2D>& gtStart,
                           const TStepObserver& onStep) {
    TRunResult res;
    rfir::common::CRawlogReader reader(cfg.rawlogPath);
    mrpt::poses::CPose2D odo;
    res.odometryStart = "origin";
    if (reader.header().startPose) {
        odo = *reader.header().startPose;
        res.odometryStart = "header";
    } else if (gtStart) {
        odo = *gtStart;
        res.odometryStart = "ground truth";
    }
    std::unique_ptr<rfir::ir::CIRLocalizer> loc;
    if (!cfg.odometryOnly)
        loc = std::make_unique<rfir::ir::CIRLocalizer>(cfg.map, cfg.params, cfg.seed);
    if (loc && cfg.params.startFromLog) {
        // The robot's own knowledge, never the ground truth.
        if (!reader.header().startPose)
            throw std::runtime_error(cfg.rawlogPath +
                                     ": [localization] start_pose = log, but the log "
                                     "has no start pose (a text log's 'start' line)");
        loc->startAt(reader.header().startPose->asTPose());
    }
    // The view's truth, read only for it (the scoring reads it after the run).
    std::optional<rfir::common::TPath2D> gt;
    if (onStep && !cfg.gtPath.empty()) gt = rfir::common::loadTUM(cfg.gtPath);
    const rfir::common::TPath2D* truth = gt ? &*gt : nullptr;
    double viewSeconds = 0;  // not the filter's time
    const auto view = [&](const TStepView& v) {
        const auto v0 = std::chrono::steady_clock::now();
        onStep(v);
        viewSeconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - v0).count();
    };
    const auto t0 = std::chrono::steady_clock::now();
    rfir::common::TRawlogStep st;
    while (reader.next(st)) {
        res.steps++;
        if (st.odometryIncrement) odo = odo + *st.odometryIncrement;
        res.odometry.push_back({st.t, odo});
        if (st.ir) res.irObservations++;
        rfir::ir::TLocalizerStep info;
        if (!loc) {
            if (onStep)
                view({res.steps - 1, st.t, cfg, nullptr, info, st.ir.get(), odo, truth});
            continue;
        }
        try {
            info = loc->step(st.odometryIncrement, st.ir.get(), st.t);
        } catch (const std::exception& e) {
            throw std::runtime_error(
                cfg.rawlogPath + ": instant " + std::to_string(st.index) +
                " (t = " + std::to_string(st.t) + " s): " + e.what());
        }
        res.readings += info.readings;
        res.used += info.used;
        res.unknownIds += info.unknownIds;
        res.decoded += info.decoded;
        if (info.resetParticles && !info.justStarted) {
            res.resetEvents++;
            res.resetParticles += info.resetParticles;
        }
        if (info.uniqueRead && !res.firstUniqueTime) res.firstUniqueTime = st.t;
        if (info.justStarted) res.startHistoryReadings = info.historyReadings;
        res.gated += info.gated;
        reportLost(info, st.t, res);
        if (info.started) res.path.push_back({st.t, loc->estimate()});
        if (onStep)
            view({res.steps - 1, st.t, cfg, loc.get(), info, st.ir.get(), odo, truth});
        if (!cfg.quiet && res.steps % 500 == 0)
            std::cerr << "rfir-localize: t = " << st.t << " s, " << res.steps
                      << " instants" << (info.started ? "" : " (waiting for a unique ID)")
                      << "\n";
    }
    res.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() -
        viewSeconds;
    if (cfg.odometryOnly) res.path = res.odometry;
    if (loc) res.emitterHealth = loc->emitterHealth();
    return res;
}

}  // namespace rfir::localize
