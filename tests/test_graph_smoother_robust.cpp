// The offline smoother on the runs a real robot records:
// after a kidnapping, on 300 mm readers with empty polls written, and on the
// fault INIs; each against the filter it starts from.
#include "test_slam_sim.h"

#include <rfir/slam/graph_smoother.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

using namespace slam_test;

namespace {
struct TScore {
    double filter = 0, smoothed = 0;            //!< whole run, robot mean, m
    double filterAfter = 0, smoothedAfter = 0;  //!< after the put-down (kidnap INIs)
    double filterTags = 0, smoothedTags = 0;
    rfir::slam::TGraphSmootherResult res;
};

/** SMOOTH_OPTS="key=value,...": [smoother] edits for the measurements. */
std::vector<std::pair<std::string, std::string>> smootherEdits() {
    std::vector<std::pair<std::string, std::string>> v;
    const char* e = std::getenv("SMOOTH_OPTS");
    std::stringstream in(e ? e : "");
    for (std::string kv; std::getline(in, kv, ',');) {
        const auto eq = kv.find('=');
        if (eq != std::string::npos)
            v.emplace_back("smoother." + kv.substr(0, eq), kv.substr(eq + 1));
    }
    return v;
}

TScore filterAndSmooth(const rfir::sim::TSimConfig& c, const std::string& name,
                       uint64_t seed, const char* method) {
    const auto sim = rfir::sim::simulate(c, seed);
    const auto cfg = stockConfig(method, smootherEdits());
    const auto f = runMethod(sim, cfg, seed);
    TScore s;
    s.res = rfir::slam::smoothRun(toInputs(sim), sim.groundTruth.front().pose, f.run,
                                  rfir::slam::smootherParams(cfg));
    const auto se = rfir::eval::computeRobotErrors(rfir::slam::stampedPath(s.res.run),
                                                   sim.groundTruth);
    const double t0 = c.kidnap.enabled ? c.kidnapDownClock() : 0;
    s.filter = f.robot, s.smoothed = se.stats.mean_dist;
    s.filterAfter = meanAfter(f.robotErrors, t0), s.smoothedAfter = meanAfter(se, t0);
    s.filterTags = f.tags;
    s.smoothedTags =
        rfir::eval::computeMapErrors(rfir::slam::landmarkEntries(s.res.run.map),
                                     sim.gtMap, rfir::common::TMapEntry::Kind::Tag)
            .stats.mean_dist;
    std::printf(
        "%s seed %d %s: filter %.1f (after %.1f) / %.1f, smoothed %.1f (after %.1f) / "
        "%.1f mm; %zu resets, %d it, %.2f s, odometry scale %+.4f, drift %+.5f rad/m\n",
        name.c_str(), int(seed), method, 1e3 * s.filter, 1e3 * s.filterAfter,
        1e3 * s.filterTags, 1e3 * s.smoothed, 1e3 * s.smoothedAfter, 1e3 * s.smoothedTags,
        f.run.resets, s.res.iterations, s.res.seconds, s.res.odometryScale,
        s.res.headingDriftPerMetre);
    return s;
}
}  // namespace

// Measurements of docs/slam.md ("Offline smoothing"): every setup, 3 seeds.
TEST(GraphSmootherRobust, DISABLED_Measure) {
    const char* only = std::getenv("SMOOTH_INI");
    for (const char* ini :
         {"sim_kidnap.ini", "sim_kidnap_300mm.ini", "sim_rfid_300mm_rotation.ini",
          "sim_rfid_60mm_16tags_loop.ini", "sim_faults_slips.ini", "sim_faults_ghost.ini",
          "sim_faults_bias.ini", "sim_faults_combined.ini"}) {
        if (only && std::string(only) != ini) continue;
        const auto c = simIni(ini);
        for (uint64_t seed = 1; seed <= 3; seed++)
            for (const char* m : {"pf", "ps"}) filterAndSmooth(c, ini, seed, m);
    }
}

// The bar: after a kidnapping the smoothed run is at least as good as
// the filter it starts from, over the whole run and after the put-down (PF-
// SLAM, the stock 60 mm and 300 mm kidnap INIs, seeds 1-3). Without robust
// losses and the cut, a smoother averages the carried robot's frozen odometry
// in and ends far worse than the filter.
TEST(GraphSmootherRobust, KidnapNoWorseThanTheFilter) {
    for (const char* ini : {"sim_kidnap.ini", "sim_kidnap_300mm.ini"})
        for (uint64_t seed = 1; seed <= 3; seed++) {
            const auto s = filterAndSmooth(simIni(ini), ini, seed, "pf");
            EXPECT_GE(s.res.cutTimes.size(), 1u) << ini << " seed " << seed;
            EXPECT_LE(s.smoothed, s.filter) << ini << " seed " << seed;
            EXPECT_LE(s.smoothedAfter, s.filterAfter) << ini << " seed " << seed;
        }
}

