// CRFIDTagParticleMap::resolveRobotReads / robotReadsLogLikelihood: the reads
// resolved once per update give exactly (bit for bit) the sum
// computeObservationLikelihood gives, under every robot-update policy and
// robot likelihood, for RFID and range-bearing observations.
#include "test_tagmaps_sim.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/poses/CPose2D.h>

using namespace tagmaps_test;
using rfir::maps::CRFIDTagParticleMap;
using rfir::maps::TRobotLikelihood;
using rfir::maps::TRobotUpdatePolicy;

namespace {
/** Compares both paths at poses about `at`; returns how many reads weighed. */
size_t expectSameSums(const CRFIDTagParticleMap& m, const mrpt::obs::CObservation& o,
                      const mrpt::math::TPose2D& at) {
    CRFIDTagParticleMap::TRobotReads r;
    EXPECT_TRUE(m.resolveRobotReads(o, r));
    for (int k = 0; k < 25; k++) {
        const mrpt::poses::CPose2D p(at.x + 0.004 * (k % 5 - 2),
                                     at.y + 0.004 * (k / 5 - 2), at.phi + 0.3 * (k - 12));
        const double ref = m.computeObservationLikelihood(o, mrpt::poses::CPose3D(p));
        EXPECT_EQ(m.robotReadsLogLikelihood(r, {p.x(), p.y(), p.phi()}), ref);
    }
    return r.reads.size();
}

mrpt::obs::CObservationBearingRange::Ptr rbObs(double range, double yaw) {
    auto o = mrpt::obs::CObservationBearingRange::Create();
    o->sensorLocationOnRobot = mrpt::poses::CPose3D(0.1, -0.05, 0, 0.2, 0, 0);
    mrpt::obs::CObservationBearingRange::TMeasurement z;
    z.landmarkID = 3;
    z.range = range;
    z.yaw = yaw;
    o->sensedData.push_back(z);
    return o;
}
}  // namespace

TEST(TagMapReads, ResolvedSumsEqualTheMapLikelihood) {
    const auto readers = ring(0.03);
    const std::vector<Tag> tags = {{"A", 0.11, 0.01}, {"B", 0.02, 0.105}};
    for (auto pol : {TRobotUpdatePolicy::Literal, TRobotUpdatePolicy::Revisit,
                     TRobotUpdatePolicy::RevisitAll})
        for (auto lik : {TRobotLikelihood::TagMean, TRobotLikelihood::TagParticles}) {
            CRFIDTagParticleMap m;
            m.likelihoodOptions.robotUpdate = pol;
            m.likelihoodOptions.robotLikelihood = lik;
            size_t weighed = 0;
            // Back and forth over the tags: first visits, re-reads, revisits.
            for (int s = 0; s < 12; s++) {
                const mrpt::math::TPose2D at(0.002 * (s % 3), 0.001 * s, 0.01 * s);
                const auto o = sense(readers, tags,
                                     (s % 4 == 3) ? mrpt::math::TPose2D(1, 1, 0) : at);
                weighed += expectSameSums(m, *o, at);
                m.insertObservation(*o, pose3(at));
                const auto b = rbObs(0.5 + 0.01 * s, 0.1);
                weighed += expectSameSums(m, *b, at);
                m.insertObservation(*b, pose3(at));
            }
            EXPECT_GE(weighed, 4u);  // the revisit policies weigh new visits only
        }
}

TEST(TagMapReads, PlainTermsAreReusedForCurrentTagMeanReads) {
    const auto readers = ring(0.03);
    CRFIDTagParticleMap m;  // literal: every read of a mapped tag weighs
    const auto o = sense(readers, {{"A", 0.11, 0.01}}, {0, 0, 0});
    m.insertObservation(*o, pose3({0, 0, 0}));
    CRFIDTagParticleMap::TRobotReads r;
    ASSERT_TRUE(m.resolveRobotReads(*o, r));
    ASSERT_EQ(r.reads.size(), 1u);
    EXPECT_TRUE(r.reads[0].plainCurrent);
    const mrpt::math::TPose2D p(0.01, -0.02, 0.1);
    const double t = m.detectionLogLikelihood(*m.getTag("A"), p, r.reads[0].area);
    EXPECT_EQ(m.robotReadsLogLikelihood(r, p), t);
    const double fake = -7.25;  // the given term is used, not recomputed
    EXPECT_EQ(m.robotReadsLogLikelihood(r, p, &fake), fake);
}
