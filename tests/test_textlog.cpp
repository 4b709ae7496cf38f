// The text log parser on a well-formed log with every record type, numbers,
// and the canonical writer.
#include <rfir/common/textlog.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

using namespace rfir::common;
using K = TTimedRecord::Kind;

namespace {
const std::string kFull = std::string(RFIR_SOURCE_DIR) + "/tests/data/textlog/full.txt";

TEST(TextLog, WellFormedLogWithEveryRecordType) {
    const auto log = readTextLog(kFull);
    const auto& h = log.header;
    ASSERT_EQ(h.readers.size(), 2u);
    EXPECT_EQ(h.readers[0], (rfir::obs::TRFIDReader{"R0", 0.15, -0.05, 0.03, 0.03}));
    EXPECT_EQ(h.readers[1].id, "R1");
    ASSERT_EQ(h.receivers.size(), 2u);
    EXPECT_EQ(h.receivers[1], (rfir::obs::TIRReceiver{"right", 0.1, -0.2, 0.35}));
    ASSERT_TRUE(h.rbSensor);
    EXPECT_EQ(h.rbSensor->x, 0.2);
    EXPECT_EQ(h.rbSensor->maxRange, 0.5);
    EXPECT_EQ(h.rbSensor->fov, 2.0943951023931953);
    ASSERT_TRUE(h.start);
    EXPECT_EQ(*h.start, (TTextLogHeader::TStart{1.25, -0.5, 1.5707963267948966}));

    const auto& r = log.records;
    ASSERT_EQ(r.size(), 17u);
    EXPECT_EQ(r[0].kind, K::Odom);
    EXPECT_EQ(r[0].line, 13u);
    EXPECT_EQ(r[1].kind, K::Rfid);
    EXPECT_EQ(r[1].tags, std::vector<std::string>{"E0040150A1B2C3D4"});
    EXPECT_TRUE(r[2].tags.empty());  // a reader polled that read nothing
    EXPECT_EQ(r[3].kind, K::Ir);
    EXPECT_EQ(r[3].codes, (std::vector<uint8_t>{3, 9}));
    EXPECT_EQ(r[3].volts, 1.82);
    EXPECT_EQ(r[4].kind, K::Rb);
    EXPECT_EQ(r[4].id, "L7");
    EXPECT_EQ(r[4].range, 0.42f);
    EXPECT_EQ(r[4].bearing, 0.3f);
    EXPECT_EQ(r[6].phi, 0.01);  // the comment after it is ignored
    EXPECT_EQ(r[7].tags, (std::vector<std::string>{"E0040150A1B2C3D4", "tag:17"}));
    EXPECT_EQ(r[9].kind, K::IrRaw);
    EXPECT_EQ(r[9].rateHz, 5000);
    EXPECT_EQ(r[9].samples.size(), 1024u);
    EXPECT_EQ(r[13].tags, std::vector<std::string>{"T-9_x.y"});
    EXPECT_EQ(r[14].phi, M_PI);  // pi itself is in (-pi, pi]
    EXPECT_EQ(r[15].codes.size(), 9u);
    EXPECT_EQ(r.back().t, 0.5);
}

TEST(TextLog, TabsCarriageReturnsAndComments) {
    std::istringstream in(
        "# leading comment\n\n  \t\nformat textlog 1\r\nreader\tR0\t0 0 0.03 0.03 # c\r\n"
        "odom 0 0 0 0#no space before the comment\n");
    const auto log = readTextLog(in, "x.txt");
    ASSERT_EQ(log.header.readers.size(), 1u);
    ASSERT_EQ(log.records.size(), 1u);
    EXPECT_EQ(log.records[0].line, 6u);
}

TEST(TextLog, SameIdForAReaderAndAReceiverIsAllowed) {
    // Duplicates are per kind: readers 0..7 and receivers 0..1 are common.
    std::istringstream in("format textlog 1\nreader 0 0 0 1 1\nreceiver 0 0 0 1\n");
    EXPECT_NO_THROW(readTextLog(in, "x.txt"));
}

TEST(TextLog, DecimalSyntax) {
    for (const char* ok : {"0", "-0", "+1", "1.", ".5", "-.5", "1e3", "1E-3", "2.5e+2"})
        EXPECT_TRUE(parseDecimal(ok)) << ok;
    for (const char* bad : {"", "+", "-", ".", "e3", "1e", "1e+", "0x10", "1,5", "1..2",
                            "nan", "inf", "1 ", "--1", "1e999", "1f"})
        EXPECT_FALSE(parseDecimal(bad)) << bad;
    EXPECT_EQ(*parseDecimal("2.5e+2"), 250.0);
}

TEST(TextLog, ShortestNumbersReadBackExactly) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1e3, 1e3);
    for (int i = 0; i < 20000; i++) {
        const double d = i % 3 ? u(rng) : u(rng) * 1e-9;
        EXPECT_EQ(*parseDecimal(formatNumber(d)), d);
        const float f = float(d);
        EXPECT_EQ(*parseDecimalFloat(formatNumber(f)), f);
    }
    EXPECT_EQ(formatNumber(0.1), "0.1");
    EXPECT_EQ(formatNumber(0.1f), "0.1");
    EXPECT_EQ(formatNumber(M_PI), "3.141592653589793");
    EXPECT_EQ(*parseDecimal(formatNumber(std::numeric_limits<double>::denorm_min())),
              std::numeric_limits<double>::denorm_min());
}

