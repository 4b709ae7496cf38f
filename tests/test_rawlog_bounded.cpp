// The bounded reads of counts, strings and flags (rfir/obs/bounded_read.h),
// and the guards on MRPT's classes (rfir/obs/mrpt_guards.h), on hand-made
// byte streams.
#include <rfir/obs/bounded_read.h>
#include <rfir/obs/registerAllClasses.h>

#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRFID.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/poses/CPosePDFParticles.h>
#include <mrpt/serialization/CArchive.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

using namespace rfir::obs;

namespace {
struct TFixedLeft : IBytesLeft {
    uint64_t n;
    explicit TFixedLeft(uint64_t v) : n(v) {}
    std::optional<uint64_t> bytesLeft() const override { return n; }
};

// A stream holding `bytes`, rewound for reading.
struct TStream {
    mrpt::io::CMemoryStream m;
    explicit TStream(const std::vector<uint8_t>& bytes) {
        if (!bytes.empty()) m.Write(bytes.data(), bytes.size());
        m.Seek(0);
    }
    mrpt::serialization::CArchiveStreamBase<mrpt::io::CMemoryStream> ar() {
        return mrpt::serialization::archiveFrom(m);
    }
};

std::vector<uint8_t> u32(uint32_t v) {
    return {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)};
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(BoundedRead, CountWithinBoundIsReturned) {
    TStream s(u32(7));
    auto a = s.ar();
    EXPECT_EQ(readBoundedCount(a, "T", 7, 1), 7u);
}

TEST(BoundedRead, CountAboveBoundNamesWhatAndBound) {
    TStream s(u32(0xFFFFFFFFu));
    auto a = s.ar();
    const auto e =
        errorOf([&] { readBoundedCount(a, "CObservationX: readers", 4096, 1); });
    EXPECT_NE(e.find("CObservationX: readers"), std::string::npos) << e;
    EXPECT_NE(e.find("4294967295"), std::string::npos) << e;
    EXPECT_NE(e.find("4096"), std::string::npos) << e;
}

TEST(BoundedRead, CountAboveBytesLeftIsRefusedBeforeAllocation) {
    TFixedLeft left(100);
    CBytesLeftScope scope(&left);
    {
        TStream s(u32(26));  // 26 x 4 bytes > 100
        auto a = s.ar();
        const auto e = errorOf([&] { readBoundedCount(a, "T", 1000, 4); });
        EXPECT_NE(e.find("only 100 left"), std::string::npos) << e;
    }
    TStream s(u32(25));  // exactly fits
    auto a = s.ar();
    EXPECT_EQ(readBoundedCount(a, "T", 1000, 4), 25u);
}

TEST(BoundedRead, ScopeRestoresThePreviousSource) {
    EXPECT_FALSE(bytesLeftInStream());
    TFixedLeft a(5), b(9);
    {
        CBytesLeftScope sa(&a);
        {
            CBytesLeftScope sb(&b);
            EXPECT_EQ(*bytesLeftInStream(), 9u);
        }
        EXPECT_EQ(*bytesLeftInStream(), 5u);
    }
    EXPECT_FALSE(bytesLeftInStream());
}

TEST(BoundedRead, Count64AboveBoundIsRefused) {
    auto b = u32(0);
    auto hi = u32(1);
    b.insert(b.end(), hi.begin(), hi.end());  // 2^32
    TStream s(b);
    auto a = s.ar();
    EXPECT_NE(
        errorOf([&] { readBoundedCount64(a, "M", 1u << 24, 1); }).find("4294967296"),
        std::string::npos);
}

TEST(BoundedRead, StringReadsMrptLayout) {
    mrpt::io::CMemoryStream m;
    auto w = mrpt::serialization::archiveFrom(m);
    w << std::string("R0") << std::string();
    m.Seek(0);
    auto a = mrpt::serialization::archiveFrom(m);
    EXPECT_EQ(readBoundedString(a, "T"), "R0");
    EXPECT_EQ(readBoundedString(a, "T"), "");
}

TEST(BoundedRead, LongStringIsRefused) {
    auto b = u32(5000);
    b.resize(b.size() + 5000, 'x');
    TStream s(b);
    auto a = s.ar();
    const auto e = errorOf([&] { readBoundedString(a, "CObservationLogHeader"); });
    EXPECT_NE(e.find("CObservationLogHeader"), std::string::npos) << e;
    EXPECT_NE(e.find("5000"), std::string::npos) << e;
}

TEST(BoundedRead, StringCutShortThrows) {
    auto b = u32(10);
    b.push_back('a');
    TStream s(b);
    auto a = s.ar();
    EXPECT_THROW(readBoundedString(a, "T"), std::exception);
}

TEST(BoundedRead, StrictBool) {
    TStream s({0, 1, 51});
    auto a = s.ar();
    EXPECT_FALSE(readStrictBool(a, "T"));
    EXPECT_TRUE(readStrictBool(a, "T"));
    const auto e = errorOf([&] { readStrictBool(a, "CObservationLogHeader"); });
    EXPECT_NE(e.find("51"), std::string::npos) << e;
}

namespace {
// An odometry action as MRPT writes it, then read back through the registry.
std::vector<uint8_t> serializedMovement(const mrpt::obs::CActionRobotMovement2D& mv) {
    mrpt::io::CMemoryStream m;
    auto w = mrpt::serialization::archiveFrom(m);
    w << mv;
    const auto* p = static_cast<const uint8_t*>(m.getRawBufferData());
    return std::vector<uint8_t>(p, p + m.getTotalBytesCount());
}

mrpt::serialization::CSerializable::Ptr readBack(const std::vector<uint8_t>& b) {
    TStream s(b);
    auto a = s.ar();
    return a.ReadObject();
}

// Offset of the int32 estimationMethod: after the name header and version.
size_t methodOffset() {
    return 1 + std::string("mrpt::obs::CActionRobotMovement2D").size() + 1;
}
}  // namespace

TEST(MrptGuards, ValidMovementReadsBackAsMrptClass) {
    registerAllClasses();
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0.2, 0.3), {});
    auto o = std::dynamic_pointer_cast<mrpt::obs::CActionRobotMovement2D>(
        readBack(serializedMovement(mv)));
    ASSERT_TRUE(o);
    EXPECT_EQ(o->GetRuntimeClass(), CLASS_ID(mrpt::obs::CActionRobotMovement2D));
    EXPECT_EQ(o->rawOdometryIncrementReading, mv.rawOdometryIncrementReading);
    // Written back, the bytes are those MRPT wrote.
    EXPECT_EQ(serializedMovement(*o), serializedMovement(mv));
}

