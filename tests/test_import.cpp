// Text log <-> rawlog conversion: content, exact round trips, timestamps, the
// rules only a rawlog adds, and the strict / lossy export.
#include "test_import_util.h"

#include <rfir/obs/ir_decoder.h>

#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <random>
#include <sstream>

using namespace rfir::common;
using namespace rfir::obs;
using rfir_test::TmpDir;

namespace {
TEST(Import, TextToRawlogFollowsTheLayout) {
    TmpDir d;
    const auto rep = convertTextLogToRawlog(rfir_test::kFull, d / "f.rawlog");
    EXPECT_EQ(rep.instants, 6u);
    EXPECT_EQ(rep.timedRecords, 17u);
    CRawlogReader r(d / "f.rawlog");
    const auto& h = r.header();
    EXPECT_EQ(h.sensorLabel, "HEADER");
    EXPECT_EQ(h.timestamp, mrpt::Clock::fromDouble(0));
    ASSERT_TRUE(h.startPose);  // the `start` record, for a later SLAM run
    EXPECT_EQ(h.startPose->x(), 1.25);
    EXPECT_EQ(h.startPose->y(), -0.5);
    EXPECT_EQ(h.startPose->phi(), 1.5707963267948966);
    EXPECT_EQ(h.rbLandmarkNames, (std::vector<std::string>{"L7", "L2"}));
    TRawlogStep st;
    ASSERT_TRUE(r.next(st));
    EXPECT_EQ(st.t, 0);
    ASSERT_TRUE(st.odometry && st.rfid && st.ir && st.rb);
    EXPECT_EQ(st.rfid->sensorLabel, "RFID");
    ASSERT_EQ(st.rfid->readings.size(), 2u);
    EXPECT_EQ(st.rfid->readings[1].reader, h.readers[1]);
    EXPECT_TRUE(st.rfid->readings[1].tags.empty());
    EXPECT_EQ(st.ir->readings[0].codes, (std::vector<uint8_t>{3, 9}));
    EXPECT_EQ(st.ir->readings[0].volts, 1.82);
    EXPECT_FALSE(st.ir->readings[0].hasRaw());
    EXPECT_EQ(st.rb->sensorLabel, "RB");
    ASSERT_EQ(st.rb->sensedData.size(), 2u);
    EXPECT_EQ(st.rb->sensedData[1].landmarkID, 1);  // L2
    EXPECT_EQ(st.rb->sensedData[1].range, 0.31f);
    EXPECT_EQ(st.rb->sensedData[1].yaw, -0.85f);
    EXPECT_EQ(st.rb->sensedData[1].pitch, 0.f);
    EXPECT_EQ(st.rb->maxSensorDistance, 0.5f);
    EXPECT_EQ(st.rb->fieldOfView_pitch, 0.f);
    EXPECT_EQ(st.rb->fieldOfView_yaw, float(2.0943951023931953));
    EXPECT_NEAR(st.rb->sensorLocationOnRobot.x(), 0.2, 1e-15);
    for (const auto& o : *st.sf) EXPECT_EQ(o->timestamp, mrpt::Clock::fromDouble(0));

    ASSERT_TRUE(r.next(st));  // t = 0.1: an ir record and an ir_raw window
    ASSERT_TRUE(st.ir);
    ASSERT_EQ(st.ir->readings.size(), 2u);
    const auto& raw = st.ir->readings[1];
    EXPECT_TRUE(raw.hasRaw());
    EXPECT_EQ(raw.rateHz, 5000);
    EXPECT_EQ(raw.raw.size(), 1024u);
    EXPECT_EQ(raw.codes, (std::vector<uint8_t>{3, 9}));  // decoded by FFT
    EXPECT_NEAR(raw.volts, 1.5, 0.15);
    ASSERT_TRUE(st.odometryIncrement);
    EXPECT_NEAR(st.odometryIncrement->x(), 0.05, 1e-12);

    ASSERT_TRUE(r.next(st));  // t = 0.2: a window with no emitter in view
    EXPECT_TRUE(st.ir->readings[0].codes.empty());
    EXPECT_TRUE(st.ir->readings[0].hasRaw());
    EXPECT_EQ(st.rb->sensedData[0].landmarkID, 1);

    ASSERT_TRUE(r.next(st));  // t = 0.35: no odometry, no motion
    EXPECT_EQ(st.t, 0.35);
    EXPECT_FALSE(st.odometry);
    EXPECT_FALSE(st.odometryIncrement);
    ASSERT_TRUE(r.next(st));
    EXPECT_EQ(st.odometry->phi(), M_PI);  // kept exactly (CPose2D would give -pi)
    ASSERT_TRUE(r.next(st));
    EXPECT_EQ(st.odometry->phi(), -3.14);
    EXPECT_FALSE(r.next(st));
}

TEST(Import, TextRawlogTextGivesTheSameRecords) {
    TmpDir d;
    convertTextLogToRawlog(rfir_test::kFull, d / "a.rawlog");
    convertRawlogToTextLog(d / "a.rawlog", d / "a.txt");
    auto orig = readTextLog(rfir_test::kFull);
    canonicalizeRecordOrder(orig);  // the rawlog keeps odom, rfid, ir, rb
    std::ostringstream expected;
    writeTextLog(expected, orig);
    EXPECT_EQ(rfir_test::slurp(d / "a.txt"), expected.str());
    const auto back = readTextLog(d / "a.txt");
    EXPECT_EQ(back.header, orig.header);
    ASSERT_EQ(back.records.size(), orig.records.size());
    for (size_t i = 0; i < back.records.size(); i++)
        EXPECT_EQ(back.records[i], orig.records[i]) << i;
}

TEST(Import, RawlogTextRawlogIsIdenticalAndStable) {
    TmpDir d;
    convertTextLogToRawlog(rfir_test::kFull, d / "1.rawlog");
    convertRawlogToTextLog(d / "1.rawlog", d / "1.txt");
    convertTextLogToRawlog(d / "1.txt", d / "2.rawlog");
    convertRawlogToTextLog(d / "2.rawlog", d / "2.txt");
    convertTextLogToRawlog(d / "2.txt", d / "3.rawlog");
    EXPECT_EQ(rfir_test::compareRawlogs(d / "1.rawlog", d / "2.rawlog"), "");
    EXPECT_EQ(rfir_test::compareRawlogs(d / "2.rawlog", d / "3.rawlog"), "");
    EXPECT_EQ(rfir_test::gunzip(d / "1.rawlog"), rfir_test::gunzip(d / "2.rawlog"));
    EXPECT_EQ(rfir_test::slurp(d / "1.txt"), rfir_test::slurp(d / "2.txt"));
}

TEST(Import, WrittenRawlogWithFullPrecisionSurvivesText) {
    // A rawlog as a simulator writes it: values with all their digits.
    TmpDir d;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> ts;
    for (int k = 0; k < 60; k++)
        ts.push_back(1e-7 * std::floor(1e7 * (1000 + 0.0133 * k + 1e-3 * u(rng))));
    auto hdr = rfir_test::randomHeader(rng);
    hdr.timestamp = mrpt::Clock::fromDouble(ts[0]);  // as the import sets it
    CRawlogWriter w(d / "sim.rawlog", hdr);
    for (int k = 0; k < 60; k++) {
        std::vector<mrpt::obs::CObservation::Ptr> obs;
        rfir_test::randomInstant(rng, hdr, k, obs);
        std::optional<mrpt::poses::CPose2D> odo;
        if (k % 7) odo = exactPose(u(rng), u(rng), M_PI * u(rng));
        w.writeStep(ts[k], odo, obs);
    }
    w.close();
    convertRawlogToTextLog(d / "sim.rawlog", d / "sim.txt");
    convertTextLogToRawlog(d / "sim.txt", d / "back.rawlog");
    EXPECT_EQ(rfir_test::compareRawlogs(d / "sim.rawlog", d / "back.rawlog"), "");
}

TEST(Import, TimestampsRoundTrip) {
    // MRPT's fromDouble truncates t * 1e7 to 100 ns ticks. A t with at most 6
    // decimals comes back digit for digit; any t comes back on its own tick.
    for (double t : {0.0, 1e-6, 0.1, 0.3, 12.345, 59.999999, 86400.000001, 1e6 + 0.5,
                     123456.765432, 9999999.999999, 1700000000.123, 1700000000.123456}) {
        const auto ts = timestampFromT(t);
        ASSERT_TRUE(ts) << t;
        const auto s = formatTimestamp(*ts);
        ASSERT_TRUE(s) << t;
        EXPECT_EQ(*parseDecimal(*s), t) << *s;
    }
    for (double t :
         {1e-7, 59.9999999, 123456.7654321, 1700000000.1234567, 99999999999.9}) {
        const auto ts = timestampFromT(t);
        const auto s = formatTimestamp(*ts);
        ASSERT_TRUE(s) << t;
        EXPECT_EQ(timestampFromT(*parseDecimal(*s)), ts) << t << " -> " << *s;
        EXPECT_NEAR(*parseDecimal(*s), t, 1.01e-7 + 1e-16 * t);
    }
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int64_t> ticks(0, int64_t(1e14));
    for (int i = 0; i < 20000; i++) {
        const int64_t n = ticks(rng);
        const double t6 = double(n / 10) / 1e6;  // 6 decimals, below 1e7 s
        const auto s6 = formatTimestamp(*timestampFromT(t6));
        ASSERT_TRUE(s6);
        EXPECT_EQ(*parseDecimal(*s6), t6) << *s6;
        const auto ts7 = *timestampFromT(double(n) / 1e7);
        const auto s7 = formatTimestamp(ts7);
        ASSERT_TRUE(s7);
        EXPECT_EQ(*timestampFromT(*parseDecimal(*s7)), ts7) << *s7;
    }
    EXPECT_FALSE(timestampFromT(-0.5));
    EXPECT_FALSE(timestampFromT(1e11));
}

TEST(Import, RawlogOnlyRulesNameTheLine) {
    const std::string hdr =  // lines 1-5
        "format textlog 1\nreceiver L 0 0 1\nrb_sensor 0 0 0 1 1\nodom 1 0 0 0\n"
        "rb 1 A 0.3 0\n";
    const struct {
        const char* body;
        const char* message;
    } cases[] = {
        {"odom -2 0 0 0\n",
         "t -2 cannot be an MRPT timestamp (t must be in [0, 1e11) seconds)"},
        {"odom 1.00000001 0 0 0\n",
         "t 1.00000001 and the previous instant's t 1 (line 4) differ by less than the "
         "100 ns resolution of MRPT timestamps"},
        {"ir_raw 2 L 1000 1,2,3\n",
         "ir_raw window of 3 samples is too short to decode (at least 16)"},
        {"rb 1 A 0.2 0\n",
         "landmark 'A' is measured twice at t 1 (first at line 5): an MRPT range-bearing "
         "observation holds one measurement per landmark"},
    };
    // A negative t needs a log that starts there.
    TmpDir d;
    for (const auto& c : cases) {
        const bool negative = std::string(c.body).find("-2") != std::string::npos;
        const std::string text =
            negative ? "format textlog 1\n" + std::string(c.body) : hdr + c.body;
        std::ofstream(d / "in.txt") << text;
        try {
            convertTextLogToRawlog(d / "in.txt", d / "out.rawlog");
            ADD_FAILURE() << "accepted: " << c.body;
        } catch (const TextLogError& e) {
            EXPECT_EQ(e.line(), negative ? 2u : 6u);
            EXPECT_EQ(e.message(), c.message);
            EXPECT_EQ(std::string(e.what()).rfind(d / "in.txt:", 0), 0u);
        }
        EXPECT_FALSE(fs::exists(d / "out.rawlog"));
        EXPECT_EQ(d.count(), 1u);  // only the input: no temporary file either
    }
}

TEST(Import, NothingIsWrittenOnError) {
    TmpDir d;
    // A long valid log whose last line is malformed.
    std::string text = rfir_test::slurp(rfir_test::kFull);
    text += "odom 0.6 0 0 0\nrfid 0.7 R0 bad/tag\n";
    std::ofstream(d / "in.txt") << text;
    EXPECT_THROW(convertTextLogToRawlog(d / "in.txt", d / "out.rawlog"), TextLogError);
    EXPECT_FALSE(fs::exists(d / "out.rawlog"));
    // An existing output is left as it was.
    std::ofstream(d / "out.rawlog") << "old";
    EXPECT_THROW(convertTextLogToRawlog(d / "in.txt", d / "out.rawlog"), TextLogError);
    EXPECT_EQ(rfir_test::slurp(d / "out.rawlog"), "old");
    EXPECT_EQ(d.count(), 2u);
}

TEST(Import, ExportIsStrictUnlessLossy) {
    TmpDir d;
    CObservationLogHeader h;
    h.readers = {{"R0", 0, 0, 0.03, 0.03}};
    h.receivers = {{"L", 0, 0, 1}, {"M", 0, 0, 1}};
    {
        CRawlogWriter w(d / "x.rawlog", h);
        auto ir = CObservationIRSignals::Create();
        ir->sensorLabel = "IR";
        // Nothing in view for M, stored before L: the import of `ir 1 L 2,5
        // 1.25` puts M after L (the export checks the canonical form).
        ir->readings.push_back({h.receivers[1], {}, 0, 0, {}});
        ir->readings.push_back({h.receivers[0], {2, 5}, 1.25, 0, {}});
        w.writeStep(1, exactPose(0, 0, 0), {ir});
        w.writeStep(2, exactPose(0, 0, 0), {});
        w.close();
    }
    try {
        convertRawlogToTextLog(d / "x.rawlog", d / "x.txt");
        FAIL();
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        EXPECT_NE(
            m.find(d / "x.rawlog: instant 1 (t 1): IR readings with nothing in view "
                       "other than one per declared receiver"),
            std::string::npos)
            << m;
    }
    EXPECT_FALSE(fs::exists(d / "x.txt"));
    TConvertOptions o;
    o.lossy = true;
    const auto rep = convertRawlogToTextLog(d / "x.rawlog", d / "x.txt", o);
    ASSERT_EQ(rep.dropped.size(), 1u);
    EXPECT_EQ(rep.dropped.begin()->second, 1u);
    const auto log = readTextLog(d / "x.txt");
    ASSERT_EQ(log.records.size(), 3u);  // odom, ir L, odom
    EXPECT_EQ(log.records[1].codes, (std::vector<uint8_t>{2, 5}));
}

TEST(Import, StartHeadingPiEitherWay) {
    // pi written exactly (the import, rfir-sim) or as -pi (MRPT's CPose2D(x,
    // y, pi), another program): both export to `start 1 2 pi`, not lossy.
    for (const double phi : {M_PI, -M_PI}) {
        TmpDir d;
        CObservationLogHeader h;
        h.readers = {{"R0", 0, 0, 0.03, 0.03}};
        h.startPose.emplace();
        h.startPose->x(1);
        h.startPose->y(2);
        h.startPose->phi(phi);
        {
            CRawlogWriter w(d / "x.rawlog", h);
            w.writeStep(1, exactPose(0, 0, 0), {});
            w.close();
        }
        EXPECT_EQ(CRawlogReader(d / "x.rawlog").header().startPose->phi(), phi);
        convertRawlogToTextLog(d / "x.rawlog", d / "x.txt");
        const auto log = readTextLog(d / "x.txt");
        ASSERT_TRUE(log.header.start);
        EXPECT_EQ(log.header.start->phi, M_PI) << phi;
        convertTextLogToRawlog(d / "x.txt", d / "y.rawlog");
        EXPECT_EQ(CRawlogReader(d / "y.rawlog").header().startPose->phi(), M_PI);
    }
}

TEST(Import, ExportRefusesWhatTheTextWouldChange) {
    TmpDir d;
    CObservationLogHeader h;
    h.readers = {{"R0", 0, 0, 0.03, 0.03}};
    const auto run = [&](const mrpt::obs::CObservation::Ptr& o) {
        fs::remove(d / "y.txt");
        {
            CRawlogWriter w(d / "y.rawlog", h);
            w.writeStep(1, std::nullopt, {o});
            w.close();
        }
        try {
            convertRawlogToTextLog(d / "y.rawlog", d / "y.txt");
        } catch (const std::runtime_error& e) {
            EXPECT_FALSE(fs::exists(d / "y.txt"));
            return std::string(e.what());
        }
        return std::string();
    };
    auto rf = CObservationRFIDReaders::Create();
    rf->sensorLabel = "RFID";
    CObservationRFIDReaders::TReading moved;
    moved.reader = h.readers[0];
    moved.reader.x = 0.5;  // not where the header puts R0
    moved.tags = {"T"};
    rf->readings.push_back(moved);
    EXPECT_NE(
        run(rf).find("CObservationRFIDReaders with fields textlog 1 does not carry"),
        std::string::npos);
    rf->readings[0].reader = h.readers[0];
    rf->sensorLabel = "MY_RFID";
    EXPECT_NE(run(rf).find("does not carry"), std::string::npos);
    rf->sensorLabel = "RFID";
    EXPECT_EQ(run(rf), "");
    rf->readings[0].reader.id = "R9";  // undeclared: the text would be invalid
    EXPECT_NE(
        run(rf).find("would write an invalid text log line: rfid names reader 'R9'"),
        std::string::npos);
    auto other = std::make_shared<CObservationLogHeader>();  // a class with no record
    EXPECT_NE(run(other).find("observation of class rfir::obs::CObservationLogHeader"),
              std::string::npos);
}

TEST(Import, TimestampThatNoDecimalGivesIsRefused) {
    // Near 1.7e9 s doubles are 2.4e-7 s apart: some 100 ns ticks (clock
    // readings) are the image of no decimal t.
    std::optional<mrpt::Clock::time_point> ts;
    for (int64_t k = 0; k < 16 && !ts; k++) {
        const mrpt::Clock::time_point c(mrpt::Clock::duration(
            mrpt::Clock::fromDouble(1700000000).time_since_epoch().count() + k));
        if (!formatTimestamp(c)) ts = c;
    }
    ASSERT_TRUE(ts);
    TmpDir d;
    CObservationLogHeader h = toLogHeader({}, {}, 0);
    h.readers = {{"R0", 0, 0, 0.03, 0.03}};
    {
        mrpt::io::CFileGZOutputStream f(d / "t.rawlog");
        auto ar = mrpt::serialization::archiveFrom(f);
        mrpt::obs::CActionCollection acts;
        mrpt::obs::CSensoryFrame sf0, sf1;
        sf0.insert(std::make_shared<CObservationLogHeader>(h));
        auto rf = CObservationRFIDReaders::Create();
        rf->sensorLabel = "RFID";
        rf->timestamp = *ts;
        rf->readings.push_back({h.readers[0], {"T"}});
        sf1.insert(rf);
        ar << acts << sf0 << acts << sf1;
    }
    try {
        convertRawlogToTextLog(d / "t.rawlog", d / "t.txt");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(
            std::string(e.what()).find("timestamp that no decimal t maps to exactly"),
            std::string::npos)
            << e.what();
    }
    TConvertOptions o;
    o.lossy = true;
    EXPECT_EQ(convertRawlogToTextLog(d / "t.rawlog", d / "t.txt", o).dropped.size(), 1u);
    EXPECT_EQ(readTextLog(d / "t.txt").records.size(), 1u);
}

}  // namespace
