/* rfir_slam: parts checked alone (copy-on-write trie, EKF by hand, FastSLAM
 * copy counting, INI rejection, sensor resetting geometry). */
#include <rfir/models/random.h>
#include <rfir/models/robot_resampling.h>
#include <rfir/slam/CFastSLAMParticles.h>
#include <rfir/slam/CRobotPoseParticles.h>
#include <rfir/slam/kidnap.h>
#include <rfir/slam/persistent_vector.h>
#include <rfir/slam/slam_config.h>
#include <rfir/slam/slam_engine.h>

#include <gtest/gtest.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/random/RandomGenerators.h>

#include <fstream>
#include <sstream>

using namespace rfir::slam;

TEST(SlamPersistentVector, CopiesAreIndependent) {
    CPersistentVector<int> a;
    for (int i = 0; i < 300; i++) a.set(size_t(i), std::make_shared<const int>(i));
    CPersistentVector<int> b = a;  // one pointer copy
    b.set(7, std::make_shared<const int>(-7));
    b.set(1000, std::make_shared<const int>(1000));
    EXPECT_EQ(*a.get(7), 7);
    EXPECT_EQ(*b.get(7), -7);
    EXPECT_EQ(a.get(1000), nullptr);
    EXPECT_EQ(*b.get(1000), 1000);
    EXPECT_EQ(b.get(299), a.get(299));  // untouched elements are shared
    EXPECT_EQ(a.get(5000), nullptr);
}

TEST(SlamEKF, RfidUpdateByHand) {
    // A tag at (1, 0) with variance 0.01 in x and y, measured at the reader
    // centre (0.5, 0) of a robot at (0.45, 0, 0) with R = 0.01 I: the gain is
    // 1/2 and the mean moves halfway to 0.95.
    TGaussianMeasurementParams p;
    p.rfidStdFactor = 1.0;
    CGaussianLandmarkModel model(p);
    TDetection d;
    d.a = 0.5;
    d.halfX = d.halfY = 0.1;
    TLandmarkEKF lm;
    lm.mean = {1.0, 0.0};
    lm.cov = 0.01 * Eigen::Matrix2d::Identity();
    const mrpt::poses::CPose2D robot(0.45, 0, 0);
    const double ll = ekfUpdate(lm, model.linearize(d, robot, lm.mean));
    EXPECT_NEAR(lm.mean.x(), 0.975, 1e-12);
    EXPECT_NEAR(lm.cov(0, 0), 0.005, 1e-12);
    // log N(0.05; 0, 0.02) * N(0; 0, 0.02)
    const double expect =
        -0.5 * (0.0025 / 0.02) - 0.5 * std::log(0.02 * 0.02) - std::log(2 * M_PI);
    EXPECT_NEAR(ll, expect, 1e-12);
}

TEST(SlamEKF, RangeBearingInverseMatchesPrediction) {
    CGaussianLandmarkModel model({});
    TDetection d;
    d.kind = TDetection::Kind::RangeBearing;
    d.a = 0.4;
    d.b = 0.3;
    d.sensor = mrpt::poses::CPose2D(0.1, 0.0, 0.2);
    const mrpt::poses::CPose2D robot(1, 2, 0.5);
    const TLandmarkEKF lm = model.initialize(d, robot);
    const TLinearMeasurement z = model.linearize(d, robot, lm.mean);
    EXPECT_NEAR(z.innovation.norm(), 0.0, 1e-12);
}

TEST(SlamFastSLAM, ResamplingSharesLandmarks) {
    mrpt::random::getRandomGenerator().randomize(3);  // MRPT's own resampling here
    rfir::models::TRandom rng(3);
    CFastSLAMParticles pf;
    pf.reset(mrpt::poses::CPose2D(), 200, 0.01, 0.01, rng);
    std::vector<TDetection> dets;
    for (int k = 0; k < 50; k++) {
        TDetection d;
        d.id = "T" + std::to_string(k);
        d.a = 0.01 * k;
        d.halfX = d.halfY = 0.03;
        dets.push_back(d);
    }
    mrpt::bayes::CParticleFilter filter;
    filter.m_options.resamplingMethod = mrpt::bayes::CParticleFilter::prSystematic;
    filter.m_options.BETA = 1.01;  // resample on every step
    mrpt::obs::CActionCollection none;
    pf.setDetections(&dets);
    filter.executeOn(pf, &none, nullptr);  // creates 50 EKFs per particle
    const size_t before = TLandmarkEKF::copyCount();
    filter.executeOn(pf, &none, nullptr);  // updates all 50 once per particle
    EXPECT_EQ(TLandmarkEKF::copyCount() - before, 200u * 50u);
    // Resampling alone copies no EKF.
    std::vector<size_t> idx(200, 0);
    const size_t c0 = TLandmarkEKF::copyCount();
    pf.performSubstitution(idx);
    EXPECT_EQ(TLandmarkEKF::copyCount(), c0);
    ASSERT_EQ(pf.landmarkCount(), 50u);
    const auto lms = pf.landmarks();
    EXPECT_NEAR(lms[10].mean.x(), 0.1, 0.05);
}

