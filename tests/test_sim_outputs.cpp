// The simulator's runs: determinism, the files it writes, trajectories and
// spots, the kidnapping, the odometry noise statistics.
#include <rfir/common/map_io.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/sim/simulator.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace fs = std::filesystem;
using namespace rfir::sim;
using mrpt::poses::CPose2D;

namespace {
std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

/** This process's folder, removed when it ends. */
const fs::path& procDir() {
    static const rfir_test::TmpDir d;
    return d.p;
}

fs::path runTo(const TSimConfig& c, uint64_t seed, const std::string& sub) {
    const auto dir = procDir() / sub;
    fs::remove_all(dir);
    fs::create_directories(dir);
    writeOutputs(simulate(c, seed), dir.string(), "run");
    return dir;
}

TSimConfig shortMixed() {
    TSimConfig c;
    c.rb.enabled = true;
    c.ir.enabled = true;
    c.maxDuration = 15;
    return c;
}
}  // namespace

TEST(SimOutputs, SameSeedSameBytesOtherSeedDiffers) {
    const auto c = shortMixed();
    const auto a = runTo(c, 11, "a"), b = runTo(c, 11, "b"), d = runTo(c, 12, "d");
    for (const char* f : {"run.rawlog", "run.gt.tum", "run.gt_map.txt"}) {
        const auto x = slurp(a / f);
        ASSERT_FALSE(x.empty()) << f;
        EXPECT_EQ(x, slurp(b / f)) << f;
    }
    EXPECT_NE(slurp(a / "run.rawlog"), slurp(d / "run.rawlog"));
    EXPECT_NE(slurp(a / "run.gt_map.txt"), slurp(d / "run.gt_map.txt"));
}

TEST(SimOutputs, RawlogReadsBackWithGroundTruth) {
    auto c = shortMixed();
    c.trajectory.spots = 50;  // one every 0.72 m: a few within the 15 s
    const auto out = simulate(c, 13);
    const auto dir = procDir() / "rb";
    fs::create_directories(dir);
    writeOutputs(out, dir.string(), "x");
    rfir::common::CRawlogReader rd((dir / "x.rawlog").string());
    EXPECT_EQ(rd.header().readers, c.readers);
    EXPECT_EQ(rd.header().receivers, c.receivers);
    ASSERT_TRUE(rd.header().startPose.has_value());
    EXPECT_NEAR(rd.header().startPose->distanceTo(out.groundTruth[0].pose), 0, 1e-12);
    EXPECT_DOUBLE_EQ(out.steps[0].t, c.startTime);  // a zero MRPT timestamp is invalid
    EXPECT_GT(c.startTime, 0);
    rfir::common::TRawlogStep s;
    size_t n = 0, withIR = 0, withRB = 0;
    while (rd.next(s)) {
        const auto& e = out.steps[n];
        EXPECT_NEAR(s.t, e.t, 1e-6);
        // IR and RB observations only when something is in view.
        ASSERT_TRUE(s.odometry && s.rfid);
        withIR += bool(s.ir), withRB += bool(s.rb);
        EXPECT_EQ(s.sf->size(), 1 + e.obs.size());
        EXPECT_NEAR(s.odometry->distanceTo(*e.odometry), 0, 1e-9);
        n++;
    }
    EXPECT_EQ(n, out.steps.size());
    EXPECT_GT(withIR, n / 2);
    EXPECT_GT(withRB, n / 2);
    const auto gt = rfir::common::loadTUM((dir / "x.gt.tum").string());
    ASSERT_EQ(gt.size(), out.steps.size());
    EXPECT_NEAR(gt.back().pose.distanceTo(out.steps.back().truePose), 0, 1e-5);
    EXPECT_EQ(rfir::common::loadMapFile((dir / "x.gt_map.txt").string()).size(),
              out.gtMap.size());
    EXPECT_EQ(rfir::common::loadTUM((dir / "x.spots.tum").string()).size(),
              out.spots.size());
}