TEST(MrptGuards, BadEstimationMethodIsRefused) {
    registerAllClasses();
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0.2, 0.3), {});
    auto b = serializedMovement(mv);
    b[methodOffset() + 1] = 0x09;  // the byte of tests/data/repro/mrpt_segv_min.rawlog
    const auto e = errorOf([&] { readBack(b); });
    EXPECT_NE(e.find("estimationMethod 2304"), std::string::npos) << e;
    b[methodOffset() + 1] = 0;
    b[methodOffset()] = 1;  // emScan2DMatching followed by a CPose2D: MRPT crashes
    const auto e1 = errorOf([&] { readBack(b); });
    EXPECT_NE(e1.find("not a pose PDF"), std::string::npos) << e1;
}

TEST(MrptGuards, HugeThrunParticleCountIsRefused) {
    registerAllClasses();
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opt;
    opt.modelSelection = mrpt::obs::CActionRobotMovement2D::mmThrun;
    opt.thrunModel.nParticlesCount = 10;
    mrpt::obs::CActionRobotMovement2D mv;
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0), opt);
    auto b = serializedMovement(mv);
    EXPECT_NO_THROW(readBack(b));
    // The count follows the method, the pose object, the model and 6 floats.
    const size_t at = methodOffset() + 4 + (1 + 20 + 1 + 24 + 1) + 4 + 24;
    ASSERT_EQ(b[at], 10);
    b[at + 3] = 0x7F;
    const auto e = errorOf([&] { readBack(b); });
    EXPECT_NE(e.find("particle count"), std::string::npos) << e;
    // Version 3 (fuzz_rawlog): 5 floats before the count, and MRPT takes any
    // model but 0 for Thrun's.
    b[methodOffset() - 1] = 3;
    b.erase(b.begin() + at - 4, b.begin() + at);
    const auto e3 = errorOf([&] { readBack(b); });
    EXPECT_NE(e3.find("particle count"), std::string::npos) << e3;
    b[at - 4 - 24] = 0xF7;  // model 247
    const auto e4 = errorOf([&] { readBack(b); });
    EXPECT_NE(e4.find("motion model 247"), std::string::npos) << e4;
    // Versions 0 and 1 start with a pose PDF of any class: refused.
    b[methodOffset() - 1] = 1;
    const auto e1 = errorOf([&] { readBack(b); });
    EXPECT_NE(e1.find("version 1"), std::string::npos) << e1;
}