namespace {
std::string stockIni(const std::string& m) {
    std::ifstream f(std::string(RFIR_SOURCE_DIR) + "/config_ini/slam_" + m + ".ini");
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}
/** Loading the stock pf INI with `edit` appended to `section` throws a message
 * containing `expect`. */
void expectRejected(const std::string& section, const std::string& key,
                    const std::string& value) {
    mrpt::config::CConfigFileMemory mem(stockIni("pf"));
    mem.write(section, key, value);
    try {
        loadSlamConfig(mem);
        FAIL() << "accepted: [" << section << "] " << key << " = " << value;
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find(key), std::string::npos)
            << "message: " << e.what();
        EXPECT_NE(std::string(e.what()).find(section), std::string::npos)
            << "message: " << e.what();
    }
}
}  // namespace

TEST(SlamConfig, StockInisLoad) {
    for (const char* m : {"pf", "ps", "fastslam"}) {
        mrpt::config::CConfigFileMemory mem(stockIni(m));
        const TSlamConfig c = loadSlamConfig(mem);
        EXPECT_EQ(methodName(c.slam.method), m);
        EXPECT_EQ(c.slam.robot_particles, 500u);
        const std::string dump = dumpSlamConfig(c);
        // The dump is itself a valid config with the same settings.
        mrpt::config::CConfigFileMemory again(dump);
        EXPECT_EQ(dumpSlamConfig(loadSlamConfig(again)), dump);
    }
}

TEST(SlamConfig, BadSettingsNameTheKey) {
    expectRejected("slam", "robot_particles", "0");
    expectRejected("slam", "robot_particles", "-5");
    expectRejected("slam", "method", "gmapping");
    expectRejected("slam", "resampling", "roulette");
    expectRejected("slam", "robot_particle", "100");
    expectRejected("motion", "a5", "0.1");
    expectRejected("kidnap", "collapse_step", "2");
    expectRejected("fastslam", "rfid_std", "1");
    expectRejected("tagmap", "lag", "0");
    expectRejected("tagmap", "lag", "-3");
    expectRejected("tagmap", "num_particles", "0");
    expectRejected("tagmap_likelihood", "robot_updates", "literal");
    mrpt::config::CConfigFileMemory mem(stockIni("pf") + "\n[slma]\nmethod = pf\n");
    EXPECT_THROW(loadSlamConfig(mem), std::invalid_argument);
    mrpt::config::CConfigFileMemory ok(stockIni("pf"));
    EXPECT_THROW(loadSlamConfig(ok, std::string("pff")), std::invalid_argument);
}

namespace {
/** A read of a tag `local` (robot frame) from pose `at`, by a reader of
 * half side `half` centred on the robot's x axis at 0.1 m. */
TAnchor anchorSeen(const char* id, const mrpt::poses::CPose2D& at,
                   const mrpt::math::TPoint2D& local, double half) {
    TAnchor a;
    a.det.id = id;
    a.det.a = 0.1;
    a.det.halfX = a.det.halfY = half;
    at.composePoint(local.x, local.y, a.x, a.y);
    return a;
}

/** Share of the resetting's poses within 0.1 rad and 0.15 m of `truth`. */
double shareNear(const std::vector<mrpt::poses::CPose2D>& ps,
                 const mrpt::poses::CPose2D& truth) {
    size_t near = 0;
    for (const auto& p : ps)
        near += std::abs(mrpt::math::wrapToPi(p.phi() - truth.phi())) < 0.1 &&
                p.distanceTo(truth) < 0.15;
    return double(near) / double(ps.size());
}
}  // namespace