TEST(SimTrajectory, ShapesStayInsideAndKeepTheSpeed) {
    std::vector<std::array<double, 3>> shapes;  // length, mean x, mean y
    for (int k = 1; k <= 5; k++) {
        TSimConfig c;
        c.trajectory.kind = TTrajectoryConfig::Kind::Predefined;
        c.trajectory.predefined = k;
        c.trajectory.laps = 1;
        c.trajectory.speed = 0.3;
        const auto out = simulate(c, 1);
        double len = 0, mx = 0, my = 0;
        for (size_t i = 0; i < out.steps.size(); i++) {
            const auto& p = out.steps[i].truePose;
            mx += p.x() / out.steps.size(), my += p.y() / out.steps.size();
            EXPECT_GE(p.x(), 0.5 - 1e-9);
            EXPECT_LE(p.x(), 3.5 + 1e-9);
            EXPECT_GE(p.y(), 0.5 - 1e-9);
            EXPECT_LE(p.y(), 3.5 + 1e-9);
            EXPECT_DOUBLE_EQ(p.phi(), 0);  // no rotation
            if (i == 0) continue;
            const double d = p.distanceTo(out.steps[i - 1].truePose);
            EXPECT_LE(d, 0.3 * c.dt + 1e-9);
            len += d;
        }
        // Closed shapes come back to the start.
        EXPECT_NEAR(out.steps.back().truePose.distanceTo(out.steps[0].truePose), 0,
                    0.031);
        for (const auto& [l, x, y] : shapes)  // five distinct shapes
            EXPECT_GT(std::abs(l - len) + std::abs(x - mx) + std::abs(y - my), 0.2)
                << "shape " << k;
        shapes.push_back({len, mx, my});
    }
}

TEST(SimTrajectory, FollowRotationFacesTheMotion) {
    TSimConfig c;
    c.trajectory.rotation = TTrajectoryConfig::Rotation::Follow;
    c.trajectory.laps = 1;
    const auto out = simulate(c, 1);
    size_t moving = 0;
    for (size_t i = 1; i < out.steps.size(); i++) {
        const auto inc = out.steps[i].truePose - out.steps[i - 1].truePose;
        if (std::abs(inc.phi()) > 1e-12) continue;  // turning at a corner
        EXPECT_NEAR(inc.y(), 0, 1e-9);  // moves straight ahead in its own frame
        EXPECT_GT(inc.x(), 0);
        moving++;
    }
    EXPECT_GT(moving, 500u);
}

TEST(SimTrajectory, SpotsAreStops) {
    TSimConfig c;
    c.trajectory.spots = 70;
    c.trajectory.spotPause = 1.0;
    const auto out = simulate(c, 1);
    ASSERT_EQ(out.spots.size(), 70u);
    for (const auto& sp : out.spots) {
        // The robot stands still for the whole pause around the spot time.
        const size_t k = size_t(std::lround((sp.t - c.startTime) / c.dt));
        for (size_t j = k - 3; j <= k + 3; j++)
            EXPECT_NEAR(out.steps[j].truePose.distanceTo(sp.pose), 0, 1e-9);
    }
}

