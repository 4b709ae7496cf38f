// CRFIDTagParticleMap, [tagmap] negative_information: a polled reader large
// enough that did not read a tag on its first visit, read recently, near it
// says the tag is not in its square; polls from one pose count once; small
// readers, tags not read recently and revisited tags are left alone; the
// options survive serialization.
#include "test_tagmaps_sim.h"

#include <gtest/gtest.h>

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <cstdio>

using namespace tagmaps_test;
using rfir::maps::CRFIDTagParticleMap;

namespace {
/** One reader of half-size h, 0.4 m ahead of the robot, reading `tags`. */
rfir::obs::CObservationRFIDReaders::Ptr poll(double h, std::vector<std::string> tags) {
    auto o = rfir::obs::CObservationRFIDReaders::Create();
    rfir::obs::CObservationRFIDReaders::TReading rd;
    rd.reader = reader("A", 0.4, 0.0, h);
    rd.tags = std::move(tags);
    o->readings.push_back(rd);
    return o;
}

/** Adds reader `id` (half-size h, at (x, y) on the robot) reading nothing. */
void addSilentReader(rfir::obs::CObservationRFIDReaders& o, const std::string& id,
                     double x, double y, double h) {
    rfir::obs::CObservationRFIDReaders::TReading rd;
    rd.reader = reader(id, x, y, h);
    o.readings.push_back(rd);
}

/** A map (seed 5, negative_information pd) that read "G" once from x = 0
 * with a 300 mm reader: G's particles over [0.25, 0.55] x [-0.15, 0.15]. */
CRFIDTagParticleMap mapThatReadG(double pd) {
    CRFIDTagParticleMap m;
    m.insertionOptions.seed = 5;
    m.insertionOptions.negativeInformation = pd;
    m.insertObservation(*poll(0.15, {"G"}), pose3({0.0, 0.0, 0.0}));
    return m;
}

/** The map written to a stream and read back. */
void roundTrip(CRFIDTagParticleMap& m) {
    mrpt::io::CMemoryStream buf;
    auto out = mrpt::serialization::archiveFrom(buf);
    out << m;
    buf.Seek(0);
    auto in = mrpt::serialization::archiveFrom(buf);
    in >> m;
}

/** "G" read once from x = 0 (its particles over x in [0.4 - h, 0.4 + h]),
 * then `n` empty polls from x = `to` (spaced `step` apart): the share of
 * its particles beyond x = `edge`. `revisit`: G is read again on a second
 * visit before the polls; `reload`: the map is saved and loaded before
 * them. */
double shareBeyondAfterEmptyPolls(double pd, double h, double to, int n,
                                  double step = 0.01, uint64_t window = 30,
                                  double edge = 0.45, bool revisit = false,
                                  bool reload = false) {
    CRFIDTagParticleMap m;
    m.insertionOptions.seed = 5;
    m.insertionOptions.negativeInformation = pd;
    m.insertionOptions.negativeWindow = window;
    m.insertObservation(*poll(h, {"G"}), pose3({0.0, 0.0, 0.0}));
    if (revisit) {  // away (the reader far from G), then G read again
        m.insertObservation(*poll(h, {"X"}), pose3({3.0, 0.0, 0.0}));
        m.insertObservation(*poll(h, {"G"}), pose3({0.0, 0.0, 0.0}));
    }
    if (reload) roundTrip(m);
    for (int i = 0; i < n; i++)
        m.insertObservation(*poll(h, {}), pose3({to + step * i, 0.0, 0.0}));
    const auto pts = m.getTag("G")->estimator->smoothedParticles();
    double beyond = 0;
    for (const auto& p : pts) beyond += p.x > edge;
    return beyond / double(pts.size());
}
}  // namespace

// A 300 mm reader read "G" from x = 0 (so G is in [0.25, 0.55]); polled from
// x = 0.15 on, its square (from [0.40, 0.70] on) reads nothing: G is below
// 0.45. A particle at 0.5 lies inside each of the ten polls' squares, 0.05
// to 0.14 m from their centres, where the miss model's P(read) is 0.99 to
// 0.2: its weight falls below 0.5^4, and the share of particles beyond 0.45
// to under half of what it is without the option.
TEST(TagMapNotRead, EmptyPollsOfALargeReaderPushTheTagOut) {
    const double off = shareBeyondAfterEmptyPolls(0, 0.15, 0.15, 10);
    EXPECT_GT(off, 0.25);
    EXPECT_LT(shareBeyondAfterEmptyPolls(0.5, 0.15, 0.15, 10), 0.5 * off);
}

