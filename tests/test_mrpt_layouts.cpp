// Rawlogs in the layouts MRPT's own programs write and read: every action
// collection holds a movement; a layout with an empty first action reads as
// the same; MRPT's observation-only layout and its CObservationRFID give
// rfir-slam the same inputs, hence the same outputs, as the project's layout.
#include <rfir/common/log_convert.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/eval/metrics.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRFID.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

using namespace rfir::common;
using namespace rfir::obs;
using mrpt::obs::CActionCollection;
using mrpt::obs::CObservation;
using mrpt::obs::CSensoryFrame;

namespace {
using rfir_test::TmpDir;
const std::string kData = std::string(RFIR_SOURCE_DIR) + "/datasets/";
const std::string kSlam = std::string(RFIR_BINARY_DIR) + "/bin/rfir-slam";
const std::string kPlugin = std::string(RFIR_BINARY_DIR) + "/lib/librfir_mrpt_plugin.so";

CObservationLogHeader header() {
    CObservationLogHeader h;
    h.readers = {{"R0", 0.1, 0, 0.03, 0.03}};
    h.startPose = exactPose(1, 2, 0.5);
    return h;
}

CObservationRFIDReaders::Ptr rfidObs(const std::string& tag) {
    auto o = CObservationRFIDReaders::Create();
    o->sensorLabel = "RFID";
    o->readings.push_back({header().readers[0], {tag}});
    return o;
}

/** Every object of a rawlog, in file order. */
std::vector<mrpt::serialization::CSerializable::Ptr> objects(const std::string& path) {
    mrpt::io::CFileGZInputStream f(path);
    auto ar = mrpt::serialization::archiveFrom(f);
    std::vector<mrpt::serialization::CSerializable::Ptr> v;
    for (;;) {
        try {
            v.push_back(ar.ReadObject());
        } catch (const std::exception&) {
            return v;  // the end of the file
        }
    }
}

void writeObjects(const std::string& path,
                  const std::vector<const mrpt::serialization::CSerializable*>& objs) {
    mrpt::io::CFileGZOutputStream f(path);
    auto ar = mrpt::serialization::archiveFrom(f);
    for (const auto* o : objs) ar << *o;
}

/** "" if both readers give the same instants (what rfir-slam reads of them). */
std::string compareSteps(CRawlogReader& a, CRawlogReader& b) {
    TRawlogStep sa, sb;
    for (size_t i = 0;; i++) {
        const bool ha = a.next(sa), hb = b.next(sb);
        const std::string at = "instant " + std::to_string(i) + ": ";
        if (ha != hb) return at + "one rawlog ends here";
        if (!ha) return "";
        if (sa.t != sb.t) return at + "times differ";
        if (sa.odometry != sb.odometry) return at + "odometry differs";
        if (sa.odometryIncrement != sb.odometryIncrement) return at + "increments differ";
        if (bool(sa.rfid) != bool(sb.rfid) ||
            (sa.rfid && sa.rfid->readings != sb.rfid->readings))
            return at + "RFID reads differ";
        if (bool(sa.rb) != bool(sb.rb) || (sa.rb && !sameSerialization(*sa.rb, *sb.rb)))
            return at + "range-bearing differs";
    }
}

/** The bundled rawlog rewritten: `convert` maps each instant's observations. */
void rewriteFlat(
    const std::string& in, const std::string& out,
    const std::function<std::vector<CObservation::Ptr>(const TRawlogStep&)>& convert) {
    CRawlogReader r(in);
    mrpt::io::CFileGZOutputStream f(out);
    auto ar = mrpt::serialization::archiveFrom(f);
    ar << r.header();
    TRawlogStep st;
    while (r.next(st))
        for (const auto& o : convert(st)) ar << *o;
}

std::string runSlam(const std::string& rawlog, const std::string& out) {
    const std::string cmd = kSlam + " --rawlog " + rawlog + " --out-dir " + out +
                            " --method ps --seed 4 > " + out + ".log 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream f(out + "/path.tum");
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

TEST(MrptLayouts, EveryActionHoldsAMovement) {
    TmpDir d;
    const auto path = d / "a.rawlog";
    CRawlogWriter w(path, header());
    w.writeStep(1.0, exactPose(0, 0, 0), {rfidObs("T1")});
    w.writeStep(1.5, std::nullopt, {rfidObs("T2")});
    w.writeStep(2.0, exactPose(1, 0.5, 0.3), {});
    w.close();
    const auto objs = objects(path);
    ASSERT_EQ(objs.size(), 8u);
    for (size_t i = 0; i < objs.size(); i += 2) {
        auto acts = std::dynamic_pointer_cast<CActionCollection>(objs[i]);
        ASSERT_TRUE(acts) << i;
        auto mv = acts->getBestMovementEstimation();
        ASSERT_TRUE(mv) << "entry " << i << " has no movement";
        if (i != 6) {
            EXPECT_EQ(mv->rawOdometryIncrementReading, mrpt::poses::CPose2D());
        }
    }
    // The reader: the anchor and the no-odometry instant carry no increment.
    CRawlogReader r(path);
    TRawlogStep st;
    ASSERT_TRUE(r.next(st));
    EXPECT_FALSE(st.odometryIncrement);
    ASSERT_TRUE(r.next(st));
    EXPECT_FALSE(st.odometryIncrement);
    ASSERT_TRUE(r.next(st));
    ASSERT_TRUE(st.odometryIncrement);
    EXPECT_NEAR(st.odometryIncrement->x(), 1, 1e-12);
    EXPECT_NEAR(st.odometryIncrement->phi(), 0.3, 1e-12);
}

TEST(MrptLayouts, OldLayoutReadsAsTheNewOne) {
    // The layout before: empty action collections for the header and for an
    // instant without odometry.
    TmpDir d;
    const auto now = d / "new.rawlog", old = d / "old.rawlog";
    {
        CRawlogWriter w(now, header());
        w.writeStep(1.0, exactPose(0, 0, 0), {rfidObs("T1")});
        w.writeStep(1.5, std::nullopt, {rfidObs("T2")});
        w.writeStep(2.0, exactPose(1, 0.5, 0.3), {rfidObs("T3")});
        w.close();
    }
    auto objs = objects(now);
    ASSERT_EQ(objs.size(), 8u);
    CActionCollection empty;
    std::vector<const mrpt::serialization::CSerializable*> v;
    for (size_t i = 0; i < objs.size(); i++)
        v.push_back((i == 0 || i == 4) ? &empty : objs[i].get());
    writeObjects(old, v);
    CRawlogReader a(now), b(old);
    EXPECT_EQ(compareSteps(a, b), "");
}

TEST(MrptLayouts, ObservationOnlyRawlogGivesTheSameRun) {
    TmpDir d;
    const auto in = kData + "rfid_60mm_16tags_loop.rawlog", flat = d / "flat.rawlog";
    rewriteFlat(in, flat, [](const TRawlogStep& st) {
        return std::vector<CObservation::Ptr>(st.sf->begin(), st.sf->end());
    });
    {
        CRawlogReader a(in), b(flat);
        EXPECT_EQ(a.header().readers, b.header().readers);
        EXPECT_EQ(compareSteps(a, b), "");
    }
    const auto pa = runSlam(in, d / "a"), pb = runSlam(flat, d / "b");
    EXPECT_GT(pa.size(), 1000u);
    EXPECT_EQ(pa, pb);
}

/** One MRPT CObservationRFID per reader reading; the ID is the sensor label. */
std::vector<CObservation::Ptr> asMrptRFID(const TRawlogStep& st) {
    std::vector<CObservation::Ptr> v;
    for (const auto& o : *st.sf) {
        if (o != st.rfid) {
            v.push_back(o);
            continue;
        }
        for (const auto& rd : st.rfid->readings) {
            auto m = mrpt::obs::CObservationRFID::Create();
            m->timestamp = o->timestamp;
            m->sensorLabel = rd.reader.id;
            m->sensorPoseOnRobot = mrpt::poses::CPose3D(rd.reader.x, rd.reader.y, 0);
            for (const auto& t : rd.tags) {
                mrpt::obs::CObservationRFID::TTagReading tr;
                tr.epc = t;
                m->tag_readings.push_back(tr);
            }
            v.push_back(m);
        }
    }
    return v;
}

TEST(MrptLayouts, MrptRFIDObservationsGiveTheSameRun) {
    TmpDir d;
    const auto in = kData + "rfid_60mm_16tags_loop.rawlog", m = d / "mrpt.rawlog";
    rewriteFlat(in, m, asMrptRFID);
    {
        CRawlogReader a(in), b(m);
        EXPECT_EQ(compareSteps(a, b), "");
    }
    EXPECT_EQ(runSlam(in, d / "a"), runSlam(m, d / "b"));
}

TEST(MrptLayouts, MrptRFIDReaderIdsAndGeometry) {
    // <label>.<port> per antenna; geometry from the header, else the pose on
    // the robot with the default area (and a warning).
    TmpDir d;
    const auto path = d / "r.rawlog";
    CObservationLogHeader h;
    h.readers = {{"IMPINJ.1", 0.2, -0.1, 0.05, 0.04}};
    auto o = mrpt::obs::CObservationRFID::Create();
    o->sensorLabel = "IMPINJ";
    o->sensorPoseOnRobot = mrpt::poses::CPose3D(0.3, 0.1, 0);
    for (const auto& [epc, port] : std::vector<std::pair<std::string, std::string>>{
             {"A", "1"}, {"B", "2"}, {"A", "1"}}) {
        mrpt::obs::CObservationRFID::TTagReading tr;
        tr.epc = epc;
        tr.antennaPort = port;
        o->tag_readings.push_back(tr);
    }
    writeObjects(path, {&h, o.get()});
    CRawlogReader r(path);
    TRawlogStep st;
    ASSERT_TRUE(r.next(st));
    ASSERT_TRUE(st.rfid);
    ASSERT_EQ(st.rfid->readings.size(), 2u);
    EXPECT_EQ(st.rfid->readings[0].reader, h.readers[0]);
    EXPECT_EQ(st.rfid->readings[0].tags, std::vector<std::string>{"A"});
    const auto& r2 = st.rfid->readings[1].reader;
    EXPECT_EQ(r2.id, "IMPINJ.2");
    EXPECT_EQ(r2.x, 0.3);
    EXPECT_EQ(r2.y, 0.1);
    EXPECT_EQ(r2.halfX, TRFIDReader().halfX);
    EXPECT_FALSE(r.next(st));
}

std::string slurp(const std::string& f) {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(MrptLayouts, RawlogCutByRawlogEditStartsAtItsFirstOdometry) {
    if (std::system("command -v rawlog-edit > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "rawlog-edit is not installed";
    TmpDir d;
    const auto in = kData + "rfid_60mm_16tags_loop.rawlog", cut = d / "cut.rawlog";
    // Entries 0 and 1 are the header pair: from entry 400 on, the 200th instant.
    // In the sanitizer build MRPT's uninstrumented rawlog-edit needs the
    // sanitizer runtimes loaded first to load the instrumented plugin.
    const char* san = std::getenv("RFIR_SANITIZER_PRELOAD");
    const std::string env = san && *san ? "LD_PRELOAD='" + std::string(san) + "' " : "";
    const std::string edit = env + "rawlog-edit -p " + kPlugin +
                             " --cut --from-index 400 -i " + in + " -o " + cut + " > " +
                             (d / "edit.log") + " 2>&1";
    ASSERT_EQ(std::system(edit.c_str()), 0) << slurp(d / "edit.log");
    CRawlogReader r(cut);
    EXPECT_FALSE(r.hasHeader());
    TRawlogStep st;
    ASSERT_TRUE(r.next(st));
    ASSERT_TRUE(st.odometry);
    const auto first = *st.odometry;
    EXPECT_GT(st.t, 20.0);  // it starts 200 instants (20 s) in

    const std::string gt = kData + "rfid_60mm_16tags_loop.gt.tum", out = d / "o";
    const std::string cmd = kSlam + " --rawlog " + cut + " --gt-path " + gt +
                            " --out-dir " + out + " --method ps --seed 4 > " + out +
                            ".log 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(out + ".log");
    const std::string log = slurp(out + ".log");
    EXPECT_NE(log.find("no rfir log header"), std::string::npos) << log;
    std::ostringstream sp;
    sp << "start pose " << first.x() << " " << first.y() << " " << first.phi()
       << " (the first odometry pose)";
    EXPECT_NE(log.find(sp.str()), std::string::npos) << log;
    EXPECT_NE(log.find("RFID readers from the observations:"), std::string::npos);
    const auto path = loadTUM(out + "/path.tum");
    ASSERT_FALSE(path.empty());
    EXPECT_EQ(path.front().t, st.t);
    // Started where the robot was, the run tracks it: 208 mm (the whole run,
    // from the header's start pose: 158 mm; the odometry from the cut: 267 mm).
    const auto truth = loadTUM(gt);
    const auto e = rfir::eval::computeRobotErrors(path, truth);
    EXPECT_LT(e.stats.mean_dist, 0.3);

    // --start overrides the assumption, and says nothing of it; from (0, 0)
    // the run is off by metres (3.8 m) on this 4 x 4 m floor.
    const std::string cmd2 = kSlam + " --rawlog " + cut + " --start 0 0 0 --out-dir " +
                             out + "2 --method ps --seed 4 > " + out + "2.log 2>&1";
    ASSERT_EQ(std::system(cmd2.c_str()), 0);
    EXPECT_EQ(slurp(out + "2.log").find("assumed"), std::string::npos);
    const auto e2 = rfir::eval::computeRobotErrors(loadTUM(out + "2/path.tum"), truth);
    EXPECT_GT(e2.stats.mean_dist, 1.0);
}

TEST(MrptLayouts, MixedLayoutIsRefused) {
    TmpDir d;
    const auto path = d / "m.rawlog";
    CSensoryFrame sf;
    auto o = mrpt::obs::CObservationOdometry::Create();
    writeObjects(path, {o.get(), &sf});
    CRawlogReader r(path);
    TRawlogStep st;
    try {
        while (r.next(st)) {
        }
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("entry 2"), std::string::npos) << e.what();
    }
}

}  // namespace
