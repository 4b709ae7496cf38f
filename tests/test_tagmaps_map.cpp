// CRFIDTagParticleMap: insertion, likelihood, robot-update policies, O(1)
// updates, range-bearing landmarks, serialization, output.
#include "test_tagmaps_sim.h"

#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

using namespace tagmaps_test;
using rfir::maps::CRFIDTagParticleMap;
using rfir::maps::TRobotUpdatePolicy;

namespace {
rfir::obs::CObservationRFIDReaders::Ptr oneRead(const std::string& tag, double h = 0.03,
                                                double rx = 0.1, double ry = 0.0) {
    auto o = rfir::obs::CObservationRFIDReaders::Create();
    rfir::obs::CObservationRFIDReaders::TReading rd;
    rd.reader = reader("A", rx, ry, h);
    if (!tag.empty()) rd.tags.push_back(tag);
    o->readings.push_back(rd);
    return o;
}
}  // namespace

TEST(TagMap, NewTagSpreadsOverTheObservedReader) {
    CRFIDTagParticleMap m;
    // Geometry always comes from the observation: a 0.3 x 0.06 reader.
    auto o = rfir::obs::CObservationRFIDReaders::Create();
    rfir::obs::CObservationRFIDReaders::TReading rd;
    rd.reader = reader("W", 0.2, 0.0, 0.15);
    rd.reader.halfY = 0.03;
    rd.tags = {"E004"};
    o->readings.push_back(rd);
    ASSERT_TRUE(m.insertObservation(*o, pose3({1.0, 1.0, M_PI / 2})));
    const auto* t = m.getTag("E004");
    ASSERT_NE(t, nullptr);
    EXPECT_EQ(t->particles().size(), 100u);
    EXPECT_EQ(t->detections, 1u);
    EXPECT_EQ(t->visits, 1u);
    for (const auto& p : t->particles())  // reader centre (1, 1.2), rotated
    {
        EXPECT_LE(std::abs(p.x - 1.0), 0.03 + 1e-9);
        EXPECT_LE(std::abs(p.y - 1.2), 0.15 + 1e-9);
    }
    EXPECT_FALSE(m.isEmpty());
    EXPECT_EQ(m.getTag("nope"), nullptr);
    // A reader with no size is rejected, not guessed.
    auto bad = oneRead("X", 0.0);
    EXPECT_THROW(m.insertObservation(*bad, pose3({0, 0, 0})), std::exception);
}

TEST(TagMap, UpdateTouchesOnlyDetectedTags) {
    CRFIDTagParticleMap m;
    m.insertionOptions.params.numParticles = 20;
    for (int i = 0; i < 3000; i++)
        m.insertObservation(*oneRead("T" + std::to_string(i)), pose3({i * 0.5, 0, 0}));
    ASSERT_EQ(m.tagCount(), 3000u);
    const uint64_t before = m.totalTouched();
    m.insertObservation(*oneRead("T17"), pose3({17 * 0.5 + 0.01, 0, 0}));
    EXPECT_EQ(m.lastInsertTouched(), 1u);
    EXPECT_EQ(m.totalTouched(), before + 1);
    m.insertObservation(*oneRead(""), pose3({0, 0, 0}));  // nothing read
    EXPECT_EQ(m.lastInsertTouched(), 0u);
    EXPECT_EQ(m.getTag("T17")->detections, 2u);
    EXPECT_EQ(m.getTag("T18")->detections, 1u);
}