TEST(MrptGuards, HugeContainerCountsAreRefused) {
    registerAllClasses();
    for (const bool frame : {false, true}) {
        mrpt::io::CMemoryStream m;
        auto w = mrpt::serialization::archiveFrom(m);
        if (frame)
            w << mrpt::obs::CSensoryFrame();
        else
            w << mrpt::obs::CActionCollection();
        const auto* p = static_cast<const uint8_t*>(m.getRawBufferData());
        std::vector<uint8_t> b(p, p + m.getTotalBytesCount());
        const std::string name =
            frame ? "mrpt::obs::CSensoryFrame" : "mrpt::obs::CActionCollection";
        EXPECT_NO_THROW(readBack(b));
        const size_t at = 1 + name.size() + 1;  // the uint32 count
        b[at + 3] = 0xFF;
        const auto e = errorOf([&] { readBack(b); });
        EXPECT_NE(e.find(name + ": object count"), std::string::npos) << e;
        if (frame) {
            // A fuzzed version byte: the pre-2009 layouts are refused.
            b[at + 3] = 0;
            b[at - 1] = 1;
            const auto e1 = errorOf([&] { readBack(b); });
            EXPECT_NE(e1.find("CSensoryFrame: version 1"), std::string::npos) << e1;
        }
    }
}

namespace {
template <class T>
std::vector<uint8_t> serialized(const T& o) {
    mrpt::io::CMemoryStream m;
    auto w = mrpt::serialization::archiveFrom(m);
    w << o;
    const auto* p = static_cast<const uint8_t*>(m.getRawBufferData());
    return std::vector<uint8_t>(p, p + m.getTotalBytesCount());
}
}  // namespace

TEST(MrptGuards, OdometryLabelLengthIsBounded) {
    registerAllClasses();
    mrpt::obs::CObservationOdometry o;
    o.sensorLabel = "ODOMETRY";
    o.odometry = mrpt::poses::CPose2D(1, 2, 0.5);
    auto b = serialized(o);
    auto back = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(readBack(b));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->sensorLabel, "ODOMETRY");
    EXPECT_EQ(serialized(*back), b);
    // The label follows the class header and the CPose2D object.
    const size_t at = 1 + std::string("mrpt::obs::CObservationOdometry").size() + 1 + 47;
    ASSERT_EQ(b[at], 8);
    b[at + 3] = 0x7F;
    const auto e = errorOf([&] { readBack(b); });
    EXPECT_NE(e.find("sensorLabel length"), std::string::npos) << e;
    // Versions 0 and 1 start the same (fuzz_rawlog tries every version).
    for (uint8_t v : {0, 1}) {
        b[at - 48] = v;
        const auto ev = errorOf([&] { readBack(b); });
        EXPECT_NE(ev.find("sensorLabel length"), std::string::npos) << int(v) << ev;
    }
}