TEST(TextLog, BearingNearPiStaysInRangeAsAFloat) {
    // float(pi) is above pi: a bearing of pi is stored as the float just below.
    std::istringstream in(
        "format textlog 1\nrb_sensor 0 0 0 1 6\nrb 0 L 0.3 3.141592653589793\n");
    const auto log = readTextLog(in, "x.txt");
    const float b = log.records[0].bearing;
    EXPECT_LE(double(b), M_PI);
    EXPECT_GT(double(b), 3.14159);
    std::ostringstream o;
    writeTextLog(o, log);
    std::istringstream back(o.str());
    EXPECT_EQ(readTextLog(back, "y.txt").records[0].bearing, b);
}

TEST(TextLog, WriterOutputParsesToTheSameLog) {
    const auto log = readTextLog(kFull);
    std::ostringstream o;
    writeTextLog(o, log);
    std::istringstream in(o.str());
    const auto back = readTextLog(in, "written.txt");
    EXPECT_EQ(back.header, log.header);
    ASSERT_EQ(back.records.size(), log.records.size());
    for (size_t i = 0; i < log.records.size(); i++)
        EXPECT_EQ(back.records[i], log.records[i]) << "record " << i;
    // Writing the re-read log gives the same text.
    std::ostringstream o2;
    writeTextLog(o2, back);
    EXPECT_EQ(o2.str(), o.str());
}

TEST(TextLog, CanonicalOrderWithinAnInstant) {
    std::istringstream in(
        "format textlog 1\nreader R 0 0 1 1\nreceiver L 0 0 1\nrb_sensor 0 0 0 1 1\n"
        "rb 1 A 0.5 0\nir 1 L 2 1\nrfid 1 R\nodom 1 0 0 0\nir_raw 1 L 100 1,2\n"
        "rfid 2 R\nodom 2 0 0 0\n");
    auto log = readTextLog(in, "x.txt");
    canonicalizeRecordOrder(log);
    std::vector<K> kinds;
    for (const auto& r : log.records) kinds.push_back(r.kind);
    EXPECT_EQ(kinds, (std::vector<K>{K::Odom, K::Rfid, K::Ir, K::IrRaw, K::Rb, K::Odom,
                                     K::Rfid}));
}

TEST(TextLog, MissingFileNamesIt) {
    try {
        readTextLog("/nonexistent/x.txt");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/x.txt"), std::string::npos);
    }
}

}  // namespace