TEST(TagMap, LikelihoodIsLowerForAShiftedRobot) {
    // Map 4 tags/m^2 with exact poses, then score a fresh pass.
    const auto readers = ring(0.03);
    const auto tags = grid(6, 0.25);
    CRFIDTagParticleMap m;
    for (const auto& p : lawnmower(-0.3, 1.6, -0.3, 1.6, 0.05, 0.01))
        m.insertObservation(*sense(readers, tags, p), pose3(p));
    ASSERT_EQ(m.tagCount(), tags.size());
    // The step model is flat inside a reader, so one read may not tell a small
    // shift apart: compare sums over a fresh pass.
    const std::vector<mrpt::math::TPose2D> shifts = {
        {0.02, 0, 0}, {0, -0.02, 0}, {0.04, 0.03, 0}, {0, 0, 0.1}, {0, 0, -0.3}};
    double atTruth = 0;
    std::vector<double> shifted(shifts.size(), 0.0);
    int scored = 0;
    for (const auto& p : lawnmower(0.0, 1.3, 0.02, 1.3, 0.11, 0.037)) {
        const auto o = sense(readers, tags, p);
        if (o->detectionCount() == 0) continue;
        atTruth += m.computeObservationLikelihood(*o, pose3(p));
        for (size_t k = 0; k < shifts.size(); k++) {
            const double s = m.computeObservationLikelihood(*o, pose3(p + shifts[k]));
            EXPECT_TRUE(std::isfinite(s));
            shifted[k] += s;
        }
        scored++;
    }
    EXPECT_GT(scored, 20);
    for (size_t k = 0; k < shifts.size(); k++)
        EXPECT_LT(shifted[k], atTruth - 1.0) << "shift " << k;
    // Far away: still finite (the particle filter asserts it).
    const auto o = sense(readers, tags, {0.5, 0.5, 0});
    EXPECT_TRUE(std::isfinite(m.computeObservationLikelihood(*o, pose3({50, -40, 2}))));
}

TEST(TagMap, LikelihoodIsThreadSafe) {
    const auto readers = ring(0.03);
    const auto tags = grid(4, 0.25);
    CRFIDTagParticleMap m;
    for (const auto& p : lawnmower(-0.2, 1.0, -0.2, 1.0, 0.05, 0.02))
        m.insertObservation(*sense(readers, tags, p), pose3(p));
    const auto o = sense(readers, tags, {0.26, 0.3, 0.1});
    std::vector<double> serial(400), parallel(400);
    auto poseOf = [](size_t i) { return pose3({0.2 + 0.001 * i, 0.3, 0.1}); };
    for (size_t i = 0; i < serial.size(); i++)
        serial[i] = m.computeObservationLikelihood(*o, poseOf(i));
    std::vector<std::thread> th;
    for (size_t t = 0; t < 4; t++)
        th.emplace_back([&, t] {
            for (size_t i = t; i < parallel.size(); i += 4)
                parallel[i] = m.computeObservationLikelihood(*o, poseOf(i));
        });
    for (auto& x : th) x.join();
    EXPECT_EQ(serial, parallel);
}

TEST(TagMap, RobotUpdatePolicies) {
    const auto far = pose3({3.0, 0.0, 0.0});  // a pose that disagrees strongly
    for (auto policy : {TRobotUpdatePolicy::Literal, TRobotUpdatePolicy::Revisit,
                        TRobotUpdatePolicy::RevisitAll}) {
        CRFIDTagParticleMap m;
        m.likelihoodOptions.robotUpdate = policy;
        EXPECT_EQ(m.updateTagsBeforeWeighing(), policy == TRobotUpdatePolicy::Literal);
        const auto o = oneRead("T");
        m.insertObservation(*o, pose3({0, 0, 0}));  // first read
        const double consecutive = m.computeObservationLikelihood(*o, far);
        EXPECT_FALSE(m.isNewVisit("T"));
        m.insertObservation(*o, pose3({0, 0, 0}));            // still the first pass
        m.insertObservation(*oneRead(""), pose3({1, 0, 0}));  // tag out of view
        EXPECT_TRUE(m.isNewVisit("T"));
        const double revisit = m.computeObservationLikelihood(*o, far);
        EXPECT_LT(revisit, -100.0) << "a new visit must weigh the robot";
        m.insertObservation(*o, pose3({0, 0, 0}));  // second visit starts
        EXPECT_EQ(m.getTag("T")->visits, 2u);
        const double within = m.computeObservationLikelihood(*o, far);
        if (policy == TRobotUpdatePolicy::Literal) {
            EXPECT_LT(consecutive, -100.0);  // every read weighs the robot
            EXPECT_LT(within, -100.0);
        } else {
            EXPECT_EQ(consecutive, 0.0) << "consecutive reads of the first pass ignored";
            if (policy == TRobotUpdatePolicy::Revisit)
                EXPECT_EQ(within, 0.0);
            else  // against the estimate frozen at the start of the visit
                EXPECT_EQ(within, revisit);
        }
    }
    // revisit_min_gap = 2: one empty observation is not enough to end a visit.
    CRFIDTagParticleMap m;
    m.likelihoodOptions.robotUpdate = TRobotUpdatePolicy::Revisit;
    m.likelihoodOptions.revisitMinGap = 2;
    m.insertObservation(*oneRead("T"), pose3({0, 0, 0}));
    m.insertObservation(*oneRead(""), pose3({0, 0, 0}));
    EXPECT_EQ(m.computeObservationLikelihood(*oneRead("T"), far), 0.0);
    m.insertObservation(*oneRead(""), pose3({0, 0, 0}));
    EXPECT_LT(m.computeObservationLikelihood(*oneRead("T"), far), -100.0);
}

