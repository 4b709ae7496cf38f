// The simulator's RFID and odometry faults (docs/simulator.md, "Faults"): each
// does what it says, measured against the ground truth and against the same
// run without it, and the ground-truth records name every injected fault.
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/sim/simulator.h>

#include <mrpt/core/bits_math.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

using namespace rfir::sim;
using mrpt::poses::CPose2D;

namespace {
TSimConfig stock(const std::string& name, const std::vector<std::string>& sets = {}) {
    return loadSimConfig(std::string(RFIR_SOURCE_DIR) + "/config_ini/" + name + ".ini",
                         sets);
}

rfir::obs::CObservationRFIDReaders::Ptr rfidOf(const TSimStep& s) {
    for (const auto& o : s.obs)
        if (auto r = std::dynamic_pointer_cast<rfir::obs::CObservationRFIDReaders>(o))
            return r;
    return {};
}

/** The fault records of one kind, split into fields. */
std::vector<std::vector<std::string>> records(const TSimOutput& out,
                                              const std::string& kind) {
    std::vector<std::vector<std::string>> v;
    for (const auto& line : out.faults) {
        std::istringstream is(line);
        std::vector<std::string> f;
        for (std::string w; is >> w;) f.push_back(w);
        if (!f.empty() && f[0] == kind) v.push_back(f);
    }
    return v;
}

/** Reads per (step, reader), as "t reader" -> tags. */
std::map<std::pair<double, std::string>, std::vector<std::string>> readsOf(
    const TSimOutput& out) {
    std::map<std::pair<double, std::string>, std::vector<std::string>> m;
    for (const auto& s : out.steps)
        if (auto r = rfidOf(s))
            for (const auto& rd : r->readings) m[{s.t, rd.reader.id}] = rd.tags;
    return m;
}

/** Odometry increment of step k (robot frame of step k - 1). */
CPose2D increment(const TSimOutput& o, size_t k) {
    return *o.steps[k].odometry - *o.steps[k - 1].odometry;
}

/** |k - n p| within 4.5 binomial standard deviations. */
void expectBinomial(size_t k, size_t n, double p) {
    const double sd = std::sqrt(n * p * (1 - p));
    EXPECT_LT(std::abs(double(k) - n * p), 4.5 * sd) << k << " of " << n << " at " << p;
}
}  // namespace

TEST(SimFaults, OffByDefaultAndOnlyWhenAsked) {
    const TSimConfig c;
    EXPECT_FALSE(c.hasFaults());
    EXPECT_FALSE(c.asyncTiming());
    auto clean = stock("sim_rfid_60mm_16tags_loop");
    clean.maxDuration = 20;
    const auto out = simulate(clean, 1);
    EXPECT_FALSE(out.hasFaults);
    EXPECT_TRUE(out.faults.empty());
    for (const char* n :
         {"sim_faults_ghost", "sim_faults_dead_reader", "sim_faults_slips",
          "sim_faults_bias", "sim_faults_async", "sim_faults_combined"})
        EXPECT_TRUE(stock(n).hasFaults()) << n;
}

