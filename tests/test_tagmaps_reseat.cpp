// CRFIDTagParticleMap, [tagmap] reseat_contradicted: a tag that more reads in
// a row contradict than agreed with it since it was placed is placed again
// at the read (a tag first mapped from a ghost read, or moved); a tag with
// many agreeing reads is not moved by a few contradicting ones (the robot
// may be the one that is off); with large readers a read whose square
// misses the tag by more than a margin contradicts it too; a read the
// agreeing ones out-vote does not move the tag; a reseated tag weighs the
// robot only from its next visit on; the counts survive serialization.
#include "test_tagmaps_sim.h"

#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>

using namespace tagmaps_test;
using rfir::maps::CRFIDTagParticleMap;

namespace {
/** One 60 mm reader 0.1 m ahead of the robot reads `tag`. */
rfir::obs::CObservationRFIDReaders::Ptr readOf(const std::string& tag) {
    auto o = rfir::obs::CObservationRFIDReaders::Create();
    rfir::obs::CObservationRFIDReaders::TReading rd;
    rd.reader = reader("A", 0.1, 0.0, 0.03);
    rd.tags.push_back(tag);
    o->readings.push_back(rd);
    return o;
}

double distTo(const CRFIDTagParticleMap& m, const std::string& id, double x, double y) {
    const auto& mean = m.getTag(id)->estimate.mean;
    return std::hypot(mean.x - x, mean.y - y);
}

/** One 300 mm reader 0.4 m ahead of the robot reads `tag`. */
rfir::obs::CObservationRFIDReaders::Ptr read300Of(const std::string& tag) {
    auto o = readOf(tag);
    o->readings[0].reader = reader("B", 0.4, 0.0, 0.15);
    return o;
}

/** A ghost read of "G" by `read` with the robot at ghostX, then three true
 * reads from trueX on; `setup` sets the map's options. */
template <class Read, class Setup>
CRFIDTagParticleMap ghostThen(Read read, double ghostX, double trueX, Setup setup) {
    CRFIDTagParticleMap m;
    setup(m.insertionOptions);
    m.insertionOptions.seed = 7;
    m.insertObservation(*read("G"), pose3({ghostX, 0.0, 0.0}));  // the ghost
    for (int i = 0; i < 3; i++)
        m.insertObservation(*read("G"), pose3({trueX + 0.005 * i, 0.0, 0.0}));
    return m;
}

/** A ghost of a 300 mm reader places "G" over [0.25, 0.55]; it lies at
 * about 0.75, where three reads then find it. */
CRFIDTagParticleMap ghostThenTrue300(double margin) {
    return ghostThen(read300Of, 0.0, 0.35, [&](auto& o) { o.contradictMargin = margin; });
}

/** "T" read five times from one spot, then once from 0.3 m further on. */
double dragByOneFarRead(bool hold) {
    CRFIDTagParticleMap m;
    m.insertionOptions.holdOutvoted = hold;
    m.insertionOptions.seed = 7;
    for (int i = 0; i < 5; i++) m.insertObservation(*readOf("T"), pose3({1.0, 0.0, 0.0}));
    const auto before = m.getTag("T")->estimate.mean;
    m.insertObservation(*readOf("T"), pose3({1.3, 0.0, 0.0}));
    EXPECT_EQ(m.getTag("T")->contradicted, 1u);
    EXPECT_EQ(m.getTag("T")->reseats, 0u);
    return distTo(m, "T", before.x, before.y);
}

/** A ghost read places "G" 0.4 m from its true spot (1.1, 0); then the robot
 * reads it three times where it really is. */
CRFIDTagParticleMap ghostThenTrue(bool reseat) {
    return ghostThen(readOf, 0.6, 1.0, [&](auto& o) { o.reseatContradicted = reseat; });
}
}  // namespace

TEST(TagMapReseat, GhostPlacedTagIsPlacedAgainByTheReadsThatContradictIt) {
    const auto on = ghostThenTrue(true);
    const auto* t = on.getTag("G");
    ASSERT_NE(t, nullptr);
    // The first true read is 1 against 1 (not yet), the second 2 against 1.
    EXPECT_EQ(t->reseats, 1u);
    EXPECT_EQ(t->contradicted, 2u);
    EXPECT_EQ(t->detections, 4u);
    EXPECT_LT(distTo(on, "G", 1.1, 0.0), 0.03);
    // Without it the tag stays where the ghost put it: no particle can move.
    const auto off = ghostThenTrue(false);
    EXPECT_EQ(off.getTag("G")->reseats, 0u);
    EXPECT_EQ(off.getTag("G")->contradicted, 3u);
    EXPECT_GT(distTo(off, "G", 1.1, 0.0), 0.3);
}

// The outlier floor's test scales with the reader: a 300 mm reader's read
// contradicts a tag only 0.69 m from its centre, so a ghost-placed tag 0.3 m
// off was never reseated. contradict_margin (stock 0.1 m) also counts a
// read whose square misses the tag's estimate by more than that.
TEST(TagMapReseat, MarginCatchesTheGhostsOfLargeReaders) {
    const auto on = ghostThenTrue300(0.1);
    EXPECT_EQ(on.getTag("G")->reseats, 1u);
    EXPECT_LT(distTo(on, "G", 0.75, 0.0), 0.15);  // inside the true square
    const auto off = ghostThenTrue300(-1);
    EXPECT_EQ(off.getTag("G")->reseats, 0u);
    EXPECT_EQ(off.getTag("G")->contradicted, 0u);
    EXPECT_GT(distTo(off, "G", 0.75, 0.0), 0.15);
}

