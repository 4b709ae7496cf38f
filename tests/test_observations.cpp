// Serialization round trips of the observation classes.
#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/CObservationLogHeader.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

using namespace rfir::obs;

template <class T>
typename T::Ptr roundTrip(const T& o) {
    mrpt::io::CMemoryStream buf;
    auto ar = mrpt::serialization::archiveFrom(buf);
    ar << o;
    buf.Seek(0);
    auto obj = ar.ReadObject();
    auto out = std::dynamic_pointer_cast<T>(obj);
    EXPECT_TRUE(out);
    return out;
}

TEST(Observations, RFIDRoundTrip) {
    CObservationRFIDReaders o;
    o.timestamp = mrpt::Clock::fromDouble(12.5);
    o.sensorLabel = "RFID";
    // Named readings: GCC 12 warns (maybe-uninitialized, a false positive)
    // on braced temporaries here.
    CObservationRFIDReaders::TReading r1, r2;
    r1.reader = {"R1", 0.15, -0.05, 0.03, 0.03};
    r1.tags = {"E0040150A1B2C3D4", "t2"};
    r2.reader = {"R2", -0.15, 0.05, 0.15, 0.15};
    o.readings.push_back(r1);
    o.readings.push_back(r2);
    auto b = roundTrip(o);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->readings, o.readings);
    EXPECT_EQ(b->sensorLabel, "RFID");
    EXPECT_EQ(b->timestamp, o.timestamp);
    EXPECT_EQ(b->detectionCount(), 2u);
}

TEST(Observations, IRRoundTripWithRaw) {
    CObservationIRSignals o;
    o.timestamp = mrpt::Clock::fromDouble(3.25);
    CObservationIRSignals::TReading r;
    r.receiver = {"left", 0.1, 0.2, 0.35};
    r.codes = {3, 9};
    r.volts = 1.75;
    r.rateHz = 8000;
    r.raw = {0.1f, 0.2f, 1.9f};
    o.readings.push_back(r);
    auto b = roundTrip(o);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->readings, o.readings);
    EXPECT_EQ(b->readings[0].emitterId(), "39");
}

TEST(Observations, HeaderRoundTrip) {
    CObservationLogHeader h;
    h.readers = {{"R1", 0.1, 0.0, 0.03, 0.03}};
    h.receivers = {{"left", 0, 0.1, 0.3}};
    h.rbSensor = TRBSensor{0.1, 0, 0, 0.5, 2.0};
    h.startPose = mrpt::poses::CPose2D(1, 2, 0.5);
    h.rbLandmarkNames = {"A", "B7"};
    auto b = roundTrip(h);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->readers, h.readers);
    EXPECT_EQ(b->receivers, h.receivers);
    ASSERT_TRUE(b->rbSensor && b->startPose);
    EXPECT_EQ(*b->rbSensor, *h.rbSensor);
    EXPECT_DOUBLE_EQ(b->startPose->phi(), 0.5);
    EXPECT_EQ(b->landmarkName(1), "B7");
    EXPECT_EQ(b->landmarkName(5), "5");
    // A start facing -x reads back as written: pi, not -pi (CPose2D's
    // constructor would normalize it).
    h.startPose->phi(M_PI);
    b = roundTrip(h);
    ASSERT_TRUE(b && b->startPose);
    EXPECT_EQ(b->startPose->phi(), M_PI);
    EXPECT_EQ(b->startPose->x(), 1.0);
}