// Ghost reads: at the configured rate per poll, real tags 0.2-0.6 m from the
// reader, and every other read exactly as without ghosts.
TEST(SimFaults, GhostRateDistanceAndGroundTruth) {
    const auto cfg = stock("sim_faults_ghost");
    ASSERT_DOUBLE_EQ(cfg.rfid.ghostRate, 0.01);
    const auto out = simulate(cfg, 4);
    const auto clean = simulate(stock("sim_faults_ghost", {"rfid.ghost_rate=0"}), 4);
    ASSERT_EQ(out.steps.size(), clean.steps.size());
    std::map<std::string, CPose2D> tagAt;
    for (const auto& e : out.gtMap) tagAt[e.id] = CPose2D(e.x, e.y, 0);
    std::map<std::string, rfir::obs::TRFIDReader> reader;
    for (const auto& r : cfg.readers) reader[r.id] = r;
    std::map<double, CPose2D> truth;
    for (const auto& s : out.steps) truth[s.t] = s.truePose;

    auto reads = readsOf(out);
    const auto cleanReads = readsOf(clean);
    const auto ghosts = records(out, "ghost");
    for (const auto& g : ghosts) {
        ASSERT_EQ(g.size(), 5u);
        const double t = std::stod(g[1]);
        auto it = reads.find({t, g[2]});
        ASSERT_NE(it, reads.end()) << g[1];
        auto& tags = it->second;
        ASSERT_FALSE(tags.empty());
        EXPECT_EQ(tags.back(), g[3]);  // a ghost follows the real reads
        tags.pop_back();
        // A real tag at the recorded distance, 0.2-0.6 m from the reader.
        const auto& r = reader.at(g[2]);
        const auto rc = truth.at(t) + CPose2D(r.x, r.y, 0);
        ASSERT_TRUE(tagAt.count(g[3]));
        const double d = rc.distanceTo(tagAt[g[3]]);
        EXPECT_NEAR(d, std::stod(g[4]), 1e-9);
        EXPECT_GE(d, 0.2);
        EXPECT_LE(d, 0.6);
    }
    // Without the ghosts the log is the clean one, read for read.
    EXPECT_TRUE(reads == cleanReads);
    expectBinomial(ghosts.size(), reads.size(), 0.01);
    EXPECT_EQ(reads.size(), out.steps.size() * cfg.readers.size());  // every poll
}

// A dead reader is polled (its empty reading is written) and reads nothing in
// its interval; it reads in the clean run and outside the interval.
TEST(SimFaults, DeadReaderReadsNothingInItsInterval) {
    const auto cfg = stock("sim_faults_dead_reader");
    ASSERT_EQ(cfg.rfid.deadReaders.size(), 2u);
    const auto out = simulate(cfg, 2);
    auto cleanCfg = cfg;
    cleanCfg.rfid.deadReaders.clear();
    const auto clean = simulate(cleanCfg, 2);
    size_t inside = 0, cleanInside = 0, outside = 0, empty = 0;
    for (size_t k = 0; k < out.steps.size(); k++) {
        const double e = out.steps[k].t - cfg.startTime;
        const auto r = rfidOf(out.steps[k]), rc = rfidOf(clean.steps[k]);
        ASSERT_TRUE(r && rc);
        ASSERT_EQ(r->readings.size(), cfg.readers.size());
        for (const auto& d : cfg.rfid.deadReaders) {
            const auto& tags = r->readings[d.reader].tags;
            empty += tags.empty();
            if (e >= d.from && e < d.to)
                inside += tags.size(), cleanInside += rc->readings[d.reader].tags.size();
            else
                outside += tags.size();
        }
    }
    EXPECT_EQ(inside, 0u);
    EXPECT_GT(cleanInside, 20u);
    EXPECT_GT(outside, 50u);
    EXPECT_GT(empty, 1000u);
    const auto dead = records(out, "dead_reader");
    ASSERT_EQ(dead.size(), 2u);
    EXPECT_EQ(dead[0][1], "R2");
    EXPECT_EQ(std::stod(dead[0][2]), cfg.startTime + 60);
    EXPECT_EQ(std::stod(dead[0][3]), cfg.startTime + 120);
}

// empty_polls = omit drops exactly the readings with no tag.
TEST(SimFaults, EmptyPollsWrittenOrOmitted) {
    auto cfg = stock("sim_faults_combined");
    cfg.maxDuration = 40;
    const auto written = simulate(cfg, 3);
    cfg.rfid.writeEmptyPolls = false;
    const auto omitted = simulate(cfg, 3);
    size_t emptyW = 0, tagsW = 0, tagsO = 0, readingsO = 0, noObs = 0;
    for (size_t k = 0; k < written.steps.size(); k++) {
        const auto w = rfidOf(written.steps[k]);
        ASSERT_TRUE(w);
        ASSERT_EQ(w->readings.size(), cfg.readers.size());
        for (const auto& rd : w->readings)
            emptyW += rd.tags.empty(), tagsW += rd.tags.size();
        const auto o = rfidOf(omitted.steps[k]);
        if (!o) {
            noObs++;
            continue;
        }
        for (const auto& rd : o->readings) {
            EXPECT_FALSE(rd.tags.empty());
            tagsO += rd.tags.size(), readingsO++;
        }
    }
    EXPECT_GT(emptyW, 100u);
    EXPECT_GT(noObs, 10u);
    EXPECT_EQ(tagsO, tagsW);
    EXPECT_EQ(readingsO + emptyW, written.steps.size() * cfg.readers.size());
}

