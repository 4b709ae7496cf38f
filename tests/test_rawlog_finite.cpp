// A NaN or infinity in a rawlog is corrupt data: the reader refuses it,
// naming the file, the instant or class, and the field, instead of handing
// it to the filters (which carried it silently: a NaN movement read as "not
// moved", since MRPT's best-movement choice skips it).
#include <rfir/common/rawlog_io.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace {
using rfir_test::TmpDir;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string errorReading(const std::string& p) {
    try {
        rfir::common::CRawlogReader r(p);
        rfir::common::TRawlogStep st;
        while (r.next(st)) {
        }
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

/** Two steps; the second's odometry and RFID reader are given. */
std::string rawlog(const TmpDir& d, const mrpt::poses::CPose2D& odom, double readerX,
                   double startX = 0) {
    const std::string p = d / "f.rawlog";
    rfir::obs::CObservationLogHeader h;
    h.startPose = mrpt::poses::CPose2D(startX, 0, 0);
    rfir::common::CRawlogWriter w(p, h);
    w.writeStep(1.0, mrpt::poses::CPose2D(0, 0, 0), {});
    auto r = rfir::obs::CObservationRFIDReaders::Create();
    r->readings.push_back({});
    r->readings.back().reader.id = "R1";
    r->readings.back().reader.x = readerX;
    w.writeStep(2.0, odom, {r});
    w.close();
    return p;
}
}  // namespace

TEST(RawlogFinite, FiniteValuesRead) {
    TmpDir d;
    EXPECT_EQ(errorReading(rawlog(d, mrpt::poses::CPose2D(0.1, 0, 0), 0.05)), "");
}

TEST(RawlogFinite, NanOdometryIsRefusedNamingTheInstant) {
    TmpDir d;
    const auto p = rawlog(d, mrpt::poses::CPose2D(kNaN, 0, 0), 0.05);
    const auto e = errorReading(p);
    EXPECT_NE(e.find(p + ": instant 2: odometry: x y phi not finite"), std::string::npos)
        << e;
}

TEST(RawlogFinite, NanInTheProjectsClassesIsRefusedByField) {
    TmpDir d;
    auto e = errorReading(rawlog(d, mrpt::poses::CPose2D(0.1, 0, 0), INFINITY));
    EXPECT_NE(e.find("CObservationRFIDReaders: reader x y halfX halfY not finite"),
              std::string::npos)
        << e;
    e = errorReading(rawlog(d, mrpt::poses::CPose2D(0.1, 0, 0), 0.05, kNaN));
    EXPECT_NE(e.find("CObservationLogHeader: start pose not finite"), std::string::npos)
        << e;
}
