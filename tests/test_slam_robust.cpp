/* rfir: robustness to ghost reads, slips, dead readers and asynchronous polls
 * (issue 12 items 2 and 4). Thresholds were set before the runs; each test
 * states them. */
#include "test_slam_sim.h"

#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/slam/graph_smoother.h>
#include <rfir/slam/motion_model.h>
#include <rfir/slam/slam_inputs.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/poses/CPose3D.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using rfir::maps::CRFIDTagParticleMap;
using namespace slam_test;

namespace {
/** One 60 mm reader at the robot centre reading `tag`. */
rfir::obs::CObservationRFIDReaders::Ptr readOf(const std::string& tag) {
    auto o = rfir::obs::CObservationRFIDReaders::Create();
    rfir::obs::CObservationRFIDReaders::TReading r;
    r.reader.id = "R0";
    r.reader.halfX = r.reader.halfY = 0.03;
    r.tags = {tag};
    o->readings.push_back(r);
    return o;
}

/** A PF tag map with tag T well placed at (0, 0): read from the robot at the
 * origin (first read plus re-reads). */
void mapWithTag(CRFIDTagParticleMap& m, double outlierWeight) {
    m.insertionOptions.estimator = rfir::models::kParticleFilterName;
    m.likelihoodOptions.detection.outlierWeight = outlierWeight;
    for (int k = 0; k < 5; k++)
        m.insertObservation(*readOf("T"), mrpt::poses::CPose3D(0, 0, 0, 0, 0, 0));
}

/** The normalised effective sample size of log-weights. */
double essShare(const std::vector<double>& lw) {
    double hi = -1e300, s = 0, s2 = 0;
    for (double x : lw) hi = std::max(hi, x);
    for (double x : lw) {
        const double w = std::exp(x - hi);
        s += w;
        s2 += w * w;
    }
    return s * s / s2 / double(lw.size());
}
}  // namespace

// One ghost read (the tag at (0, 0) reported by the reader at (0.4, 0)):
// without the mixture the tag's particles collapse to the square's edge
// nearest the ghost (thresholds: a drag above 10 mm); with outlier_weight
// 0.005 it moves under 2 mm. The read is counted as contradicted either way.
// The mixture alone: [tagmap] hold_outvoted (on in the stock INIs) would
// keep the read from the tag in both runs (TagMapReseat.OutvotedRead...).
TEST(OutlierReads, GhostReadDragsTheTagOnlyWithoutTheMixture) {
    for (const double eps : {0.0, 0.005}) {
        CRFIDTagParticleMap m;
        m.insertionOptions.holdOutvoted = false;
        mapWithTag(m, eps);
        const auto before = m.getTag("T")->estimate.mean;
        EXPECT_EQ(m.getTag("T")->contradicted, 0u);
        m.insertObservation(*readOf("T"), mrpt::poses::CPose3D(0.4, 0, 0, 0, 0, 0));
        const auto* t = m.getTag("T");
        const double drag =
            std::hypot(t->estimate.mean.x - before.x, t->estimate.mean.y - before.y);
        std::cout << "outlier_weight " << eps << ": tag dragged " << 1000 * drag
                  << " mm\n";
        if (eps == 0)
            EXPECT_GT(drag, 0.010);
        else
            EXPECT_LT(drag, 0.002);
        EXPECT_EQ(t->detections, 6u);
        EXPECT_EQ(t->contradicted, 1u);
    }
}

// The same ghost read weighing 200 robot particles spread +-50 mm about the
// true pose (0.4, 0): without the mixture the normalised ESS falls below
// 0.2 (the particles nearest the tag take the weight); with it, above 0.9.
TEST(OutlierReads, GhostReadCollapsesTheRobotOnlyWithoutTheMixture) {
    for (const double eps : {0.0, 0.005}) {
        CRFIDTagParticleMap m;
        mapWithTag(m, eps);
        rfir::models::TRandom rng(7);
        std::vector<double> lw;
        for (int i = 0; i < 200; i++) {
            const mrpt::poses::CPose3D p(0.4 + 0.05 * rng.drawGaussian1D_normalized(),
                                         0.05 * rng.drawGaussian1D_normalized(), 0, 0, 0,
                                         0);
            lw.push_back(m.computeObservationLikelihood(*readOf("T"), p));
        }
        const double ess = essShare(lw);
        std::cout << "outlier_weight " << eps << ": robot ESS share " << ess << "\n";
        if (eps == 0)
            EXPECT_LT(ess, 0.2);
        else
            EXPECT_GT(ess, 0.9);
    }
}

