/* rfir-experiments: simulate, run a method, score it. */
#include <rfir/common/install_paths.h>
#include <rfir/experiments/runner.h>

#include <rfir/common/ini_file.h>
#include <rfir/common/ini_override.h>
#include <rfir/eval/metrics.h>
#include <rfir/slam/slam_engine.h>
#include <rfir/slam/slam_inputs.h>
#include <rfir/slam/slam_outputs.h>

#include <mrpt/random/RandomGenerators.h>

#include <sstream>
#include <stdexcept>

namespace rfir::experiments {
namespace {
using rfir::common::TMapEntry;

rfir::slam::TSlamConfig slamConfig(const TSetup& s, const TMethodSpec& m,
                                   const TPoint& p) {
    const std::string path = rfir::common::slamIniPath(s.configDir, m.method);
    auto ini = rfir::common::readIniFile(path);
    // Edits go into the in-memory copy of the INI (never the file).
    rfir::common::applyIniOverrides(ini, p.slamEdits);
    rfir::common::applyIniOverrides(ini, m.edits);
    rfir::common::applyIniOverrides(ini, s.slamEdits);
    return rfir::slam::loadSlamConfig(ini, m.method);
}

std::vector<std::string> simOverrides(const TSetup& s, const TSubRun& run,
                                      const TPoint& point) {
    std::vector<std::string> ov = run.simOverrides;
    ov.insert(ov.end(), point.simOverrides.begin(), point.simOverrides.end());
    ov.insert(ov.end(), s.simEdits.begin(), s.simEdits.end());
    return ov;
}

TMapEntry::Kind mapKind(const rfir::sim::TSimOutput& sim) {
    return sim.header.readers.empty() && sim.header.rbSensor ? TMapEntry::Kind::Landmark
                                                             : TMapEntry::Kind::Tag;
}

/** Error before the kidnapping, after it, and the time to get back to the
 * accuracy of before (below twice the mean error before the kidnapping). */
void kidnapMetrics(const rfir::sim::TSimConfig& cfg, TRunResult& r) {
    const double t0 = cfg.kidnapLiftClock(), tDown = cfg.kidnapDownClock();
    const auto& pp = r.eval.robot->perPose;
    double sb = 0, sa = 0;
    size_t nb = 0, na = 0;
    for (const auto& e : pp) {
        if (e.t < t0) sb += e.dist, nb++;
        if (e.t > tDown + kRecoveryWindow) sa += e.dist, na++;
    }
    if (nb) r.beforeKidnap = sb / double(nb);
    if (na) r.afterKidnap = sa / double(na);
    if (!nb || !na || r.afterKidnap > 2 * r.beforeKidnap) return;  // not recovered
    for (const auto& e : pp)
        if (e.t >= tDown && e.dist < 2 * r.beforeKidnap) {
            r.recoveryTime = e.t - tDown;
            break;
        }
}
}  // namespace

TSetup makeSetup(const std::string& configDir, const std::vector<std::string>& sets) {
    const auto split = rfir::common::routeIniEdits(
        {{"sim", "simulation INIs", rfir::sim::simConfigSections()},
         {"slam", "SLAM INIs", rfir::slam::slamConfigSections()}},
        sets);
    return {configDir, split[0], split[1]};
}

void checkConfigs(const TSetup& setup, const std::vector<TRow>& rows) {
    // The user's edits are the command line's: an INI they break is a
    // CUsageError naming the edit; the rows' own are the project's.
    rfir::common::loadWithIniEdits(
        setup.simEdits, [&](const std::vector<std::string>& e) {
            TSetup s = setup;
            s.simEdits = e;
            for (const auto& row : rows)
                for (const auto& p : row.points)
                    for (const auto& r : row.runs)
                        rfir::sim::loadSimConfig(s.configDir + "/" + r.simIni,
                                                 simOverrides(s, r, p));
        });
    rfir::common::loadWithIniEdits(setup.slamEdits,
                                   [&](const std::vector<std::string>& e) {
                                       TSetup s = setup;
                                       s.slamEdits = e;
                                       for (const auto& row : rows)
                                           for (const auto& p : row.points)
                                               for (const auto& m : row.methods)
                                                   slamConfig(s, m, p);
                                   });
}

TDataSet simulateDataSet(const TSetup& setup, const TSubRun& run, const TPoint& point,
                         uint64_t seed) {
    TDataSet d;
    d.cfg = rfir::sim::loadSimConfig(setup.configDir + "/" + run.simIni,
                                     simOverrides(setup, run, point));
    if (point.odometryScale > 0) d.cfg.odometry.scale(point.odometryScale);
    d.sim = rfir::sim::simulate(d.cfg, seed);
    if (!d.sim.header.readers.empty())
        d.passed = rfir::eval::tagsPassedOver(d.sim.gtMap, d.sim.groundTruth,
                                              d.sim.header.readers);
    else if (d.sim.header.rbSensor)
        d.passed = rfir::eval::landmarksInView(d.sim.gtMap, d.sim.groundTruth,
                                               *d.sim.header.rbSensor);
    return d;
}

TRunResult runMethod(const TSetup& setup, const TDataSet& data, const TMethodSpec& m,
                     const TPoint& point, uint64_t seed, bool keepOutputs) {
    auto cfg = slamConfig(setup, m, point);
    cfg.seed = seed;
    auto engine = rfir::slam::makeEngine(cfg, data.sim.header);
    const auto run = rfir::slam::runEngine(*engine, data.sim.groundTruth.front().pose,
                                           rfir::slam::inputsFromSteps(data.sim.steps));
    TRunResult r;
    r.method = m.label;
    r.seed = seed;
    r.msPerStep = 1e3 * run.meanStepTime;
    r.maxStepMs = 1e3 * run.maxStepTime;
    r.totalSeconds = run.totalTime;
    r.steps = run.path.size();
    r.resets = run.resets;
    rfir::common::TPath2D est = rfir::slam::stampedPath(run);
    rfir::common::TMapFile map = rfir::slam::landmarkEntries(run.map);
    r.eval.label = m.label;
    r.eval.robot = rfir::eval::computeRobotErrors(est, data.sim.groundTruth);
    r.eval.map = rfir::eval::computeMapErrors(map, data.sim.gtMap, mapKind(data.sim));
    if (data.passed) rfir::eval::setPassedOver(*r.eval.map, *data.passed, map);
    if (data.cfg.kidnap.enabled) kidnapMetrics(data.cfg, r);
    if (keepOutputs) {
        r.estPath = std::move(est);
        r.estMap = std::move(map);
    } else
        r.eval.robot->perPose.clear(), r.eval.map->perLandmark.clear();
    return r;
}

}  // namespace rfir::experiments
