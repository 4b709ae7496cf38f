// CRawlogWriter / CRawlogReader: the project's rawlog layout written and read
// back, and every way a rawlog can be broken reported with the file's name.
#include <rfir/common/log_convert.h>
#include <rfir/common/rawlog_io.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace rfir::common;
using namespace rfir::obs;

// A class the rawlog can hold but that nobody registers with MRPT.
namespace rfir_test {
class CUnregisteredObs : public mrpt::obs::CObservation {
    DEFINE_SERIALIZABLE(CUnregisteredObs, rfir_test)
  public:
    void getSensorPose(mrpt::poses::CPose3D& p) const override { p = {}; }
    void setSensorPose(const mrpt::poses::CPose3D&) override {}
    using mrpt::obs::CObservation::getSensorPose;
    using mrpt::obs::CObservation::setSensorPose;
};
}  // namespace rfir_test
IMPLEMENTS_SERIALIZABLE(CUnregisteredObs, mrpt::obs::CObservation, rfir_test)
uint8_t rfir_test::CUnregisteredObs::serializeGetVersion() const {
    return 0;
}
void rfir_test::CUnregisteredObs::serializeTo(mrpt::serialization::CArchive& o) const {
    o << timestamp << sensorLabel;
}
void rfir_test::CUnregisteredObs::serializeFrom(mrpt::serialization::CArchive& i,
                                                uint8_t) {
    i >> timestamp >> sensorLabel;
}