TEST(OutlierReads, IniKeys) {
    const auto load = [](const std::string& v) {
        mrpt::config::CConfigFileMemory f("[l]\noutlier_weight = " + v +
                                          "\noutlier_log_floor = -12\n");
        CRFIDTagParticleMap::TLikelihoodOptions o;
        o.loadFromConfigFile(f, "l");
        return o;
    };
    EXPECT_EQ(load("0.01").detection.outlierWeight, 0.01);
    EXPECT_EQ(load("0.01").detection.outlierLogFloor, -12);
    EXPECT_THROW(load("0.6"), std::exception);
    EXPECT_THROW(load("-0.1"), std::exception);
    // The stock INIs set the key; FastSLAM does not use it.
    for (const char* method : {"pf", "ps"}) {
        const auto cfg = stockConfig(method);
        const auto dump = rfir::slam::dumpSlamConfig(cfg);
        EXPECT_NE(dump.find("outlier_weight"), std::string::npos) << method;
    }
}

// A 0.5 m odometry jump in 0.1 s with max_speed 0.5 m/s: believed 0.05 m,
// with more noise than the plain model of 0.05 m; within the limits the
// movement is the plain model's, bit for bit.
TEST(SlipAwareMotion, JumpBeyondTheLimitsIsNotBelieved) {
    rfir::slam::TMotionOptions o;
    o.max_speed = 0.5;
    o.max_turn_rate = 2;
    const mrpt::poses::CPose2D jump(0.5, 0, 0), ok(0.04, 0, 0.1);
    EXPECT_NEAR(rfir::slam::slipLimited(jump, 0.1, o), 0.1, 1e-12);
    EXPECT_EQ(rfir::slam::slipLimited(ok, 0.1, o), 1.0);
    EXPECT_EQ(rfir::slam::slipLimited(jump, 0, o), 1.0);  // dt unknown
    const auto g = rfir::slam::makeMovement(jump, 0.1, {}, o);
    EXPECT_NEAR(g.rawOdometryIncrementReading.x(), 0.05, 1e-12);
    const auto plain = rfir::slam::makeMovement(mrpt::poses::CPose2D(0.05, 0, 0), o);
    const auto mean = [](const mrpt::obs::CActionRobotMovement2D& a) {
        mrpt::poses::CPose2D m;
        mrpt::math::CMatrixDouble33 c;
        a.poseChange->getCovarianceAndMean(c, m);
        return c;
    };
    EXPECT_GT(mean(g)(0, 0), 4 * mean(plain)(0, 0));
    // With the memory: the robot keeps the last believed speed (0.2 m/s).
    rfir::slam::CSlipAwareMotion slip;
    slip.movement(mrpt::poses::CPose2D(0.02, 0, 0), 0.1, {}, o);
    const auto kept = slip.movement(jump, 0.1, {}, o);
    EXPECT_NEAR(kept.rawOdometryIncrementReading.x(), 0.02, 1e-12);
    EXPECT_GT(mean(kept)(0, 0), 4 * mean(plain)(0, 0));
    const auto same = rfir::slam::makeMovement(ok, 0.1, {}, o);
    EXPECT_EQ(mean(same), mean(rfir::slam::makeMovement(ok, o)));
    // The INI keys and their ranges.
    mrpt::config::CConfigFileMemory f("[m]\nmax_speed = -1\n");
    EXPECT_THROW(o.loadFromConfigFile(f, "m"), std::exception);
    mrpt::config::CConfigFileMemory g2("[m]\nodometry_latency = 0.02\n");
    EXPECT_THROW(o.loadFromConfigFile(g2, "m"), std::exception);  // needs interpolation
}

