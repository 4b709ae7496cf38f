// CRFIDTagParticleMap::resolveRobotReads / robotReadsLogLikelihood (which
// computeObservationLikelihood also uses): the sum over the resolved reads
// equals each read's term computed here by hand (the detection likelihood of
// the tag mean, or the log mean over the tag particles; the range-bearing
// Gaussian), under every robot-update policy and robot likelihood; under the
// literal policy every read of a mapped landmark weighs.
#include "test_tagmaps_sim.h"

#include <gtest/gtest.h>
#include <rfir/models/detection_likelihood.h>
#include <rfir/models/range_bearing.h>

#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/poses/CPose2D.h>
#include <cmath>

using namespace tagmaps_test;
using rfir::maps::CRFIDTagParticleMap;
using rfir::maps::TRobotLikelihood;
using rfir::maps::TRobotUpdatePolicy;

namespace {
/** One resolved read's term, by hand. */
double termByHand(const CRFIDTagParticleMap& m, const CRFIDTagParticleMap::TRobotReads& r,
                  const CRFIDTagParticleMap::TRobotReads::TRead& rd,
                  const mrpt::poses::CPose2D& p) {
    const mrpt::math::TPose2D robot(p.x(), p.y(), p.phi());
    if (r.rangeBearing) {
        const auto sensor =
            (p + mrpt::poses::CPose2D(r.sensorX, r.sensorY, r.sensorYaw)).asTPose();
        return rfir::models::rangeBearingLogLikelihood(
            sensor, rd.est->mean, rd.range, rd.yaw, m.likelihoodOptions.rangeBearing);
    }
    const rfir::models::DetectionLikelihood det(m.likelihoodOptions.detection);
    if (m.likelihoodOptions.robotLikelihood == TRobotLikelihood::TagMean ||
        rd.sample->empty())
        return det.logLikelihood(robot, rd.area, rd.est->mean);
    double s = 0;
    for (const auto& q : *rd.sample) s += std::exp(det.logLikelihood(robot, rd.area, q));
    return std::log(s / double(rd.sample->size()));
}

/** Checks the sums at poses about `at`; returns how many reads weighed. */
size_t expectSameSums(const CRFIDTagParticleMap& m, const mrpt::obs::CObservation& o,
                      const mrpt::math::TPose2D& at, size_t knownReads) {
    CRFIDTagParticleMap::TRobotReads r;
    EXPECT_TRUE(m.resolveRobotReads(o, r));
    if (m.likelihoodOptions.robotUpdate == TRobotUpdatePolicy::Literal) {
        EXPECT_EQ(r.reads.size(), knownReads);
    }
    for (int k = 0; k < 25; k++) {
        const mrpt::poses::CPose2D p(at.x + 0.004 * (k % 5 - 2),
                                     at.y + 0.004 * (k / 5 - 2), at.phi + 0.3 * (k - 12));
        double ref = 0;
        for (const auto& rd : r.reads) ref += termByHand(m, r, rd, p);
        const double got = m.computeObservationLikelihood(o, mrpt::poses::CPose3D(p));
        EXPECT_NEAR(got, ref, 1e-9 * (1 + std::abs(ref)));
        EXPECT_EQ(m.robotReadsLogLikelihood(r, {p.x(), p.y(), p.phi()}), got);
    }
    return r.reads.size();
}

/** Reads in `o` of tags (or landmarks) the map already has. */
size_t knownReads(const CRFIDTagParticleMap& m, const mrpt::obs::CObservation& o) {
    size_t n = 0;
    if (const auto* f = dynamic_cast<const rfir::obs::CObservationRFIDReaders*>(&o)) {
        for (const auto& rd : f->readings)
            for (const auto& id : rd.tags) n += m.getTag(id) ? 1 : 0;
    } else if (const auto* b =
                   dynamic_cast<const mrpt::obs::CObservationBearingRange*>(&o)) {
        for (const auto& z : b->sensedData)
            n += m.getLandmark(m.landmarkName(z.landmarkID)) ? 1 : 0;
    }
    return n;
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

TEST(TagMapReads, MapLikelihoodIsTheSumOfTheReadsTerms) {
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
                weighed += expectSameSums(m, *o, at, knownReads(m, *o));
                m.insertObservation(*o, pose3(at));
                const auto b = rbObs(0.5 + 0.01 * s, 0.1);
                weighed += expectSameSums(m, *b, at, knownReads(m, *b));
                m.insertObservation(*b, pose3(at));
            }
            EXPECT_GE(weighed, 4u);  // the revisit policies weigh new visits only
        }
}

TEST(TagMapReads, BaseSumIsTheSumWithoutTheOutlierMixture) {
    // The weighing mixes each read's term; the kidnap check reads the base
    // sum, which the mixture would cap at log(eps) + floor per read.
    const auto readers = ring(0.03);
    for (const double eps : {0.0, 0.005}) {
        CRFIDTagParticleMap m;  // literal: every read of a mapped tag weighs
        m.likelihoodOptions.detection.outlierWeight = eps;
        const auto o = sense(readers, {{"A", 0.11, 0.01}}, {0, 0, 0});
        m.insertObservation(*o, pose3({0, 0, 0}));
        CRFIDTagParticleMap::TRobotReads r;
        ASSERT_TRUE(m.resolveRobotReads(*o, r));
        ASSERT_EQ(r.reads.size(), 1u);
        const mrpt::math::TPose2D near(0.01, -0.02, 0.1), far(1.5, 0.4, 0.1);
        const rfir::models::DetectionLikelihood base([&] {
            auto p = m.likelihoodOptions.detection;
            p.outlierWeight = 0;
            return p;
        }());
        const auto* tag = m.getTag("A");
        for (const auto& p : {near, far}) {
            double b = 1;
            const double mixed = m.robotReadsLogLikelihood(r, p, &b);
            EXPECT_EQ(mixed,
                      rfir::models::DetectionLikelihood(m.likelihoodOptions.detection)
                          .logLikelihood(p, r.reads[0].area, tag->estimate.mean));
            EXPECT_DOUBLE_EQ(b,
                             base.logLikelihood(p, r.reads[0].area, tag->estimate.mean));
            if (eps == 0) {
                EXPECT_EQ(b, mixed);
            }
        }
        double bFar = 0;
        const double mixedFar = m.robotReadsLogLikelihood(r, far, &bFar);
        if (eps > 0) {
            EXPECT_LT(bFar, -100.0);                           // 1.5 m off a 30 mm reader
            EXPECT_GT(mixedFar, std::log(eps) - 10.0 - 1e-9);  // capped
        }
    }
}