TEST(TagMap, RevisitNeedsTravelWhenAsked) {
    // revisit_min_travel: reads separated by a short gap (the tag passing from
    // one reader to the next) stay in one visit; a long trip makes a new one.
    const auto far = pose3({3.0, 0.0, 0.0});
    CRFIDTagParticleMap m;
    m.likelihoodOptions.robotUpdate = TRobotUpdatePolicy::Revisit;
    m.likelihoodOptions.revisitMinTravel = 0.5;
    // The reads below are 0.3 m apart, more than the reader explains: with
    // reseat_contradicted the third one places "T" again, which starts its
    // visits over. This test counts visits alone.
    m.insertionOptions.reseatContradicted = false;
    m.insertObservation(*oneRead("T"), pose3({0, 0, 0}));
    m.insertObservation(*oneRead(""), pose3({0.1, 0, 0}));
    m.insertObservation(*oneRead(""), pose3({0.2, 0, 0}));
    EXPECT_FALSE(m.isNewVisit("T"));
    EXPECT_EQ(m.computeObservationLikelihood(*oneRead("T"), far), 0.0);
    m.insertObservation(*oneRead("T"), pose3({0.3, 0, 0}));  // same visit
    EXPECT_EQ(m.getTag("T")->visits, 1u);
    for (double x : {0.6, 0.9, 0.6, 0.35})  // away and back: 1.15 m since the read
        m.insertObservation(*oneRead(""), pose3({x, 0, 0}));
    EXPECT_TRUE(m.isNewVisit("T"));
    EXPECT_LT(m.computeObservationLikelihood(*oneRead("T"), far), -100.0);
    m.insertObservation(*oneRead("T"), pose3({0.3, 0, 0}));
    EXPECT_EQ(m.getTag("T")->visits, 2u);
    EXPECT_NEAR(m.getTag("T")->lastReadTravel, 1.5, 1e-12);
}