namespace {
/** The 60 mm loop (three laps: SLAM needs the returns) with a forward odometry jump of
 * `jump` m at step k (every later odometry pose carried along). */
rfir::sim::TSimOutput loopWithSlip(uint64_t seed, double jump) {
    auto sim = rfir::sim::simulate(setup60mmLoop(3), seed);
    const size_t k = sim.steps.size() / 3;
    std::optional<mrpt::poses::CPose2D> prev;
    for (size_t i = 0; i < sim.steps.size(); i++) {
        auto& s = sim.steps[i];
        if (i < k || !s.odometry) continue;
        if (!prev) {
            // The last odometry pose before k.
            for (size_t j = k; j-- > 0;)
                if (sim.steps[j].odometry) {
                    prev = sim.steps[j].odometry;
                    break;
                }
        }
        const auto rel = *s.odometry - *prev;
        s.odometry = *prev + mrpt::poses::CPose2D(jump, 0, 0) + rel;
    }
    return sim;
}
}  // namespace

/** Mean robot error over the poses in [t0, t0 + len) s. */
double windowError(const TResult& r, double t0, double len) {
    double s = 0;
    size_t n = 0;
    for (const auto& e : r.robotErrors.perPose)
        if (e.t >= t0 && e.t < t0 + len) s += e.dist, n++;
    return n ? s / double(n) : 0;
}

// A 0.3 m slip on the 60 mm loop, 3 laps (robot at 0.2 m/s; the stock
// limits 1 m/s, 3 rad/s), PF-SLAM, seeds 1-3, scored over the 2 s after the
// slip. Thresholds: with the limits that error is below half of the error
// without them, and within 1.5 x (+10 mm) of the run without the slip; no
// more kidnap resets than without the slip. (Scored over 20 s the unlimited
// run is level: kidnap resetting pulls it back within a few seconds, at the
// price of two extra resets; docs/slam.md.)
TEST(SlipAwareMotion, SlipOnTheLoop) {
    const double kWindow = 2;  // s
    double with = 0, without = 0, clean = 0;
    size_t rWith = 0, rWithout = 0, rClean = 0;
    for (uint64_t seed : {1, 2, 3}) {
        const auto sim = loopWithSlip(seed, 0.3);
        const double t0 = sim.steps[sim.steps.size() / 3].t;
        // Stock limits (1 m/s, 3 rad/s) against none.
        const auto a = runMethod(sim, stockConfig("pf"), seed);
        const auto b = runMethod(
            sim,
            stockConfig("pf", {{"motion.max_speed", "0"}, {"motion.max_turn_rate", "0"}}),
            seed);
        const auto c = runMethod(loopWithSlip(seed, 0), stockConfig("pf"), seed);
        with += windowError(a, t0, kWindow) / 3;
        without += windowError(b, t0, kWindow) / 3;
        clean += windowError(c, t0, kWindow) / 3;
        rWith += a.run.resets, rWithout += b.run.resets, rClean += c.run.resets;
    }
    std::cout << "slip 0.3 m, PF mean robot error over the 2 s after it (3 seeds): "
              << "limits off " << 1000 * without << " mm (" << rWithout << " resets), on "
              << 1000 * with << " mm (" << rWith << " resets), no slip " << 1000 * clean
              << " mm (" << rClean << " resets)\n";
    EXPECT_LT(with, 0.5 * without);
    EXPECT_LT(with, 1.5 * clean + 0.01);
    EXPECT_LE(rWith, rClean);
}

// Reader R0 dead (reads nothing) for the middle third of the 60 mm loop (3
// laps), PF and PS, seed 1. Thresholds: no kidnap reset (the bar first
// stated; before the kidnap detector of issue 12 item 3 the run with every
// reader had two false ones, so it was relaxed to "no more than with every
// reader", and is restored with the detector), and the mean robot error
// within 1.5 x (+10 mm) of the run with every reader.
TEST(DeadReader, NoDamage) {
    auto sim = rfir::sim::simulate(setup60mmLoop(3), 1);
    const auto full = sim;
    const size_t n = sim.steps.size();
    for (size_t i = n / 3; i < 2 * n / 3; i++)
        for (auto& o : sim.steps[i].obs)
            if (auto r =
                    std::dynamic_pointer_cast<rfir::obs::CObservationRFIDReaders>(o)) {
                auto c = rfir::obs::CObservationRFIDReaders::Create(*r);
                for (auto& rd : c->readings)
                    if (rd.reader.id == full.header.readers.front().id) rd.tags.clear();
                o = c;
            }
    for (const char* method : {"pf", "ps"}) {
        const auto dead = runMethod(sim, stockConfig(method), 1);
        const auto all = runMethod(full, stockConfig(method), 1);
        std::cout << method
                  << ": one reader dead for a third of the run: " << 1000 * dead.robot
                  << " mm (" << dead.run.resets << " resets), every reader "
                  << 1000 * all.robot << " mm (" << all.run.resets << " resets)\n";
        EXPECT_EQ(dead.run.resets, 0u) << method;
        EXPECT_LE(dead.run.resets, all.run.resets) << method;
        EXPECT_LT(dead.robot, 1.5 * all.robot + 0.01) << method;
    }
}

