// One malformed case per rule of the text log format (textlog 1): each must be
// rejected with "FILE:LINE: message", naming the right line.
#include <rfir/common/textlog.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>

using namespace rfir::common;

namespace {
// Lines 1-5 of every case that does not bring its own header.
const char* kHeader =
    "format textlog 1\n"
    "reader R0 0.15 -0.05 0.03 0.03\n"
    "receiver left 0.1 0.2 0.35\n"
    "rb_sensor 0.2 0 0 0.5 2\n"
    "odom 1 0 0 0\n";

struct TCase {
    const char* name;
    bool ownHeader;    // the body is the whole file
    const char* body;  // appended after kHeader otherwise (from line 6)
    size_t line;
    const char* message;
};

const TCase kCases[] = {
    // The format line.
    {"no format line", true, "reader R0 0 0 1 1\n", 1,
     "the first record must be 'format textlog 1', got 'reader R0'"},
    {"other version", true, "# v2\nformat textlog 2\n", 2,
     "unsupported format line 'format textlog 2' (this program reads 'format textlog "
     "1')"},
    {"byte order mark", true,
     "\xEF\xBB\xBF"
     "format textlog 1\n",
     1, "the file starts with a UTF-8 byte order mark: save it without one"},
    {"format with extra field", true, "format textlog 1 x\n", 1,
     "unsupported format line 'format textlog 1 x' (this program reads 'format textlog "
     "1')"},
    {"empty log", true, "# only a comment\n\n", 2,
     "empty text log: the first record must be 'format textlog 1'"},
    {"format twice", false, "format textlog 1\n", 6,
     "'format' may appear only once, as the first record"},
    // Unknown records and field counts.
    {"unknown record", false, "lidar 1 2 3\n", 6,
     "unknown record 'lidar' (expected reader, receiver, rb_sensor, start, odom, rfid, "
     "ir, "
     "ir_raw or rb)"},
    {"record names are case-sensitive", false, "ODOM 2 0 0 0\n", 6,
     "unknown record 'ODOM' (expected reader, receiver, rb_sensor, start, odom, rfid, "
     "ir, "
     "ir_raw or rb)"},
    {"reader fields", true, "format textlog 1\nreader R0 0 0 0.03\n", 2,
     "'reader' takes 5 fields (<reader_id> <x> <y> <half_x> <half_y>), got 4"},
    {"receiver fields", true, "format textlog 1\nreceiver L 0 0 0.3 1\n", 2,
     "'receiver' takes 4 fields (<receiver_id> <x> <y> <z>), got 5"},
    {"rb_sensor fields", true, "format textlog 1\nrb_sensor 0 0 0 0.5\n", 2,
     "'rb_sensor' takes 5 fields (<x> <y> <yaw> <max_range> <fov>), got 4"},
    {"start fields", true, "format textlog 1\nstart 0 0\n", 2,
     "'start' takes 3 fields (<x> <y> <phi>), got 2"},
    {"odom fields", false, "odom 2 0 0 0 0\n", 6,
     "'odom' takes 4 fields (<t> <x> <y> <phi>), got 5"},
    {"rfid fields", false, "rfid 2\n", 6,
     "'rfid' takes at least 2 fields (<t> <reader_id> [<tag_id> ...]), got 1"},
    {"ir fields", false, "ir 2 left 3\n", 6,
     "'ir' takes 4 fields (<t> <receiver_id> <codes> <volts>), got 3"},
    {"ir_raw fields", false, "ir_raw 2 left 1000 1,2 3\n", 6,
     "'ir_raw' takes 4 fields (<t> <receiver_id> <rate_hz> <v1,v2,...>), got 5"},
    {"rb fields", false, "rb 2 L1 0.3\n", 6,
     "'rb' takes 4 fields (<t> <landmark_id> <range> <bearing>), got 3"},
    // IDs.
    {"ID character", true, "format textlog 1\nreader R/0 0 0 1 1\n", 2,
     "reader_id 'R/0' has a character outside [A-Za-z0-9_.:-]"},
    {"ID length", true,
     "format textlog 1\nreceiver "
     "A123456789B123456789C123456789D123456789E123456789F123456789G1234 0 0 1\n",
     2,
     "receiver_id 'A123456789B123456789C123456789D123456789E123456789F123456789G1234' is "
     "longer than 64 characters"},
    {"tag ID", false, "rfid 2 R0 T1 T,2\n", 6,
     "tag_id 'T,2' has a character outside [A-Za-z0-9_.:-]"},
    {"landmark ID", false, "rb 2 L$ 0.3 0\n", 6,
     "landmark_id 'L$' has a character outside [A-Za-z0-9_.:-]"},
    // Numbers.
    {"nan", false, "odom 2 nan 0 0\n", 6,
     "x 'nan' is not a finite number (nan and inf are not allowed)"},
    {"inf", false, "odom 2 0 -inf 0\n", 6,
     "y '-inf' is not a finite number (nan and inf are not allowed)"},
    {"infinity in t", false, "odom Infinity 0 0 0\n", 6,
     "t 'Infinity' is not a finite number (nan and inf are not allowed)"},
    {"not a number", false, "odom 2 0 0 abc\n", 6,
     "phi 'abc' is not a finite decimal number"},
    {"hex float", false, "odom 2 0x1p3 0 0\n", 6,
     "x '0x1p3' is not a finite decimal number"},
    {"decimal comma", false, "odom 2 0,5 0 0\n", 6,
     "x '0,5' is not a finite decimal number"},
    // A corrupt file's bytes are quoted escaped, so the error stays text.
    {"binary bytes", false, "odom 2 0\x01\xd9 0 0\n", 6,
     "x '0\\x01\\xD9' is not a finite decimal number"},
    {"overflow", false, "ir 2 left 3 1e999\n", 6,
     "volts '1e999' is not a finite decimal number"},
    // Sizes, ranges and rates.
    {"half_x zero", true, "format textlog 1\nreader R0 0 0 0 0.03\n", 2,
     "half_x must be > 0, got 0"},
    {"half_y negative", true, "format textlog 1\nreader R0 0 0 0.03 -0.03\n", 2,
     "half_y must be > 0, got -0.03"},
    {"max_range zero", true, "format textlog 1\nrb_sensor 0 0 0 0 2\n", 2,
     "max_range must be > 0, got 0"},
    {"fov zero", true, "format textlog 1\nrb_sensor 0 0 0 0.5 0\n", 2,
     "fov must be > 0, got 0"},
    {"fov beyond a turn", true, "format textlog 1\nrb_sensor 0 0 0 0.5 6.3\n", 2,
     "fov must be in (0, 2 pi] radians, got 6.3"},
    {"range zero", false, "rb 2 L1 0 0.1\n", 6, "range must be > 0, got 0"},
    {"rate_hz zero", false, "ir_raw 2 left 0 1,2,3\n", 6, "rate_hz must be > 0, got 0"},
    {"rate_hz negative", false, "ir_raw 2 left -8000 1,2,3\n", 6,
     "rate_hz must be > 0, got -8000"},
    // Angles in (-pi, pi].
    {"odom phi", false, "odom 2 0 0 3.1416\n", 6,
     "phi must be an angle in (-pi, pi] radians, got 3.1416"},
    {"phi = -pi", false, "odom 2 0 0 -3.141592653589793\n", 6,
     "phi must be an angle in (-pi, pi] radians, got -3.141592653589793"},
    {"start phi", true, "format textlog 1\nstart 0 0 -4\n", 2,
     "phi must be an angle in (-pi, pi] radians, got -4"},
    {"rb_sensor yaw", true, "format textlog 1\nrb_sensor 0 0 7 0.5 2\n", 2,
     "yaw must be an angle in (-pi, pi] radians, got 7"},
    {"bearing", false, "rb 2 L1 0.3 -3.2\n", 6,
     "bearing must be an angle in (-pi, pi] radians, got -3.2"},
    // Order: header first, time non-decreasing, one pose per instant.
    {"header after timed", false, "reader R9 0 0 0.03 0.03\n", 6,
     "header record 'reader' after the first timed record (line 5): header records come "
     "first"},
    {"start after timed", false, "odom 2 0 0 0\nstart 0 0 0\n", 7,
     "header record 'start' after the first timed record (line 5): header records come "
     "first"},
    {"time goes back", false, "odom 2 0 0 0\nrfid 1.5 R0\n", 7,
     "t 1.5 is earlier than the previous record's t 2 (line 6): timed records must be in "
     "non-decreasing time"},
    {"two poses at one t", false, "rfid 2 R0\nodom 2 0 0 0\nodom 2 1 0 0\n", 8,
     "second odom record at t 2 (first at line 7): one sensing instant has one pose"},
    // Declarations.
    {"undeclared reader", false, "rfid 2 R5 T1\n", 6,
     "rfid names reader 'R5', which no 'reader' header record declares"},
    {"undeclared receiver (ir)", false, "ir 2 right 3 1.0\n", 6,
     "ir names receiver 'right', which no 'receiver' header record declares"},
    {"undeclared receiver (ir_raw)", false, "ir_raw 2 right 1000 1,2\n", 6,
     "ir_raw names receiver 'right', which no 'receiver' header record declares"},
    {"rb without rb_sensor", true, "format textlog 1\nodom 0 0 0 0\nrb 0 L1 0.3 0\n", 3,
     "'rb' record without an 'rb_sensor' header record"},
    {"duplicate reader", true,
     "format textlog 1\nreader R0 0 0 1 1\n# again\nreader R0 1 0 1 1\n", 4,
     "duplicate reader ID 'R0' (first declared at line 2)"},
    {"duplicate receiver", true, "format textlog 1\nreceiver a 0 0 1\nreceiver a 0 0 1\n",
     3, "duplicate receiver ID 'a' (first declared at line 2)"},
    {"duplicate rb_sensor", true,
     "format textlog 1\nrb_sensor 0 0 0 0.5 2\nrb_sensor 0 0 0 0.5 2\n", 3,
     "duplicate 'rb_sensor' record (first declared at line 2)"},
    {"duplicate start", true, "format textlog 1\nstart 0 0 0\nstart 1 0 0\n", 3,
     "duplicate 'start' record (first declared at line 2)"},
    // IR codes and raw windows.
    {"codes repeated", false, "ir 2 left 3,3 1\n", 6,
     "codes '3,3' is not a comma-separated ascending list of codes 1..9"},
    {"codes descending", false, "ir 2 left 9,3 1\n", 6,
     "codes '9,3' is not a comma-separated ascending list of codes 1..9"},
    {"code 0", false, "ir 2 left 0 1\n", 6,
     "codes '0' is not a comma-separated ascending list of codes 1..9"},
    {"code 10", false, "ir 2 left 10 1\n", 6,
     "codes '10' is not a comma-separated ascending list of codes 1..9"},
    {"codes trailing comma", false, "ir 2 left 3, 1\n", 6,
     "codes '3,' is not a comma-separated ascending list of codes 1..9"},
    {"codes as emitter ID", false, "ir 2 left 39 1\n", 6,
     "codes '39' is not a comma-separated ascending list of codes 1..9"},
    {"empty sample", false, "ir_raw 2 left 1000 1,,2\n", 6,
     "sample 2 '' of the ir_raw window is not a finite decimal number"},
    {"nan sample", false, "ir_raw 2 left 1000 1,2,nan\n", 6,
     "sample 3 'nan' of the ir_raw window is not a finite decimal number"},
    {"sample beyond float", false, "ir_raw 2 left 1000 1,1e40\n", 6,
     "sample 2 '1e40' of the ir_raw window is not a finite decimal number"},
};

class TextLogRule : public ::testing::TestWithParam<TCase> {};

TEST_P(TextLogRule, IsRejectedWithFileLineAndMessage) {
    const TCase& c = GetParam();
    const std::string text = c.ownHeader ? c.body : std::string(kHeader) + c.body;
    std::istringstream in(text);
    try {
        readTextLog(in, "case.txt");
        FAIL() << "accepted: " << c.name;
    } catch (const TextLogError& e) {
        EXPECT_EQ(e.line(), c.line) << c.name;
        EXPECT_EQ(e.message(), c.message) << c.name;
        EXPECT_EQ(std::string(e.what()),
                  "case.txt:" + std::to_string(c.line) + ": " + c.message);
    }
}

std::string caseName(const ::testing::TestParamInfo<TCase>& i) {
    std::string n;
    for (const char* p = i.param.name; *p; p++)
        n += std::isalnum(static_cast<unsigned char>(*p)) ? *p : '_';
    return n + "_" + std::to_string(i.index);
}

INSTANTIATE_TEST_SUITE_P(All, TextLogRule, ::testing::ValuesIn(kCases), caseName);

TEST(TextLogRules, HeaderAloneIsWellFormed) {
    // The common prefix of the cases is itself valid: each case fails only
    // because of its own line.
    std::istringstream in(kHeader);
    const auto log = readTextLog(in, "case.txt");
    EXPECT_EQ(log.records.size(), 1u);
}

}  // namespace