// A slip adds its size along the motion to the odometry of its interval and
// nothing elsewhere; the odometry error against the truth jumps there.
TEST(SimFaults, SlipShowsInOdometryAgainstTruth) {
    const auto cfg = stock("sim_faults_slips");
    const auto out = simulate(cfg, 5);
    auto cleanCfg = cfg;
    cleanCfg.odometry.slipTimes.clear();
    const auto clean = simulate(cleanCfg, 5);
    const auto slips = records(out, "slip");
    ASSERT_EQ(slips.size(), 3u);
    std::set<double> slipT;
    for (const auto& s : slips) slipT.insert(std::stod(s[1]));
    size_t seen = 0;
    for (size_t k = 1; k < out.steps.size(); k++) {
        const CPose2D a = increment(out, k), b = increment(clean, k);
        const double dt = std::hypot(a.x() - b.x(), a.y() - b.y());
        const double dphi = std::remainder(a.phi() - b.phi(), 2 * M_PI);
        // Against the truth: the reported increment errs by the slip there,
        // by the random noise only (< 2 cm per 2 cm step) elsewhere.
        const CPose2D tr = out.steps[k].truePose - out.steps[k - 1].truePose;
        const double vsTruth = std::hypot(a.x() - tr.x(), a.y() - tr.y());
        if (slipT.count(out.steps[k].t)) {
            seen++;
            EXPECT_NEAR(dt, 0.05, 1e-9);
            EXPECT_NEAR(dphi, mrpt::DEG2RAD(2.0), 1e-9);
            EXPECT_GT(vsTruth, 0.035) << out.steps[k].t;
        } else {
            EXPECT_LT(dt, 1e-9) << out.steps[k].t;
            EXPECT_LT(std::abs(dphi), 1e-9) << out.steps[k].t;
            EXPECT_LT(vsTruth, 0.02) << out.steps[k].t;
        }
    }
    EXPECT_EQ(seen, 3u);
    // slip_count draws that many more, at times inside the run.
    auto more = stock("sim_faults_slips", {"odometry.slip_count=4"});
    EXPECT_EQ(records(simulate(more, 5), "slip").size(), 7u);
}

// Fixed systematic errors: the along-track odometry is (1 + scale_error) times
// the truth's and the heading drifts heading_drift_error per metre, on top of
// the very same random noise.
TEST(SimFaults, SystematicOdometryError) {
    auto cfg = stock("sim_faults_bias");
    cfg.maxDuration = 60;
    const auto out = simulate(cfg, 6);
    EXPECT_DOUBLE_EQ(out.scaleBias, 0.02);
    EXPECT_DOUBLE_EQ(out.headingDrift, 0.01);
    EXPECT_DOUBLE_EQ(out.rotScaleBias, -0.01);
    auto cleanCfg = cfg;
    cleanCfg.odometry.scaleError = cleanCfg.odometry.rotScaleError =
        cleanCfg.odometry.headingDriftError = 0;
    const auto clean = simulate(cleanCfg, 6);
    double along = 0, alongClean = 0, length = 0, dphi = 0;
    for (size_t k = 1; k < out.steps.size(); k++) {
        const CPose2D t = out.steps[k].truePose - out.steps[k - 1].truePose;
        const double d = std::hypot(t.x(), t.y());
        if (d < 1e-12) continue;
        const CPose2D a = increment(out, k), b = increment(clean, k);
        along += (a.x() * t.x() + a.y() * t.y()) / d;
        alongClean += (b.x() * t.x() + b.y() * t.y()) / d;
        dphi += std::remainder(a.phi() - b.phi(), 2 * M_PI);
        length += d;
    }
    ASSERT_GT(length, 10);
    EXPECT_NEAR((along - alongClean) / length, 0.02, 1e-3);
    EXPECT_NEAR(dphi / length, 0.01, 1e-4);
}