TEST(MrptGuards, BearingRangeCountIsBounded) {
    registerAllClasses();
    mrpt::obs::CObservationBearingRange o;
    o.sensorLabel = "RB";
    o.maxSensorDistance = 0.5;
    o.sensedData.resize(2);
    o.sensedData[1].range = 0.25f;
    o.sensedData[1].landmarkID = 7;
    auto b = serialized(o);
    auto back =
        std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(readBack(b));
    ASSERT_TRUE(back);
    ASSERT_EQ(back->sensedData.size(), 2u);
    EXPECT_EQ(back->sensedData[1].landmarkID, 7);
    EXPECT_EQ(serialized(*back), b);
    // Header, 4 floats, the CPose3D object, timestamp, flag, 3 deviations.
    const size_t at = 1 + std::string("mrpt::obs::CObservationBearingRange").size() + 1 +
                      16 + 119 + 8 + 1 + 12;
    ASSERT_EQ(b[at], 2);
    b[at + 3] = 0x40;
    const auto e = errorOf([&] { readBack(b); });
    EXPECT_NE(e.find("measurement count"), std::string::npos) << e;
    // Version 2 (no covariance flag, no deviations, 3 floats before the pose)
    // and version 0 (no timestamp either): the same count is bounded.
    const size_t ver = 1 + std::string("mrpt::obs::CObservationBearingRange").size();
    auto b2 = b;
    b2[ver] = 2;
    b2.erase(b2.begin() + at - 13, b2.begin() + at);       // the flag and deviations
    b2.erase(b2.begin() + ver + 1, b2.begin() + ver + 5);  // one float
    const auto e2 = errorOf([&] { readBack(b2); });
    EXPECT_NE(e2.find("measurement count"), std::string::npos) << e2;
    b2[ver] = 0;
    const size_t ts = ver + 1 + 12 + 119;
    b2.erase(b2.begin() + ts, b2.begin() + ts + 8);
    const auto e0 = errorOf([&] { readBack(b2); });
    EXPECT_NE(e0.find("measurement count"), std::string::npos) << e0;
}

namespace {
// Offset of the measurement count of a serialized bearing-range observation.
size_t bearingCountOffset(bool validCov) {
    return 1 + std::string("mrpt::obs::CObservationBearingRange").size() + 1 + 16 + 119 +
           8 + 1 + (validCov ? 0 : 12);
}
}  // namespace

// The label after the measurements (fuzz_crashes/rawlog/oom_string_2gb_at_merge).
TEST(MrptGuards, BearingRangeLabelIsBounded) {
    registerAllClasses();
    mrpt::obs::CObservationBearingRange o;
    o.sensorLabel = "RB";
    o.sensedData.resize(2);
    o.sensedData[1].landmarkID = 7;  // MRPT refuses to write duplicate IDs
    auto b = serialized(o);
    const size_t at = bearingCountOffset(false) + 4 + 2 * 16;
    ASSERT_EQ(b[at], 2);
    b[at + 3] = 0x7F;
    const auto e = errorOf([&] { readBack(b); });
    EXPECT_NE(e.find("CObservationBearingRange: sensorLabel length 2130706434"),
              std::string::npos)
        << e;
}

TEST(MrptGuards, BearingRangeCovariancesAreChecked) {
    registerAllClasses();
    mrpt::obs::CObservationBearingRange o;
    o.validCovariances = true;
    o.sensorLabel = "RB";
    o.sensedData.resize(2);
    o.sensedData[1].landmarkID = 7;
    o.sensedData[1].covariance(2, 1) = 0.5;
    auto b = serialized(o);
    auto back =
        std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(readBack(b));
    ASSERT_TRUE(back);
    ASSERT_EQ(back->sensedData.size(), 2u);
    EXPECT_EQ(back->sensedData[1].covariance(2, 1), 0.5);
    EXPECT_EQ(serialized(*back), b);
    // The rows of the first covariance: after 16 bytes, the CMatrixD header.
    const size_t rows = bearingCountOffset(true) + 4 + 16 + 1 +
                        std::string("mrpt::math::CMatrixD").size() + 1;
    ASSERT_EQ(b[rows], 3);
    auto big = b;
    big[rows + 3] = 0x7F;
    const auto e = errorOf([&] { readBack(big); });
    EXPECT_NE(e.find("not 3x3"), std::string::npos) << e;
}