// Polled from x = 0.3 on, the squares (from [0.55, 0.85] on) lie beyond all
// of G's particles: G is left as it was. The read model's tail as P(read)
// (w = 0.92 for a particle at 0.54, 0.16 m from the first square's centre)
// pushed it by 0.54 per poll; on a lawnmower path that push added up stripe
// after stripe (docs/slam.md, "Negative information").
TEST(TagMapNotRead, ATagJustOutsideTheUnreadSquaresIsLeftAlone) {
    for (double edge : {0.45, 0.5})
        EXPECT_EQ(shareBeyondAfterEmptyPolls(0.5, 0.15, 0.3, 10, 0.01, 30, edge),
                  shareBeyondAfterEmptyPolls(0, 0.15, 0.3, 10, 0.01, 30, edge));
}

// Polls from one pose repeat one piece of evidence: ten of them weigh the
// tag as one does (a robot stopped, or carried with its odometry frozen,
// would otherwise push the tags it was reading out of its squares).
TEST(TagMapNotRead, PollsFromOnePoseCountOnce) {
    EXPECT_EQ(shareBeyondAfterEmptyPolls(0.5, 0.15, 0.2, 10, 0.0),
              shareBeyondAfterEmptyPolls(0.5, 0.15, 0.2, 1, 0.0));
    EXPECT_NE(shareBeyondAfterEmptyPolls(0.5, 0.15, 0.2, 10, 0.01),
              shareBeyondAfterEmptyPolls(0.5, 0.15, 0.2, 1, 0.01));
}

// 60 mm readers are left alone (negative_min_half_size 0.1 m: on the 60 mm
// loops it cost accuracy, docs/slam.md), and so are tags not read in the
// last negative_window observations.
TEST(TagMapNotRead, SmallReadersAndOldTagsAreLeftAlone) {
    // G over [0.37, 0.43]; polled from 0.03 on, the squares from [0.40,
    // 0.46] on: about half of G's particles are in the first ones.
    const double small = shareBeyondAfterEmptyPolls(0.5, 0.03, 0.03, 3, 0.01, 30, 0.4);
    EXPECT_GT(small, 0.3);
    EXPECT_EQ(small, shareBeyondAfterEmptyPolls(0, 0.03, 0.03, 3, 0.01, 30, 0.4));
    EXPECT_EQ(shareBeyondAfterEmptyPolls(0.5, 0.15, 0.2, 10, 0.01, 1),
              shareBeyondAfterEmptyPolls(0, 0.15, 0.2, 10, 0.01, 1));
}

// Only a tag on its first visit: a revisited tag's estimate is older and
// better than the robot's pose at the revisit (docs/slam.md).
TEST(TagMapNotRead, RevisitedTagsAreLeftAlone) {
    const auto revisited = [](double pd) {
        return shareBeyondAfterEmptyPolls(pd, 0.15, 0.2, 10, 0.01, 30, 0.45, true);
    };
    EXPECT_GT(revisited(0), 0.25);
    EXPECT_EQ(revisited(0.5), revisited(0));
}

// Which tags the polls may push out comes from each tag's visits and last
// read and from the map's step count: a map saved and loaded again between
// G's read and the polls pushes G out exactly as the map never saved does.
TEST(TagMapNotRead, ALoadedMapKnowsItsRecentReads) {
    const auto pushed = [](bool reload) {
        return shareBeyondAfterEmptyPolls(0.5, 0.15, 0.15, 10, 0.01, 30, 0.45, false,
                                          reload);
    };
    EXPECT_LT(pushed(true), 0.5 * shareBeyondAfterEmptyPolls(0, 0.15, 0.15, 10));
    EXPECT_EQ(pushed(true), pushed(false));
}

// An observation is one update of a tag, however many of its readers
// missed it (their miss terms summed): for PS-SLAM an update is a step of
// the tag's smoother, and one per reader cost a step each and moved its lag
// window by the number of readers (docs/slam.md, "Its cost").
TEST(TagMapNotRead, AnObservationsMissesAreOneUpdate) {
    // G about (0.4, 0), its particles over [0.25, 0.55] x [-0.15, 0.15].
    // Polled from x = 0.15: A's square is [0.40, 0.70] x [-0.15, 0.15]; B,
    // 0.2 m to its left, covers [0.40, 0.70] x [0.05, 0.35], and pushes G's
    // particles in it to the right (-y). Neither reads G.
    const auto afterPoll = [](bool withB) {
        CRFIDTagParticleMap m = mapThatReadG(0.5);
        const uint64_t before = m.getTag("G")->estimator->updateCount();
        auto o = poll(0.15, {});
        if (withB) addSilentReader(*o, "B", 0.4, 0.2, 0.15);
        m.insertObservation(*o, pose3({0.15, 0.0, 0.0}));
        const auto& e = *m.getTag("G");
        return std::make_pair(e.estimator->updateCount() - before, e.estimate.mean.y);
    };
    const auto [updatesA, yA] = afterPoll(false);
    const auto [updatesAB, yAB] = afterPoll(true);
    EXPECT_EQ(updatesA, 1u);
    EXPECT_EQ(updatesAB, 1u);    // one per reader: 2
    EXPECT_LT(yAB, yA - 0.005);  // and B's term is in it
    std::printf("G's mean y after A's miss %.4f, after A's and B's %.4f\n", yA, yAB);
}