// Round-robin polls: one reader at a time, in turn, 5 Hz each, within the
// jitter of their slots; odometry at 25 Hz reporting the pose 20 ms earlier.
TEST(SimFaults, AsyncPollsAndOdometryLatency) {
    auto cfg = stock("sim_faults_async");
    cfg.maxDuration = 20;
    // Noise-free odometry: what is left is the latency.
    cfg.odometry.kXY = cfg.odometry.kPhiRot = cfg.odometry.kPhiXY = 0;
    const auto out = simulate(cfg, 7);
    const double slot = 1.0 / (cfg.rfid.pollRate * cfg.readers.size());
    auto tick = [&](double t) { return std::llround((t - cfg.startTime) * 1e4); };
    std::map<long long, CPose2D> truth;
    for (const auto& s : out.steps) truth[tick(s.t)] = s.truePose;
    std::vector<size_t> perReader(cfg.readers.size(), 0);
    size_t polls = 0, odo = 0, lagChecked = 0;
    for (const auto& s : out.steps) {
        const double e = s.t - cfg.startTime;
        if (s.odometry) {
            odo++;
            EXPECT_NEAR(std::remainder(e, 0.04), 0, 1e-9) << s.t;
            auto it = truth.find(tick(s.t) - 200);  // 20 ms earlier
            if (it != truth.end() && e >= 0.02) {
                lagChecked++;
                EXPECT_LT(s.odometry->distanceTo(it->second), 1e-9) << s.t;
            }
        }
        if (const auto r = rfidOf(s))
            for (const auto& rd : r->readings) {
                const size_t i = size_t(std::stoi(rd.reader.id.substr(1)));
                // Poll p = (n-th poll of reader i) * readers + i, at p * slot.
                const double p = double(perReader[i]++ * cfg.readers.size() + i);
                EXPECT_LE(std::abs(e - p * slot), cfg.rfid.pollJitter + 1e-4) << s.t;
                polls++;
            }
    }
    EXPECT_EQ(odo, size_t(20 / 0.04 + 1e-9) + 1);
    EXPECT_GT(lagChecked, 50u);
    EXPECT_EQ(polls, size_t(20 / slot + 1e-9) + 1);
    for (size_t n : perReader) EXPECT_NEAR(double(n), 100, 1);
}

TEST(SimFaults, BadFaultKeysNameSectionAndKey) {
    auto errorOf = [](const std::vector<std::string>& sets) -> std::string {
        try {
            simulate(stock("sim_faults_combined", sets), 1);
        } catch (const std::exception& e) {
            return e.what();
        }
        return {};
    };
    EXPECT_NE(errorOf({"rfid.dead_readers=9 1 2"}).find("[rfid] dead_readers"),
              std::string::npos);
    EXPECT_NE(errorOf({"rfid.dead_readers=1 5 2"}).find("[rfid] dead_readers"),
              std::string::npos);
    EXPECT_NE(errorOf({"rfid.ghost_distance=0.6 0.2"}).find("[rfid] ghost_distance"),
              std::string::npos);
    EXPECT_NE(errorOf({"rfid.polling=round_robin", "rfid.poll_jitter=0.02"})
                  .find("[rfid] poll_jitter"),
              std::string::npos);
    EXPECT_NE(errorOf({"odometry.slip_times=-3"}).find("[odometry] slip_times"),
              std::string::npos);
    EXPECT_NE(errorOf({"rfid.empty_polls=sometimes"}).find("[rfid] empty_polls"),
              std::string::npos);
}