TEST(SlamKidnap, PairsOfTheRunGiveTheHeading) {
    // The robot read A, drove about a metre, and reads B; the odometry has
    // its own frame. Two 60 mm reads a metre apart fix the heading within
    // about 0.06 rad, so every pose drawn from the pair is near the truth,
    // while uniform headings leave almost none there.
    const mrpt::poses::CPose2D now(2, 1, 0.7),
        before = now + mrpt::poses::CPose2D(-1, 0.2, -0.3);
    const mrpt::poses::CPose2D odoBefore(10, -5, 2.0),
        odoNow = odoBefore + (now - before);
    const double half = 0.03;
    const std::vector<TRunAnchor> run{
        {anchorSeen("A", before, {0.12, 0.02}, half), odoBefore}};
    const std::vector<TAnchor> b{anchorSeen("B", now, {0.08, -0.02}, half)};
    TKidnapOptions o;
    o.keep_heading_share = 0;
    o.pair_heading_share = 1;
    rfir::models::TRandom rng(9);
    const auto paired = resettingPoses(b, odoNow, run, 200, 0, o, rng);
    ASSERT_EQ(paired.size(), 200u);
    EXPECT_EQ(shareNear(paired, now), 1.0);
    for (const auto& p : paired) {  // and each explains this step's read
        const auto local = mrpt::poses::CPose2D(b[0].x, b[0].y, 0) - p;
        EXPECT_LE(std::abs(local.x() - 0.1), half + 1e-9);
        EXPECT_LE(std::abs(local.y()), half + 1e-9);
    }
    o.pair_min_distance = 5;  // A too close to pair: uniform headings
    EXPECT_LT(shareNear(resettingPoses(b, odoNow, run, 200, 0, o, rng), now), 0.2);
    o.pair_min_distance = 0.5;
    o.pair_heading_share = 0;
    EXPECT_LT(shareNear(resettingPoses(b, odoNow, run, 200, 0, o, rng), now), 0.2);
}

TEST(SlamKidnap, ResettingPosesExplainTheDetection) {
    rfir::models::TRandom rng(5);
    TAnchor a;
    a.det.id = "T";
    a.det.a = 0.2;
    a.det.b = -0.1;
    a.det.halfX = 0.03;
    a.det.halfY = 0.05;
    a.x = 3;
    a.y = 4;
    for (int i = 0; i < 100; i++) {
        const double phi = rng.drawUniform(-M_PI, M_PI);
        const auto p = poseFromAnchor(a, phi, rng);
        // The tag seen from p lies inside the reader's area.
        const auto local = mrpt::poses::CPose2D(a.x, a.y, 0) - p;
        EXPECT_LE(std::abs(local.x() - 0.2), 0.03 + 1e-9);
        EXPECT_LE(std::abs(local.y() + 0.1), 0.05 + 1e-9);
        EXPECT_NEAR(p.phi(), phi, 1e-9);
    }
    TKidnapOptions o;
    o.collapse_steps = 2;
    o.min_tags = 2;
    o.evidence_drop = 50;
    CKidnapMonitor m(o);
    auto step = [](double t, double ll, std::vector<std::string> ids) {
        TStepEvidence e;
        e.t = t;
        e.reads = ids.empty() ? 1 : ids.size();
        e.bestMeanLogLik = e.meanLogEvidence = ll;
        e.disagreeing = std::move(ids);
        return e;
    };
    EXPECT_FALSE(m.update(step(0, -0.1, {})));  // agreeing: the long-term level
    EXPECT_FALSE(m.update(step(1, -1000, {"A"})));
    EXPECT_TRUE(m.suspicious());
    EXPECT_FALSE(m.update(TStepEvidence{}));  // no read: no evidence
    // Two disagreeing steps, but the same tag: not yet.
    EXPECT_FALSE(m.update(step(2, -1000, {"A"})));
    EXPECT_TRUE(m.update(step(3, -1000, {"B"})));
    EXPECT_FALSE(m.update(step(4, -0.1, {})));
    EXPECT_FALSE(m.suspicious());
    // A mild disagreement over many tags is not a drop: with the persistence
    // criterion off (stock), no reset however many tags disagree.
    ASSERT_EQ(o.persist_tags, 0u);
    CKidnapMonitor mild(o);
    EXPECT_FALSE(mild.update(step(0, -0.1, {})));
    for (int k = 1; k < 20; k++)
        EXPECT_FALSE(mild.update(step(k, -10, {"T" + std::to_string(k)})));
    EXPECT_EQ(mild.resets(), 0u);
    // With it (persist_tags = 12): a run that 12 distinct tags contradict,
    // with no agreeing read, resets at its 12th tag (a robot put down a metre
    // away among 300 mm readers); one agreeing read before that ends the run.
    o.persist_tags = 12;
    CKidnapMonitor persist(o);
    EXPECT_FALSE(persist.update(step(0, -0.1, {})));
    for (int k = 1; k < 12; k++)
        EXPECT_FALSE(persist.update(step(0.1 * k, -10, {"T" + std::to_string(k)})));
    EXPECT_TRUE(persist.update(step(1.2, -10, {"T12"})));
    CKidnapMonitor corrected(o);
    EXPECT_FALSE(corrected.update(step(0, -0.1, {})));
    for (int k = 1; k < 20; k++) {
        auto e = step(0.1 * k, -10, {"T" + std::to_string(k)});
        if (k == 11) e.agreeing = 1;
        EXPECT_FALSE(corrected.update(e)) << k;
    }
    // A run ends after max_gap seconds without a disagreeing step.
    CKidnapMonitor gap(o);
    EXPECT_FALSE(gap.update(step(0, -0.1, {})));
    EXPECT_FALSE(gap.update(step(1, -1000, {"A"})));
    EXPECT_FALSE(gap.update(step(1 + o.max_gap + 1, -1000, {"B"})));
    EXPECT_TRUE(gap.update(step(1 + o.max_gap + 2, -1000, {"C"})));
    EXPECT_EQ(m.resets(), 1u);
    // Ghost reads: every step has one read that contradicts the best particle
    // badly, but also one it explains; no run of disagreeing steps opens.
    CKidnapMonitor ghost(o);
    EXPECT_FALSE(ghost.update(step(0, -0.1, {})));
    for (int k = 1; k < 20; k++) {
        auto e = step(k, -500, {"G" + std::to_string(k)});
        e.reads = 2;
        e.agreeing = 1;
        EXPECT_FALSE(ghost.update(e));
        EXPECT_FALSE(ghost.suspicious());
    }
    EXPECT_EQ(ghost.resets(), 0u);
}