TEST(TagMapNotRead, OptionsSurviveSerialization) {
    CRFIDTagParticleMap m;
    m.insertionOptions.negativeInformation = 0.4;
    m.insertionOptions.negativeWindow = 12;
    m.insertionOptions.negativeMinHalfSize = 0.07;
    m.likelihoodOptions.robotNegativeInformation = 0.3;
    CRFIDTagParticleMap back = m;
    roundTrip(back);
    EXPECT_EQ(back.insertionOptions.negativeInformation, 0.4);
    EXPECT_EQ(back.insertionOptions.negativeWindow, 12u);
    EXPECT_EQ(back.insertionOptions.negativeMinHalfSize, 0.07);
    EXPECT_EQ(back.likelihoodOptions.robotNegativeInformation, 0.3);
}

// insertNewTags (the kidnap check's open run, [kidnap] map_new_tags_in_run):
// a tag the map does not hold is placed over its reader's square;
// a known tag is neither updated by its read nor pushed out by the readers
// that missed it; an observation of known tags only changes nothing.
TEST(TagMapNotRead, InsertNewTagsLeavesKnownTagsAlone) {
    // G's particles are over x in [0.25, 0.55]. From x = 0.05, reader A
    // (square [0.3, 0.6]) reads G and N; B, 0.5 m ahead (square [0.4, 0.7]),
    // reads nothing: each of the two would move G.
    auto o = poll(0.15, {"G", "N"});
    addSilentReader(*o, "B", 0.5, 0.0, 0.15);
    const mrpt::poses::CPose2D at(0.05, 0.0, 0.0);
    CRFIDTagParticleMap all = mapThatReadG(0.5), fresh = mapThatReadG(0.5);
    all.insertObservation(*o, mrpt::poses::CPose3D(at));
    ASSERT_TRUE(fresh.insertNewTags(*o, at));
    // The new tag: over A's square.
    ASSERT_NE(fresh.getTag("N"), nullptr);
    EXPECT_NEAR(fresh.getTag("N")->estimate.mean.x, 0.45, 0.03);
    EXPECT_NEAR(fresh.getTag("N")->estimate.mean.y, 0.0, 0.03);
    EXPECT_EQ(fresh.tagCount(), 2u);
    // The known tag: untouched here, moved by the full insertion.
    const CRFIDTagParticleMap before = mapThatReadG(0.5);
    const auto& g0 = before.getTag("G")->estimate.mean;
    EXPECT_EQ(fresh.getTag("G")->estimate.mean.x, g0.x);
    EXPECT_EQ(fresh.getTag("G")->detections, before.getTag("G")->detections);
    EXPECT_NE(all.getTag("G")->estimate.mean.x, g0.x);
    EXPECT_GT(all.getTag("G")->detections, before.getTag("G")->detections);
    // Known tags only: nothing is inserted.
    CRFIDTagParticleMap again = mapThatReadG(0.5);
    EXPECT_FALSE(again.insertNewTags(*poll(0.15, {"G"}), at));
    EXPECT_EQ(again.getTag("G")->estimate.mean.x, g0.x);
    EXPECT_EQ(again.tagCount(), 1u);
}

// [tagmap_likelihood] robot_negative_information: T (mapped by reader A,
// 0.4 m ahead) read again by A, not by B (0.2 m to A's left, the squares
// overlap). From y = 0 T lies in A's square only; from y = -0.12 in both:
// the read is flat over both poses, B's miss tells them apart. The kidnap
// check's base sum reads the read alone.
TEST(TagMapNotRead, RobotMissesTellPosesTheFlatReadCannot) {
    CRFIDTagParticleMap m;
    m.insertionOptions.seed = 5;
    m.insertObservation(*poll(0.15, {"T"}), pose3({0.0, 0.0, 0.0}));
    auto o = poll(0.15, {"T"});
    addSilentReader(*o, "B", 0.4, 0.2, 0.15);
    const auto weigh = [&](double pd, double y, double* base) {
        m.likelihoodOptions.robotNegativeInformation = pd;
        CRFIDTagParticleMap::TRobotReads r;
        EXPECT_TRUE(m.resolveRobotReads(*o, r));
        EXPECT_EQ(r.reads.size(), 1u);
        return m.robotReadsLogLikelihood(r, {0.0, y, 0.0}, base);
    };
    double b0 = 0, b1 = 0;
    EXPECT_NEAR(weigh(0, 0, &b0), weigh(0, -0.12, &b1), 1e-12);
    EXPECT_GT(weigh(0.5, 0, &b0) - weigh(0.5, -0.12, &b1), 0.5);
    EXPECT_NEAR(b0, b1, 1e-12);
}