TEST(SimKidnap, JumpInTruthNotInOdometry) {
    for (auto mode : {TKidnapConfig::Odometry::Frozen, TKidnapConfig::Odometry::Stop}) {
        TSimConfig c;
        c.kidnap.enabled = true;
        c.kidnap.time = 100;
        c.kidnap.carryTime = 2;
        c.kidnap.toTime = 20;
        c.kidnap.odometry = mode;
        c.maxDuration = 130;
        const auto out = simulate(c, 21);
        // The carried steps: no observation (lifted at 100 s, put down at 102 s).
        size_t k0 = 0, k1 = 0;
        while (!out.steps[k0].obs.empty()) k0++;
        for (k1 = k0; out.steps[k1].obs.empty();) k1++;
        EXPECT_NEAR(double(k0), 1000, 1);
        EXPECT_NEAR(double(k1 - k0), 20, 1);
        // Ground truth: put down where the robot was at 20 s.
        EXPECT_GT(out.steps[k0 - 1].truePose.distanceTo(out.steps[k1].truePose), 1.0);
        EXPECT_NEAR(out.steps[k1].truePose.distanceTo(out.steps[200].truePose), 0,
                    0.2 * 0.1 + 1e-9);
        // Odometry: no jump while carried, nor when put down.
        const auto before = *out.steps[k0 - 1].odometry;
        for (size_t k = k0; k < k1; k++) {
            if (mode == TKidnapConfig::Odometry::Stop)
                EXPECT_FALSE(out.steps[k].odometry.has_value());
            else
                EXPECT_EQ(*out.steps[k].odometry, *out.steps[k0].odometry);
        }
        EXPECT_LT(out.steps[k1].odometry->distanceTo(before), 0.03);
        // After it, odometry follows the replayed path again.
        const auto dt = out.steps[k1 + 50].truePose - out.steps[k1].truePose;
        const auto dodo = *out.steps[k1 + 50].odometry - *out.steps[k1].odometry;
        EXPECT_NEAR(dt.distanceTo(dodo), 0, 0.05);
    }
}

TEST(SimOdometry, NoiseStatisticsMatchTheModel) {
    TSimConfig c;
    c.trajectory.kind = TTrajectoryConfig::Kind::Random;
    c.trajectory.rotation = TTrajectoryConfig::Rotation::Spin;
    c.trajectory.spinRate = 0.5;
    c.trajectory.waypoints = 40;
    c.odometry.scaleSigma = c.odometry.rotScaleSigma = 0;  // no biases
    c.odometry.headingDriftSigma = 0;
    const auto out = simulate(c, 31);
    double sx = 0, sy = 0, sp = 0;
    size_t n = 0;
    for (size_t i = 1; i < out.steps.size(); i++) {
        const auto t = out.steps[i].truePose - out.steps[i - 1].truePose;
        const auto o = *out.steps[i].odometry - *out.steps[i - 1].odometry;
        const double d = std::hypot(t.x(), t.y());
        if (d < 1e-6) continue;
        const double sphi =
            std::sqrt(0.02 * 0.02 * std::abs(t.phi()) + 0.005 * 0.005 * d);
        sx += std::pow((o.x() - t.x()) / (0.01 * std::sqrt(d)), 2);
        sy += std::pow((o.y() - t.y()) / (0.01 * std::sqrt(d)), 2);
        sp += std::pow(mrpt::math::wrapToPi(o.phi() - t.phi()) / sphi, 2);
        n++;
    }
    ASSERT_GT(n, 2000u);
    // Normalized residuals have unit variance (5 % is about 3 sigma here).
    EXPECT_NEAR(std::sqrt(sx / n), 1, 0.05);
    EXPECT_NEAR(std::sqrt(sy / n), 1, 0.05);
    EXPECT_NEAR(std::sqrt(sp / n), 1, 0.05);
}

TEST(SimOdometry, BiasesAreSystematic) {
    TSimConfig c;
    c.trajectory.rotation = TTrajectoryConfig::Rotation::Follow;
    c.odometry.kXY = c.odometry.kPhiRot = c.odometry.kPhiXY = 0;  // biases only
    c.odometry.scaleSigma = c.odometry.rotScaleSigma = 0.02;
    c.odometry.headingDriftSigma = 0.01;
    c.maxDuration = 60;
    const auto out = simulate(c, 41);
    EXPECT_NE(out.scaleBias, 0);
    for (size_t i = 1; i < out.steps.size(); i++) {
        const auto t = out.steps[i].truePose - out.steps[i - 1].truePose;
        const auto o = *out.steps[i].odometry - *out.steps[i - 1].odometry;
        const double d = std::hypot(t.x(), t.y());
        EXPECT_NEAR(o.x(), (1 + out.scaleBias) * t.x(), 1e-9);
        EXPECT_NEAR(o.y(), (1 + out.scaleBias) * t.y(), 1e-9);
        EXPECT_NEAR(o.phi(), (1 + out.rotScaleBias) * t.phi() + out.headingDrift * d,
                    1e-9);
    }
}