namespace {
using rfir_test::TmpDir;

CObservationLogHeader header() {
    CObservationLogHeader h;
    h.readers = {{"R0", 0.1, 0, 0.03, 0.03}};
    h.receivers = {{"left", 0, 0.2, 0.3}};
    h.startPose = exactPose(1, 2, 0.5);
    return h;
}

CObservationRFIDReaders::Ptr rfidObs(const std::string& tag) {
    auto o = CObservationRFIDReaders::Create();
    o->sensorLabel = "RFID";
    o->readings.push_back({header().readers[0], {tag}});
    return o;
}

void writeSteps(const std::string& path, size_t n) {
    CRawlogWriter w(path, header());
    for (size_t i = 0; i < n; i++) {
        auto ir = CObservationIRSignals::Create();
        ir->sensorLabel = "IR";
        CObservationIRSignals::TReading rd;
        rd.receiver = header().receivers[0];
        rd.rateHz = 8000;
        rd.raw.assign(256, float(i));
        ir->readings.push_back(rd);
        w.writeStep(0.1 * i, exactPose(0.01 * i, 0, 0),
                    {rfidObs("T" + std::to_string(i)), ir});
    }
    w.close();
}

std::string readAllError(const std::string& path) {
    try {
        CRawlogReader r(path);
        TRawlogStep st;
        while (r.next(st)) {
        }
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(RawlogIO, WriterReaderPair) {
    TmpDir d;
    const auto path = d / "a.rawlog";
    {
        CRawlogWriter w(path, header());
        w.writeStep(1.0, exactPose(0, 0, 0), {rfidObs("T1")});
        w.writeStep(1.5, std::nullopt, {rfidObs("T2")});
        w.writeStep(2.0, exactPose(1, 0.5, 0.3), {});
        EXPECT_FALSE(fs::exists(path));  // only the temporary file so far
        w.close();
        EXPECT_EQ(w.stepsWritten(), 3u);
    }
    EXPECT_EQ(d.count(), 1u);  // no temporary file left
    CRawlogReader r(path);
    EXPECT_EQ(r.header().readers, header().readers);
    EXPECT_EQ(r.header().receivers, header().receivers);
    EXPECT_EQ(r.header().sensorLabel, "HEADER");
    EXPECT_EQ(r.header().startPose->phi(), 0.5);
    TRawlogStep st;
    ASSERT_TRUE(r.next(st));
    EXPECT_EQ(st.index, 0u);
    EXPECT_EQ(st.t, 1.0);
    ASSERT_TRUE(st.odometry && st.rfid);
    // The first odometry record anchors the frame: no increment (a filter
    // would draw motion noise for a zero one).
    EXPECT_FALSE(st.odometryIncrement);
    EXPECT_EQ(st.rfid->readings[0].tags, std::vector<std::string>{"T1"});
    EXPECT_EQ(st.rfid->timestamp, mrpt::Clock::fromDouble(1.0));
    ASSERT_TRUE(r.next(st));
    EXPECT_EQ(st.t, 1.5);
    EXPECT_FALSE(st.odometry);
    EXPECT_FALSE(st.odometryIncrement);  // no odom: empty action
    ASSERT_TRUE(r.next(st));
    EXPECT_EQ(st.t, 2.0);
    ASSERT_TRUE(st.odometryIncrement);
    EXPECT_NEAR(st.odometryIncrement->x(), 1, 1e-12);
    EXPECT_NEAR(st.odometryIncrement->phi(), 0.3, 1e-12);
    EXPECT_FALSE(st.rfid);
    EXPECT_FALSE(r.next(st));
    EXPECT_FALSE(r.next(st));
}

TEST(RawlogIO, UnclosedWriterLeavesNothing) {
    TmpDir d;
    {
        CRawlogWriter w(d / "b.rawlog", header());
        w.writeStep(0, exactPose(0, 0, 0), {});
    }
    EXPECT_EQ(d.count(), 0u);
}

TEST(RawlogIO, WriterToMissingFolderNamesTheFile) {
    try {
        CRawlogWriter w("/nonexistent_dir/x.rawlog", header());
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent_dir/x.rawlog"),
                  std::string::npos);
    }
}

TEST(RawlogIO, TruncatedRawlogThrowsNamingTheFile) {
    TmpDir d;
    const auto path = d / "c.rawlog";
    writeSteps(path, 300);
    EXPECT_EQ(readAllError(path), "");
    const auto size = fs::file_size(path);
    for (double frac : {0.5, 0.9, 0.999}) {
        fs::copy_file(path, d / "cut.rawlog", fs::copy_options::overwrite_existing);
        fs::resize_file(d / "cut.rawlog", uintmax_t(size * frac));
        const auto err = readAllError(d / "cut.rawlog");
        EXPECT_NE(err.find(d / "cut.rawlog"), std::string::npos) << frac << ": " << err;
    }
    fs::resize_file(d / "cut.rawlog", 10);
    EXPECT_NE(readAllError(d / "cut.rawlog").find("cut.rawlog"), std::string::npos);
}

TEST(RawlogIO, CorruptObjectThrowsNamingTheFileAndEntry) {
    TmpDir d;
    const auto path = d / "d.rawlog";
    {
        mrpt::io::CFileGZOutputStream f(path);
        auto ar = mrpt::serialization::archiveFrom(f);
        mrpt::obs::CActionCollection acts;
        mrpt::obs::CSensoryFrame sf;
        sf.insert(std::make_shared<CObservationLogHeader>(header()));
        ar << acts << sf;
        const char junk[] = "this is not an MRPT object at all, just bytes";
        f.Write(junk, sizeof(junk));
    }
    const auto err = readAllError(path);
    EXPECT_NE(err.find(path + ": entry 3"), std::string::npos) << err;
}

TEST(RawlogIO, UnregisteredClassIsAnErrorNotAnEnd) {
    TmpDir d;
    const auto path = d / "e.rawlog";
    {
        CRawlogWriter w(path, header());
        w.writeStep(0, exactPose(0, 0, 0), {rfidObs("T1")});
        w.writeStep(1, exactPose(0, 0, 0),
                    {std::make_shared<rfir_test::CUnregisteredObs>()});
        w.writeStep(2, exactPose(0, 0, 0), {rfidObs("T3")});
        w.close();
    }
    CRawlogReader r(path);
    TRawlogStep st;
    ASSERT_TRUE(r.next(st));
    try {
        r.next(st);
        FAIL() << "an unregistered class was read as the end of the file";
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(path + ": entry"), std::string::npos) << m;
        EXPECT_NE(m.find("CUnregisteredObs"), std::string::npos) << m;
    }
}

namespace {
/** A rawlog as another program may write it: no header, one instant with an
 * odometry record and, optionally, a movement. */
void writeOdometryOnly(const std::string& path, double t, const mrpt::poses::CPose2D& odo,
                       std::optional<mrpt::poses::CPose2D> movement = std::nullopt) {
    mrpt::io::CFileGZOutputStream f(path);
    auto ar = mrpt::serialization::archiveFrom(f);
    mrpt::obs::CActionCollection acts;
    if (movement) {
        mrpt::obs::CActionRobotMovement2D mv;
        mv.computeFromOdometry(*movement, {});
        acts.insert(mv);
    }
    mrpt::obs::CSensoryFrame sf;
    auto od = mrpt::obs::CObservationOdometry::Create();
    od->timestamp = mrpt::Clock::fromDouble(t);
    od->odometry = odo;
    sf.insert(od);
    ar << acts << sf;
}
}  // namespace

TEST(RawlogIO, RawlogWithoutHeaderIsReadWithAnEmptyHeader) {
    TmpDir d;
    const auto path = d / "f.rawlog";
    writeOdometryOnly(path, 3, exactPose(1, 2, 3));
    CRawlogReader r(path);
    EXPECT_TRUE(r.header().readers.empty());
    TRawlogStep st;
    ASSERT_TRUE(r.next(st));
    ASSERT_TRUE(st.odometry);
    EXPECT_EQ(st.odometry->phi(), 3);
    EXPECT_EQ(st.t, 3);
    EXPECT_FALSE(r.next(st));
}

TEST(RawlogIO, FirstMovementKeptUnlessZero) {
    // Another program's rawlog: the first odometry record comes with a real
    // movement, which the reader keeps (only the writer's zero anchor goes).
    TmpDir d;
    const auto path = d / "m.rawlog";
    writeOdometryOnly(path, 3, exactPose(1, 2, 0), mrpt::poses::CPose2D(0.1, 0, 0));
    CRawlogReader r(path);
    TRawlogStep st;
    ASSERT_TRUE(r.next(st));
    ASSERT_TRUE(st.odometryIncrement);
    EXPECT_EQ(st.odometryIncrement->x(), 0.1);
}

TEST(RawlogIO, NotARawlogIsRejected) {
    TmpDir d;
    std::ofstream(d / "g.rawlog") << "format textlog 1\n";
    EXPECT_NE(readAllError(d / "g.rawlog").find("g.rawlog"), std::string::npos);
    EXPECT_NE(readAllError(d / "missing.rawlog").find("missing.rawlog"),
              std::string::npos);
}

}  // namespace