// The bar: on the 300 mm loop with rotation and empty polls written
// (the simulator's default), the smoothed robot error is at most 0.8 x the
// filter's (PF-SLAM, seeds 1-3).
TEST(GraphSmootherRobust, EmptyPolls300mmLoop) {
    const char* ini = "sim_rfid_300mm_rotation.ini";
    auto c = simIni(ini);
    ASSERT_TRUE(c.rfid.writeEmptyPolls);
    for (uint64_t seed = 1; seed <= 3; seed++) {
        const auto s = filterAndSmooth(c, ini, seed, "pf");
        EXPECT_GT(s.res.negatives, 0u);
        EXPECT_LE(s.smoothed, 0.8 * s.filter) << "seed " << seed;
    }
}

// The smoother started from the ground truth (sim_rfid_300mm_rotation, seed
// 1): the cost at the truth and where the optimum lies, with the odometry
// scale held and estimated (how the scale's default was chosen).
TEST(GraphSmootherRobust, DISABLED_FromTruth) {
    const auto sim = rfir::sim::simulate(simIni("sim_rfid_300mm_rotation.ini"), 1);
    rfir::slam::TSlamRun gt;
    for (const auto& g : sim.groundTruth) gt.path.emplace_back(g.t, g.pose);
    for (const auto& e : sim.gtMap) {
        rfir::slam::TLandmarkOut l;
        l.id = e.id, l.x = e.x, l.y = e.y;
        gt.map.push_back(l);
    }
    for (double sp : {0.0, 0.01}) {
        auto p = rfir::slam::smootherParams(stockConfig("pf", smootherEdits()));
        p.options.scale_prior_std = sp;
        const auto r =
            rfir::slam::smoothRun(toInputs(sim), sim.groundTruth.front().pose, gt, p);
        const auto se = rfir::eval::computeRobotErrors(rfir::slam::stampedPath(r.run),
                                                       sim.groundTruth);
        std::printf(
            "prior %.2f: cost %.1f -> %.1f, %zu reads %zu neg, err %.1f mm scale %.4f\n",
            sp, r.initialCost, r.finalCost, r.reads, r.negatives,
            1e3 * se.stats.mean_dist, r.odometryScale);
    }
}

// The 30 x 20 m floor's third seed (docs/slam.md, "What the floor's third
// seed does"): the odometry drifts about 0.011 rad/m, the first return to a
// tag comes 6.7 m off, and PF- and PS-SLAM end metres off with resets. The
// smoother, which estimates the drift, is not lost there. Thresholds set from
// one measurement, with no smoother setting changed for it (PS filter 3094
// mm mean, smoothed 160 mm, drift estimated 0.0104 rad/m): at most a quarter
// of the filter's mean and under 0.5 m, and the drift found within a factor
// of two. With loop closure by smoothing the filter closes its first return
// instead of resetting, and the smoother, with no cut to make, ends well
// inside these bounds.
TEST(GraphSmootherRobust, FloorWithHeadingDrift) {
    const auto s = filterAndSmooth(simIni("bench_floor_30x20.ini"), "floor", 3, "ps");
    EXPECT_LT(s.smoothed, 0.25 * s.filter);
    EXPECT_LT(s.smoothed, 0.5);
    EXPECT_GT(s.res.headingDriftPerMetre, 0.0055);
    EXPECT_LT(s.res.headingDriftPerMetre, 0.022);
}

// The odometry bias is estimated only where closures show it: half a lap of
// the 60 mm loop (30 s of a 60 s lap, a tag read again only after the lap)
// has none, so the drift is held at zero; the whole run (3 laps) has many.
TEST(GraphSmootherRobust, BiasOnlyWithClosures) {
    auto c = simIni("sim_faults_bias.ini");
    const auto all = filterAndSmooth(c, "bias", 1, "pf");
    EXPECT_GE(all.res.closures, 20u);
    EXPECT_TRUE(all.res.biasEstimated);
    EXPECT_NE(all.res.headingDriftPerMetre, 0.0);
    c.maxDuration = 30;
    const auto half = filterAndSmooth(c, "bias, 30 s", 1, "pf");
    EXPECT_LT(half.res.closures, 20u);
    EXPECT_FALSE(half.res.biasEstimated);
    EXPECT_EQ(half.res.headingDriftPerMetre, 0.0);
}