TEST(TagMap, RangeBearingLandmarks) {
    CRFIDTagParticleMap m;
    m.setLandmarkNames({"L0", "L1", ""});
    m.insertionOptions.estimator = rfir::models::kFixedLagSmootherName;
    m.insertionOptions.params.stepSigma = 0.002;
    const mrpt::math::TPoint2D truth(1.2, 0.4);
    rfir::models::TRandom noise(9);
    const auto& rb = m.likelihoodOptions.rangeBearing;
    auto observe = [&](const mrpt::math::TPose2D& robot, int32_t id) {
        auto o = mrpt::obs::CObservationBearingRange::Create();
        o->sensorLocationOnRobot = mrpt::poses::CPose3D(0.1, 0, 0, 0, 0, 0);
        const mrpt::math::TPose2D s(robot.x + 0.1 * std::cos(robot.phi),
                                    robot.y + 0.1 * std::sin(robot.phi), robot.phi);
        double r, b;
        rfir::models::predictRangeBearing(s, truth, r, b);
        mrpt::obs::CObservationBearingRange::TMeasurement z;
        z.range =
            static_cast<float>(r + rb.sigmaRange * noise.drawGaussian1D_normalized());
        z.yaw =
            static_cast<float>(b + rb.sigmaBearing * noise.drawGaussian1D_normalized());
        z.pitch = 0;
        z.landmarkID = id;
        o->sensedData.push_back(z);
        return o;
    };
    for (int k = 0; k < 40; k++) {
        const mrpt::math::TPose2D robot(0.8 + 0.01 * k, 0.1 * std::sin(k * 0.3),
                                        0.4 - 0.02 * k);
        m.insertObservation(*observe(robot, 1), pose3(robot));
    }
    m.insertObservation(*observe({1.0, 0.0, 0.3}, 2), pose3({1.0, 0.0, 0.3}));
    m.insertObservation(*observe({1.0, 0.0, 0.3}, 7), pose3({1.0, 0.0, 0.3}));
    ASSERT_EQ(m.landmarkCount(), 3u);
    const auto* l = m.getLandmark("L1");
    ASSERT_NE(l, nullptr);
    const double err =
        std::hypot(l->estimate.mean.x - truth.x, l->estimate.mean.y - truth.y);
    std::printf("[range-bearing, PS, 40 reads, exact poses] landmark error %.1f mm\n",
                err * 1e3);
    EXPECT_LT(err, 0.015);
    EXPECT_NE(m.getLandmark("2"), nullptr);  // empty name: decimal ID
    EXPECT_NE(m.getLandmark("7"), nullptr);  // beyond the names: decimal ID
    // Robot likelihood: truth beats a shifted pose, summed over 20 noisy
    // readings (one reading's noise, 1 cm and 3 deg, can favour a pose 3 cm
    // off: which one did depended on the generator's draws).
    const mrpt::math::TPose2D robot(1.0, 0.0, 0.3);
    std::vector<mrpt::obs::CObservationBearingRange::Ptr> obs;
    for (int k = 0; k < 20; k++) obs.push_back(observe(robot, 1));
    const auto sum = [&](const mrpt::math::TPose2D& p) {
        double s = 0;
        for (const auto& o : obs) s += m.computeObservationLikelihood(*o, pose3(p));
        return s;
    };
    EXPECT_GT(sum(robot), sum({1.03, 0.0, 0.3}));
    m.likelihoodOptions.rbUseLandmarkCov = true;  // wider, still ordered
    EXPECT_GT(sum(robot), sum({1.03, 0.0, 0.3}));
}

// robot_likelihood = tag_particles: the detection likelihood averaged over K
// evenly spaced tag particles (log of the mean), computed here by hand.
TEST(TagMap, RobotLikelihoodOverTagParticles) {
    CRFIDTagParticleMap m;
    m.likelihoodOptions.robotLikelihood = rfir::maps::TRobotLikelihood::TagParticles;
    m.likelihoodOptions.robotLikelihoodK = 4;
    const auto o = oneRead("T");
    m.insertObservation(*o, pose3({0, 0, 0}));
    const auto* t = m.getTag("T");
    ASSERT_EQ(t->sample.size(), 4u);
    for (size_t k = 0; k < 4; k++)  // particles 12, 37, 62, 87 of 100
        EXPECT_EQ(t->sample[k].x, t->particles()[(2 * k + 1) * 100 / 8].x);
    const mrpt::math::TPose2D robot{0.04, -0.02, 0.1};
    const rfir::models::DetectionLikelihood det;
    const rfir::models::ReaderArea r{0.1, 0.0, 0.03, 0.03};
    double s = 0;
    for (const auto& p : t->sample) s += std::exp(det.logLikelihood(robot, r, p));
    EXPECT_NEAR(m.computeObservationLikelihood(*o, pose3(robot)), std::log(s / 4), 1e-12);
    // tag_mean: against the mean only.
    m.likelihoodOptions.robotLikelihood = rfir::maps::TRobotLikelihood::TagMean;
    // The robot pose as the map sees it: CPose3D's yaw() is rebuilt from its
    // rotation matrix (0.1 comes back as 0.10000000000000009).
    const auto P = pose3(robot);
    EXPECT_EQ(m.computeObservationLikelihood(*o, P),
              det.logLikelihood({P.x(), P.y(), P.yaw()}, r, t->estimate.mean));
    // K set in code above the weighing's bound: refused, not cut to 64.
    CRFIDTagParticleMap big;
    big.likelihoodOptions.robotLikelihood = rfir::maps::TRobotLikelihood::TagParticles;
    big.likelihoodOptions.robotLikelihoodK = 65;
    EXPECT_THROW(big.insertObservation(*o, pose3({0, 0, 0})), std::invalid_argument);
}