// Polls between odometry records: placed at the interpolated odometry, and
// the noise variances drawn over one interval add up to that interval's.
TEST(InterpolatedPolls, PlacementAndNoiseOncePerInterval) {
    using mrpt::poses::CPose2D;
    std::vector<rfir::slam::TRawInstant> v;
    v.push_back({0.0, CPose2D(0, 0, 0), nullptr, nullptr});
    for (double t : {0.25, 0.5, 0.75}) v.push_back({t, std::nullopt, nullptr, nullptr});
    v.push_back({1.0, CPose2D(1, 0, 0.2), nullptr, nullptr});
    const auto in = rfir::slam::interpolatedInputs(v, 0);
    ASSERT_EQ(in.size(), 5u);
    EXPECT_FALSE(in[0].odometryIncrement);
    CPose2D p;
    rfir::slam::TMotionOptions o;
    double vx = 0;
    for (size_t i = 1; i < 5; i++) {
        ASSERT_TRUE(in[i].odometryIncrement);
        ASSERT_EQ(in[i].odometryParts.size(), 1u);
        EXPECT_NEAR(in[i].odometryParts[0].fraction, 0.25, 1e-12);
        p = p + *in[i].odometryIncrement;
        const auto mv = rfir::slam::makeMovement(
            *in[i].odometryIncrement, in[i].odometryDt, in[i].odometryParts, o);
        vx += mv.motionModelConfiguration.gaussianModel.minStdXY *
              mv.motionModelConfiguration.gaussianModel.minStdXY;
        if (i == 1) {
            EXPECT_NEAR(p.x(), 0.25, 0.01);
        }
    }
    EXPECT_NEAR(p.x(), 1, 1e-9);
    EXPECT_NEAR(p.phi(), 0.2, 1e-9);
    double sxy, sphi;
    o.noise().stds(1, 0, 0.2, sxy, sphi);
    EXPECT_NEAR(vx, sxy * sxy, 1e-12);  // not 4 x the per-step floor
    // Latency: a record stamped t is the pose at t - 0.25, so the polls at 0
    // and 0.5 are at the record interval's 0.25 and 0.75: 0.5 m apart.
    const auto lat = rfir::slam::interpolatedInputs(v, 0.25);
    CPose2D q;
    for (size_t i = 1; i <= 2; i++)
        if (lat[i].odometryIncrement) q = q + *lat[i].odometryIncrement;
    EXPECT_NEAR(q.x(), 0.5, 0.01);
    // Synchronous records: every increment is a whole interval (plain model).
    std::vector<rfir::slam::TRawInstant> s = {{0, CPose2D(0, 0, 0), nullptr, nullptr},
                                              {1, CPose2D(1, 0, 0), nullptr, nullptr}};
    EXPECT_TRUE(rfir::slam::interpolatedInputs(s, 0)[1].odometryParts.empty());
    v[2].t = 0.1;  // back in time
    EXPECT_THROW(rfir::slam::interpolatedInputs(v, 0), std::invalid_argument);
}

namespace {
/** The instants of a simulated run with odometry kept on every `every`-th
 * step only (the readers polled in between). */
std::vector<rfir::slam::TRawInstant> sparseOdometry(const rfir::sim::TSimOutput& sim,
                                                    size_t every) {
    std::vector<rfir::slam::TRawInstant> v;
    for (size_t i = 0; i < sim.steps.size(); i++) {
        const auto& s = sim.steps[i];
        rfir::slam::TRawInstant r;
        r.t = s.t;
        if (i % every == 0) r.odometry = s.odometry;
        for (const auto& o : s.obs) {
            if (auto f = std::dynamic_pointer_cast<rfir::obs::CObservationRFIDReaders>(o))
                r.rfid = f;
        }
        v.push_back(r);
    }
    return v;
}

/** Plain pairing: an instant without odometry does not move the robot. */
std::vector<rfir::slam::TSlamInput> plainInputs(
    const std::vector<rfir::slam::TRawInstant>& v) {
    struct TStep {
        double t;
        std::optional<mrpt::poses::CPose2D> odometry;
        std::vector<mrpt::obs::CObservation::Ptr> obs;
    };
    std::vector<TStep> s;
    for (const auto& r : v) {
        TStep st{r.t, r.odometry, {}};
        if (r.rfid) st.obs.push_back(r.rfid);
        s.push_back(st);
    }
    return rfir::slam::inputsFromSteps(s);
}
}  // namespace

