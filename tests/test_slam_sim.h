// Helpers of the SLAM accuracy tests: simulated runs through the sim API, the
// methods run with their stock INIs, errors from rfir_eval.
#pragma once

#include <rfir/common/install_paths.h>
#include <rfir/eval/metrics.h>
#include <rfir/sim/simulator.h>
#include <rfir/slam/slam_engine.h>
#include <rfir/slam/slam_inputs.h>
#include <rfir/slam/slam_outputs.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace slam_test {
inline std::vector<rfir::slam::TSlamInput> toInputs(const rfir::sim::TSimOutput& out) {
    return rfir::slam::inputsFromSteps(out.steps);
}

/** An INI file with `section.key` edits, loaded for `method`. */
inline rfir::slam::TSlamConfig configFromIni(
    const std::string& path, const std::string& method,
    const std::vector<std::pair<std::string, std::string>>& edits) {
    // A memory copy: CConfigFile would write the edits back into the INI.
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    mrpt::config::CConfigFileMemory f(text.str());
    for (const auto& [sk, v] : edits) {
        const auto dot = sk.find('.');
        f.write(sk.substr(0, dot), sk.substr(dot + 1), v);
    }
    return rfir::slam::loadSlamConfig(f, method);
}

/** The stock INI of `method`, with optional "section.key = value" edits. */
inline rfir::slam::TSlamConfig stockConfig(
    const std::string& method,
    const std::vector<std::pair<std::string, std::string>>& edits = {}) {
    return configFromIni(
        rfir::common::slamIniPath(std::string(RFIR_SOURCE_DIR) + "/config_ini", method),
        method, edits);
}

struct TResult {
    double robot = 0, tags = 0;  //!< mean distance errors, m
    size_t mapped = 0;
    rfir::slam::TSlamRun run;
    rfir::eval::TRobotErrors robotErrors;
};

inline TResult runMethod(const rfir::sim::TSimOutput& sim, rfir::slam::TSlamConfig cfg,
                         uint64_t seed) {
    cfg.seed = seed;
    mrpt::random::getRandomGenerator().randomize(uint32_t(seed));
    auto engine = rfir::slam::makeEngine(cfg, sim.header);
    TResult r;
    r.run = rfir::slam::runEngine(*engine, sim.groundTruth.front().pose, toInputs(sim));
    r.robotErrors =
        rfir::eval::computeRobotErrors(rfir::slam::stampedPath(r.run), sim.groundTruth);
    r.robot = r.robotErrors.stats.mean_dist;
    const auto m = rfir::slam::landmarkEntries(r.run.map);
    const auto kind = sim.header.rbSensor && !sim.header.readers.size()
                          ? rfir::common::TMapEntry::Kind::Landmark
                          : rfir::common::TMapEntry::Kind::Tag;
    const auto me = rfir::eval::computeMapErrors(m, sim.gtMap, kind);
    r.tags = me.stats.mean_dist;
    r.mapped = me.mapped;
    return r;
}

/** The odometry noise of a stock simulator INI: the setups of the papers use
 * the papers' zero-mean noise at the calibrated level (docs/simulator.md), the
 * `_biased` INIs realistic odometry with per-run systematic errors. */
inline rfir::sim::TOdometryNoise stockOdometry(const std::string& ini) {
    return rfir::sim::loadSimConfig(std::string(RFIR_SOURCE_DIR) + "/config_ini/" + ini)
        .odometry;
}

/** The thesis 4.1 / 4.2 setup: 8 readers of 300 mm, 4 tags/m^2; odometry of
 * sim_rfid_300mm_4tags_random[_biased].ini. */
inline rfir::sim::TSimConfig setup300mm(double duration, bool biased = false) {
    rfir::sim::TSimConfig c;
    c.odometry = stockOdometry(biased ? "sim_rfid_300mm_4tags_random_biased.ini"
                                      : "sim_rfid_300mm_4tags_random.ini");
    c.readers = rfir::sim::ringReaderLayout(0.4, 0.15);
    c.rfid.density = 4;
    c.trajectory.kind = rfir::sim::TTrajectoryConfig::Kind::Random;
    c.trajectory.waypoints = 30;
    c.maxDuration = duration;
    return c;
}

/** The thesis 3.1 setup: 8 readers of 60 mm, 16 tags/m^2, rectangle loop;
 * odometry of sim_rfid_60mm_16tags_loop[_biased].ini. */
inline rfir::sim::TSimConfig setup60mmLoop(int laps, bool biased = false) {
    rfir::sim::TSimConfig c;  // the simulator's defaults are this setup
    c.odometry = stockOdometry(biased ? "sim_rfid_60mm_16tags_loop_biased.ini"
                                      : "sim_rfid_60mm_16tags_loop.ini");
    c.readers = rfir::sim::ringReaderLayout(0.15, 0.03);
    c.rfid.density = 16;
    c.trajectory.kind = rfir::sim::TTrajectoryConfig::Kind::Loop;
    c.trajectory.laps = laps;
    return c;
}

inline double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0 : s / double(v.size());
}
inline double stddev(const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return v.size() < 2 ? 0 : std::sqrt(s / double(v.size() - 1));
}

/** A stock simulator INI (config_ini/<ini>), cut at maxDuration s if > 0. */
inline rfir::sim::TSimConfig simIni(const std::string& ini, double maxDuration = 0) {
    auto c =
        rfir::sim::loadSimConfig(std::string(RFIR_SOURCE_DIR) + "/config_ini/" + ini);
    if (maxDuration > 0) c.maxDuration = maxDuration;
    return c;
}

/** The mean robot error over the poses after t0 (s). */
inline double meanAfter(const rfir::eval::TRobotErrors& e, double t0) {
    std::vector<double> v;
    for (const auto& pe : e.perPose)
        if (pe.t > t0) v.push_back(pe.dist);
    return mean(v);
}

}  // namespace slam_test