// Sensor resetting weighs what it injects (Mixture MCL): a pose that explains
// the step gets the step's best prior weight plus its own term, so it
// outweighs every particle of the lost set, and a pose that explains nothing
// does not (before, each injected pose got the lost set's best weight).
TEST(SlamKidnap, InjectedPosesAreWeighedByTheStep) {
    struct TModel : CRobotPoseParticles::IStepModel {
        void afterMotion() override {}
        bool weighs() const override { return true; }
        double logLikelihood(size_t, const CParticlePose2D& p) const override {
            return ll(p);
        }
        static double ll(const mrpt::poses::CPose2D& p) {  // the truth is at (1, 0)
            return -50.0 * ((p.x() - 1) * (p.x() - 1) + p.y() * p.y());
        }
    } model;
    rfir::models::TRandom rng(5);
    CRobotPoseParticles pf;
    pf.reset(mrpt::poses::CPose2D(0, 0, 0), 100, 0.05, 0.01, rng);  // lost
    pf.setStepModel(&model);
    mrpt::bayes::CParticleFilter filter;
    filter.m_options = rfir::models::withoutMrptResampling(filter.m_options);
    mrpt::obs::CActionCollection none;
    filter.executeOn(pf, &none, nullptr);
    double bestOld = -1e300;
    for (size_t i = 0; i < pf.m_particles.size(); i++)
        bestOld = std::max(bestOld, pf.getW(i));
    const double prior = pf.bestPriorLogW();
    const mrpt::poses::CPose2D good(1, 0, 0), bad(3, 0, 0);
    pf.replacePose(0, good, prior + TModel::ll(good), TModel::ll(good));
    pf.replacePose(1, bad, prior + TModel::ll(bad), TModel::ll(bad));
    EXPECT_GT(pf.getW(0), bestOld + 20);
    EXPECT_LT(pf.getW(1), bestOld - 100);
    // The step's evidence still reads the weighing's terms: both now carry
    // the best prior under their own terms, and the best prior the next
    // injection starts from is unchanged.
    EXPECT_NEAR(pf.getW(0) - pf.stepLogLik()[0], prior, 1e-9);
    EXPECT_NEAR(pf.getW(1) - pf.stepLogLik()[1], prior, 1e-9);
    EXPECT_NEAR(pf.bestPriorLogW(), prior, 1e-9);
}
