/* rfir_slam experiments behind docs/slam.md (not run by ctest: DISABLED_).
 * Run: test_slam_experiments --gtest_also_run_disabled_tests
 *   SLAM_EXP_SETUP = 60mm | 300mm | 60mm_kidnap | rb     (default 60mm)
 *                    60mm_biased | 300mm_biased (odometry with systematic errors)
 *   SLAM_EXP_SEEDS = number of seeds                   (default 3)
 *   SLAM_EXP_METHODS = comma list of pf,ps,fastslam,odometry
 *   SLAM_EXP_EDITS = "section.key=value;..." applied to every method's INI
 *   SLAM_EXP_ODO_SCALE = factor on every odometry noise parameter of the setup */
#include "test_slam_sim.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

using namespace slam_test;

namespace {
std::string env(const char* k, const std::string& def) {
    const char* v = std::getenv(k);
    return v ? v : def;
}
std::vector<std::string> split(const std::string& s, char c) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string x;
    while (std::getline(ss, x, c))
        if (!x.empty()) out.push_back(x);
    return out;
}
rfir::sim::TSimConfig setup(const std::string& name) {
    if (name == "300mm") return setup300mm(150);
    if (name == "300mm_long") return setup300mm(0);
    if (name == "60mm_biased") return setup60mmLoop(3, true);
    if (name == "300mm_biased") return setup300mm(150, true);
    if (name == "60mm_random") {
        auto c = setup60mmLoop(1);
        c.trajectory.kind = rfir::sim::TTrajectoryConfig::Kind::Random;
        c.trajectory.waypoints = 30;
        return c;
    }
    if (name == "60mm_nobias" || name == "300mm_nobias") {
        // Only the random odometry noise: no per-run scale / heading biases.
        auto c = name == "60mm_nobias" ? setup60mmLoop(3) : setup300mm(150);
        c.odometry.scaleSigma = c.odometry.rotScaleSigma = 0;
        c.odometry.headingDriftSigma = 0;
        return c;
    }
    if (name == "60mm_lownoise" || name == "300mm_lownoise") {
        // A quieter odometry (heading random walk 1 mrad/sqrt(m), no biases).
        auto c = name == "60mm_lownoise" ? setup60mmLoop(3) : setup300mm(150);
        c.odometry.scaleSigma = c.odometry.rotScaleSigma = 0;
        c.odometry.headingDriftSigma = 0;
        c.odometry.kPhiXY = 0.001;
        c.odometry.kXY = 0.005;
        return c;
    }
    if (name == "60mm_kidnap") {
        auto c = setup60mmLoop(2);
        c.kidnap.enabled = true;
        c.kidnap.time = 70;
        c.kidnap.toTime = 25;
        return c;
    }
    if (name == "300mm_kidnap") {
        auto c = setup300mm(200);
        c.kidnap.enabled = true;
        c.kidnap.time = 120;
        c.kidnap.toTime = 40;
        return c;
    }
    if (name == "rb" || name == "rb_rot") {
        auto c = setup60mmLoop(3);
        c.rfid.enabled = false;
        c.rb.enabled = true;
        c.trajectory.kind = rfir::sim::TTrajectoryConfig::Kind::Predefined;
        if (name == "rb_rot")
            c.trajectory.rotation = rfir::sim::TTrajectoryConfig::Rotation::Follow;
        return c;
    }
    return setup60mmLoop(3);
}
}  // namespace

TEST(SlamExperiments, DISABLED_Compare) {
    const std::string setupName = env("SLAM_EXP_SETUP", "60mm");
    const int seeds = std::atoi(env("SLAM_EXP_SEEDS", "3").c_str());
    const auto methods = split(env("SLAM_EXP_METHODS", "pf,ps,fastslam,odometry"), ',');
    std::vector<std::pair<std::string, std::string>> edits;
    for (const auto& e : split(env("SLAM_EXP_EDITS", ""), ';')) {
        const auto eq = e.find('=');
        edits.emplace_back(e.substr(0, eq), e.substr(eq + 1));
    }
    auto simCfg = setup(setupName);
    // SLAM_EXP_ODO_SCALE: every odometry noise parameter scaled.
    if (const double k = std::atof(env("SLAM_EXP_ODO_SCALE", "0").c_str()); k > 0)
        simCfg.odometry.scale(k);
    std::printf("setup %s, %d seeds, edits '%s'\n", setupName.c_str(), seeds,
                env("SLAM_EXP_EDITS", "").c_str());
    std::vector<std::vector<double>> robot(methods.size()), tags(methods.size()),
        times(methods.size()), late(methods.size());
    for (int s = 1; s <= seeds; s++) {
        const auto sim = rfir::sim::simulate(simCfg, uint64_t(s));
        for (size_t m = 0; m < methods.size(); m++) {
            const auto r = runMethod(sim, stockConfig(methods[m], edits), uint64_t(s));
            robot[m].push_back(r.robot);
            tags[m].push_back(r.tags);
            times[m].push_back(r.run.meanStepTime);
            std::vector<double> e;
            const double t0 = simCfg.kidnap.enabled ? simCfg.kidnapDownClock() + 15 : 0;
            for (const auto& pe : r.robotErrors.perPose)
                if (pe.t > t0) e.push_back(pe.dist);
            late[m].push_back(mean(e));
            if (!env("SLAM_EXP_PROFILE", "").empty()) {
                std::printf("  profile %s:", methods[m].c_str());
                for (size_t i = 0; i < r.robotErrors.perPose.size(); i += 150)
                    std::printf(" %.0f", 1e3 * r.robotErrors.perPose[i].dist);
                std::printf("\n");
            }
            std::printf(
                "  seed %d %-9s robot %7.1f tags %7.1f mm (%zu tags, %zu resets)\n", s,
                methods[m].c_str(), 1e3 * r.robot, 1e3 * r.tags, r.mapped, r.run.resets);
        }
    }
    for (size_t m = 0; m < methods.size(); m++)
        std::printf(
            "%-9s robot %7.1f (sd %5.1f)  tags %7.1f (sd %5.1f) mm  %.3f ms/step"
            "%s\n",
            methods[m].c_str(), 1e3 * mean(robot[m]), 1e3 * stddev(robot[m]),
            1e3 * mean(tags[m]), 1e3 * stddev(tags[m]), 1e3 * mean(times[m]),
            simCfg.kidnap.enabled
                ? (" after kidnap " + std::to_string(int(1e3 * mean(late[m]))) + " mm")
                      .c_str()
                : "");
}