// Odometry on every 4th step of the 60 mm loop (3 laps), readers polled on
// every step: PF and PS with the polls at the interpolated odometry against
// the plain pairing (a poll at the last record), seeds 1-3. Threshold,
// stated before the run: interpolated mean robot error at most 1.1 x (+5 mm)
// the plain one for each method.
TEST(InterpolatedPolls, SparseOdometryOnTheLoop) {
    for (const char* method : {"pf", "ps"}) {
        double plain = 0, interp = 0;
        for (uint64_t seed : {1, 2, 3}) {
            const auto sim = rfir::sim::simulate(setup60mmLoop(3), seed);
            const auto raw = sparseOdometry(sim, 4);
            const auto run = [&](const std::vector<rfir::slam::TSlamInput>& in) {
                auto cfg = stockConfig(method);
                cfg.seed = seed;
                auto engine = rfir::slam::makeEngine(cfg, sim.header);
                const auto r =
                    rfir::slam::runEngine(*engine, sim.groundTruth.front().pose, in);
                return rfir::eval::computeRobotErrors(rfir::slam::stampedPath(r),
                                                      sim.groundTruth)
                    .stats.mean_dist;
            };
            plain += run(plainInputs(raw)) / 3;
            interp += run(rfir::slam::interpolatedInputs(raw, 0)) / 3;
        }
        std::cout << method << ", odometry at a quarter of the poll rate (3 seeds): "
                  << "plain " << 1000 * plain << " mm, interpolated " << 1000 * interp
                  << " mm\n";
        EXPECT_LT(interp, 1.1 * plain + 0.005) << method;
    }
}

// The offline smoother on the same inputs: a poll at the interpolated odometry
// carries its share of the interval's noise, as in the filters (the noise
// floor of an increment of its own for every poll would loosen the chain).
// sim_faults_async (25 Hz
// odometry) with each reader polled at 25 Hz in turn (8 polls per record),
// 90 s. Threshold, stated before the run: smoothed after interpolated inputs
// at most 1.1 x (+5 mm) smoothed after the plain ones, PF-SLAM, seeds 1-3.
// Measured: 31.2 against 32.9 mm.
TEST(InterpolatedPolls, SmootherOnAsynchronousPolls) {
    auto c = rfir::sim::loadSimConfig(std::string(RFIR_SOURCE_DIR) +
                                      "/config_ini/sim_faults_async.ini");
    c.maxDuration = 90;
    c.rfid.pollRate = 25;  // 8 polls per odometry record
    c.rfid.pollJitter = 0.001;
    double plain = 0, interp = 0;
    for (uint64_t seed : {1, 2, 3}) {
        const auto sim = rfir::sim::simulate(c, seed);
        const auto raw = sparseOdometry(sim, 1);
        const auto run = [&](const std::vector<rfir::slam::TSlamInput>& in) {
            auto cfg = stockConfig("pf");
            cfg.seed = seed;
            auto engine = rfir::slam::makeEngine(cfg, sim.header);
            const auto start = sim.groundTruth.front().pose;
            const auto f = rfir::slam::runEngine(*engine, start, in);
            const auto s =
                rfir::slam::smoothRun(in, start, f, rfir::slam::smootherParams(cfg));
            return rfir::eval::computeRobotErrors(rfir::slam::stampedPath(s.run),
                                                  sim.groundTruth)
                .stats.mean_dist;
        };
        plain += run(plainInputs(raw)) / 3;
        interp += run(rfir::slam::interpolatedInputs(raw, 0)) / 3;
    }
    std::cout << "smoothed, asynchronous polls (3 seeds): plain " << 1000 * plain
              << " mm, interpolated " << 1000 * interp << " mm\n";
    EXPECT_LT(interp, 1.1 * plain + 0.005);
}