// hold_outvoted (stock): a read that contradicts a tag the agreeing reads
// still out-vote does not update it; without it one far read drags the
// tag's particles to the edge of its cloud nearest the read.
TEST(TagMapReseat, OutvotedReadDoesNotDragTheTag) {
    EXPECT_EQ(dragByOneFarRead(true), 0.0);
    EXPECT_GT(dragByOneFarRead(false), 0.01);
}

TEST(TagMapReseat, WellSupportedTagOutlastsAsManyContradictingReads) {
    CRFIDTagParticleMap m;
    m.insertionOptions.seed = 3;
    ASSERT_TRUE(m.insertionOptions.reseatContradicted);  // the code's default
    for (int i = 0; i < 10; i++)                         // 10 agreeing reads at (1.1, 0)
        m.insertObservation(*readOf("T"), pose3({1.0 + 0.002 * (i % 3), 0.0, 0.0}));
    ASSERT_EQ(m.getTag("T")->contradicted, 0u);
    // A robot that believes itself 0.3 m off: as many contradicting reads as
    // agreeing ones leave the tag where it was...
    for (int i = 0; i < 10; i++)
        m.insertObservation(*readOf("T"), pose3({1.3, 0.0, 0.0}));
    EXPECT_EQ(m.getTag("T")->contradicted, 10u);
    EXPECT_EQ(m.getTag("T")->reseats, 0u);
    EXPECT_LT(distTo(m, "T", 1.1, 0.0), 0.03);
    // ...one more is the majority: the tag follows the reads.
    m.insertObservation(*readOf("T"), pose3({1.3, 0.0, 0.0}));
    EXPECT_EQ(m.getTag("T")->reseats, 1u);
    EXPECT_LT(distTo(m, "T", 1.4, 0.0), 0.03);
    // One agreeing read in between starts the count again.
    m.insertObservation(*readOf("T"), pose3({1.3, 0.0, 0.0}));
    EXPECT_EQ(m.getTag("T")->againstRun, 0u);
    EXPECT_EQ(m.getTag("T")->support, 2u);
}

TEST(TagMapReseat, CountsAndOptionSurviveSerialization) {
    const auto m = ghostThenTrue(true);
    mrpt::io::CMemoryStream buf;
    auto out = mrpt::serialization::archiveFrom(buf);
    out << m;
    buf.Seek(0);
    CRFIDTagParticleMap back;
    back.insertionOptions.reseatContradicted = false;
    back.insertionOptions.contradictMargin = -1;
    back.insertionOptions.holdOutvoted = false;
    auto in = mrpt::serialization::archiveFrom(buf);
    in >> back;
    EXPECT_TRUE(back.insertionOptions.reseatContradicted);
    EXPECT_EQ(back.insertionOptions.contradictMargin, 0.1);
    EXPECT_TRUE(back.insertionOptions.holdOutvoted);
    const auto* a = m.getTag("G");
    const auto* b = back.getTag("G");
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->support, a->support);
    EXPECT_EQ(b->againstRun, a->againstRun);
    EXPECT_EQ(b->reseats, a->reseats);
    EXPECT_EQ(b->contradicted, a->contradicted);
}

// A reseated tag starts over as a tag on its first visit: its placement is
// the robot's own pose, so the rest of that visit must not weigh the robot
// against it (that would be the double counting revisit_min_travel keeps
// out); a later visit does.
TEST(TagMapReseat, ReseatedTagWeighsTheRobotFromTheNextVisitOn) {
    CRFIDTagParticleMap m;
    m.likelihoodOptions.robotUpdate = rfir::maps::TRobotUpdatePolicy::RevisitAll;
    m.likelihoodOptions.revisitMinTravel = 1;
    m.insertionOptions.seed = 7;
    const auto weighing = [&] {
        CRFIDTagParticleMap::TRobotReads r;
        EXPECT_TRUE(m.resolveRobotReads(*readOf("G"), r));
        return r.reads.size();
    };
    // Drives 2 m (to x and back) reading only "X": the next read of "G"
    // starts a new visit.
    const auto away = [&](double x) {
        for (int i = 0; i <= 20; i++)
            m.insertObservation(*readOf("X"),
                                pose3({x + 0.1 * (i <= 10 ? i : 20 - i), 0, 0}));
    };
    m.insertObservation(*readOf("G"), pose3({0.6, 0.0, 0.0}));  // a ghost places "G"
    away(3.0);
    EXPECT_EQ(weighing(), 1u);   // the second visit weighs the robot
    for (int i = 0; i < 2; i++)  // two true reads: the second reseats "G"
        m.insertObservation(*readOf("G"), pose3({1.0 + 0.005 * i, 0.0, 0.0}));
    ASSERT_EQ(m.getTag("G")->reseats, 1u);
    EXPECT_EQ(weighing(), 0u);  // the rest of this visit does not
    m.insertObservation(*readOf("G"), pose3({1.01, 0.0, 0.0}));
    EXPECT_EQ(weighing(), 0u);
    away(3.0);
    EXPECT_EQ(weighing(), 1u);  // the next visit does
    EXPECT_LT(distTo(m, "G", 1.1, 0.0), 0.03);
}