TEST(MrptGuards, MrptRFIDCountsAndStringsAreBounded) {
    registerAllClasses();
    mrpt::obs::CObservationRFID o;
    o.sensorLabel = "RFID";
    o.tag_readings.resize(2);
    o.tag_readings[1].epc = "E00401";
    o.tag_readings[1].antennaPort = "1";
    o.tag_readings[1].power = -55;
    auto b = serialized(o);
    auto back = std::dynamic_pointer_cast<mrpt::obs::CObservationRFID>(readBack(b));
    ASSERT_TRUE(back);
    ASSERT_EQ(back->tag_readings.size(), 2u);
    EXPECT_EQ(back->tag_readings[1].epc, "E00401");
    EXPECT_EQ(serialized(*back), b);
    const size_t count = 1 + std::string("mrpt::obs::CObservationRFID").size() + 1;
    ASSERT_EQ(b[count], 2);
    auto many = b;
    many[count + 3] = 0x10;
    const auto e = errorOf([&] { readBack(many); });
    EXPECT_NE(e.find("CObservationRFID: tag count"), std::string::npos) << e;
    // The second EPC's length: after the count, two powers, the first EPC.
    auto epc = b;
    const size_t epc2 = count + 4 + 16 + 4;
    ASSERT_EQ(epc[epc2], 6);
    epc[epc2 + 3] = 0x7F;
    const auto e2 = errorOf([&] { readBack(epc); });
    EXPECT_NE(e2.find("EPC/antenna port length"), std::string::npos) << e2;
}

TEST(MrptGuards, ScanMatchingMovementNeedsAGaussianPdf) {
    registerAllClasses();
    mrpt::obs::CActionRobotMovement2D mv;
    mv.estimationMethod = mrpt::obs::CActionRobotMovement2D::emScan2DMatching;
    mrpt::poses::CPosePDFGaussian g(mrpt::poses::CPose2D(0.1, 0.2, 0.3));
    mv.poseChange = std::make_shared<mrpt::poses::CPosePDFGaussian>(g);
    auto b = serializedMovement(mv);
    auto back = std::dynamic_pointer_cast<mrpt::obs::CActionRobotMovement2D>(readBack(b));
    ASSERT_TRUE(back);
    EXPECT_EQ(serializedMovement(*back), b);
    // The PDF's version byte: after the method and the PDF's class name.
    const size_t ver =
        methodOffset() + 4 + 1 + std::string("mrpt::poses::CPosePDFGaussian").size();
    ASSERT_EQ(b[ver], 2);
    b[ver] = 1;
    const auto e1 = errorOf([&] { readBack(b); });
    EXPECT_NE(e1.find("only a CPosePDFGaussian (version 2)"), std::string::npos) << e1;
    mrpt::poses::CPosePDFParticles p(3);
    mv.poseChange = std::make_shared<mrpt::poses::CPosePDFParticles>(p);
    const auto e = errorOf([&] { readBack(serializedMovement(mv)); });
    EXPECT_NE(e.find("only a CPosePDFGaussian"), std::string::npos) << e;
}

// fuzz_rawlog found MRPT crashing (SIGSEGV) on an action collection whose
// member is a null object: each member must be of the container's kind.
TEST(MrptGuards, ContainerMembersMustBeOfTheirKind) {
    registerAllClasses();
    for (const bool null : {true, false}) {
        auto b = serialized(mrpt::obs::CActionCollection());
        const size_t at = 1 + std::string("mrpt::obs::CActionCollection").size() + 1;
        b[at] = 1;     // one member ...
        b.pop_back();  // ... before the end marker
        const auto member = null ? serialized(mrpt::serialization::CSerializable::Ptr())
                                 : serialized(mrpt::obs::CObservationOdometry());
        b.insert(b.end(), member.begin(), member.end());
        b.push_back(0x88);
        const auto e = errorOf([&] { readBack(b); });
        EXPECT_NE(e.find(null ? "object 0 is nullptr"
                              : "object 0 is a mrpt::obs::CObservationOdometry"),
                  std::string::npos)
            << e;
    }
}