// map.txt's read counts: written by PF/PS, read back by every map reader;
// maps without them (4 or 6 fields) still load; bad counts are refused.
TEST(MapReadCounts, WrittenAndReadBack) {
    CRFIDTagParticleMap m;
    mapWithTag(m, 0.005);
    m.insertObservation(*readOf("T"), mrpt::poses::CPose3D(0.4, 0, 0, 0, 0, 0));
    const std::string path = std::string(RFIR_BINARY_DIR) + "/test_read_counts.txt";
    m.saveToTextFile(path);
    const auto f = rfir::common::loadMapFile(path);
    ASSERT_EQ(f.size(), 1u);
    ASSERT_TRUE(f[0].reads && f[0].contradicted);
    EXPECT_EQ(*f[0].reads, 6u);
    EXPECT_EQ(*f[0].contradicted, 1u);
    // The prior-map reader takes the same file.
    CRFIDTagParticleMap prior;
    prior.loadPriorFromTextFile(path);
    EXPECT_EQ(prior.tagCount(), 1u);
    std::remove(path.c_str());
    const auto load = [](const std::string& text) {
        std::istringstream in(text);
        return rfir::common::loadMapFile(in, "map.txt");
    };
    EXPECT_FALSE(load("tag a 1 2\n")[0].reads);
    EXPECT_FALSE(load("tag a 1 2 0.1 0.1\n")[0].reads);
    EXPECT_EQ(*load("tag a 1 2 0.1 0.1 7 2\n")[0].contradicted, 2u);
    for (const char* bad : {"tag a 1 2 0.1 0.1 3 5\n", "tag a 1 2 0.1 0.1 -1 0\n",
                            "tag a 1 2 0.1 0.1 3\n", "tag a 1 2 0.1 0.1 2.5 1\n"})
        EXPECT_THROW(load(bad), std::runtime_error) << bad;
    // Written back with the counts, after the stds.
    rfir::common::TMapFile out = load("tag a 1 2 0.1 0.1 7 2\n");
    const std::string p2 = std::string(RFIR_BINARY_DIR) + "/test_read_counts2.txt";
    rfir::common::saveMapFile(p2, out);
    EXPECT_EQ(*rfir::common::loadMapFile(p2)[0].reads, 7u);
    std::remove(p2.c_str());
}

// Issue 12's bar on two stock fault INIs (60 mm loop with slips; with bias,
// slips, a dead reader and ghost reads), seeds 1-3: PF- and PS-SLAM within
// 1.25 x FastSLAM's mean robot error with zero resets. Without the map
// correction they missed it on 5 of these 6 runs (1.36-1.77 x: the one shared
// map keeps the first lap's drift, docs/slam.md); with it, the summed error
// must also fall. Thresholds are the issue's, set before the runs.
TEST(MapCorrection, FaultInisWithinFastSlam) {
    for (const char* ini : {"sim_faults_slips.ini", "sim_faults_combined.ini"}) {
        const auto c =
            rfir::sim::loadSimConfig(std::string(RFIR_SOURCE_DIR) + "/config_ini/" + ini);
        for (uint64_t seed = 1; seed <= 3; seed++) {
            const auto sim = rfir::sim::simulate(c, seed);
            const double fs = runMethod(sim, stockConfig("fastslam"), seed).robot;
            for (const char* m : {"pf", "ps"}) {
                const auto on = runMethod(sim, stockConfig(m), seed);
                const auto off = runMethod(
                    sim, stockConfig(m, {{"slam.map_correction", "false"}}), seed);
                std::cout << ini << " seed " << seed << " " << m << ": " << 1e3 * on.robot
                          << " mm (" << on.run.resets
                          << " resets), without the correction " << 1e3 * off.robot
                          << " mm, FastSLAM " << 1e3 * fs << " mm\n";
                EXPECT_LE(on.robot, 1.25 * fs) << ini << " seed " << seed << " " << m;
                EXPECT_EQ(on.run.resets, 0u) << ini << " seed " << seed << " " << m;
                EXPECT_LT(on.robot, off.robot) << ini << " seed " << seed << " " << m;
            }
        }
    }
}