// tag_robot_pose = samples_init: a new tag's particles are placed by robot
// poses drawn from the robot set, so they cover both candidate robot poses.
TEST(TagMap, NewTagFromRobotSamples) {
    CRFIDTagParticleMap m;
    m.insertionOptions.tagRobotPose = rfir::maps::TTagRobotPose::SamplesInit;
    m.setRobotSamples({{-0.2, 0, 0}, {0.2, 0, 0}});
    m.insertObservation(*oneRead("T"), pose3({0, 0, 0}));
    size_t left = 0, right = 0;
    for (const auto& p : m.getTag("T")->particles()) {
        const bool l = std::abs(p.x - (-0.1)) <= 0.03 + 1e-9,
                   r = std::abs(p.x - 0.3) <= 0.03 + 1e-9;
        EXPECT_TRUE(l || r) << p.x;
        left += l;
        right += r;
    }
    EXPECT_GT(left, 20u);
    EXPECT_GT(right, 20u);
}

// tag_robot_pose = samples_visit: the first visit's reads are placed by the
// robot mean; the estimate is spread by the drawn robot poses, and the spread
// becomes the estimator's state when the second visit starts. Serialized
// copies keep it.
TEST(TagMap, FirstVisitSpreadByRobotSamples) {
    CRFIDTagParticleMap m;
    m.insertionOptions.tagRobotPose = rfir::maps::TTagRobotPose::SamplesVisit;
    m.setRobotSamples({{-0.2, 0, 0}, {0.2, 0, 0}});
    const auto o = oneRead("T");
    m.insertObservation(*o, pose3({0, 0, 0}));
    m.insertObservation(*o, pose3({0, 0, 0}));  // same visit: placed by the mean
    const auto* t = m.getTag("T");
    ASSERT_EQ(t->spreadPoses.size(), 100u);
    for (const auto& p : t->particles()) EXPECT_LE(std::abs(p.x - 0.1), 0.03 + 1e-9);
    EXPECT_GT(t->estimate.cov(0, 0), 0.15 * 0.15);  // about 0.2^2
    CRFIDTagParticleMap copy;
    {
        mrpt::io::CMemoryStream buf;
        mrpt::serialization::archiveFrom(buf) << m;
        buf.Seek(0);
        mrpt::serialization::archiveFrom(buf) >> copy;
    }
    EXPECT_EQ(copy.getTag("T")->spreadPoses.size(), 100u);
    EXPECT_EQ(copy.getTag("T")->estimate.cov(0, 0), t->estimate.cov(0, 0));
    const double var = t->estimate.cov(0, 0);
    m.insertObservation(*oneRead(""), pose3({1, 0, 0}));
    EXPECT_EQ(t->estimate.cov(0, 0), var);  // reads of other tags change nothing
    // The second visit commits the spread: the states themselves move.
    m.insertObservation(*o, pose3({0.2, 0, 0}));
    EXPECT_TRUE(t->spreadPoses.empty());
    EXPECT_EQ(t->visits, 2u);
    size_t moved = 0;
    for (const auto& p : t->particles()) moved += std::abs(p.x - 0.1) > 0.03 + 1e-9;
    EXPECT_GT(moved, 20u);
}

// spread_commit_travel: a new visit after a short trip (the next reader of
// the same pass) keeps the spread pending; a long one commits it.
TEST(TagMap, SpreadCommitNeedsTravel) {
    CRFIDTagParticleMap m;
    m.insertionOptions.tagRobotPose = rfir::maps::TTagRobotPose::SamplesVisit;
    m.insertionOptions.spreadCommitTravel = 2.0;
    m.setRobotSamples({{-0.2, 0, 0}, {0.2, 0, 0}});
    const auto o = oneRead("T");
    m.insertObservation(*o, pose3({0, 0, 0}));
    m.insertObservation(*oneRead(""), pose3({0.5, 0, 0}));
    m.insertObservation(*o, pose3({0, 0, 0}));  // a new visit after 1 m
    EXPECT_EQ(m.getTag("T")->visits, 2u);
    EXPECT_EQ(m.getTag("T")->spreadPoses.size(), 100u);
    m.insertObservation(*oneRead(""), pose3({1.5, 0, 0}));
    m.insertObservation(*o, pose3({0, 0, 0}));  // after 4 m
    EXPECT_TRUE(m.getTag("T")->spreadPoses.empty());
}
