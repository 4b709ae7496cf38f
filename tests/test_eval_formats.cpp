/* rfir_eval's readers of the files it scores: the TUM shape check (a file
 * that is not TUM is refused, saying what it looks like) and what MRPT's
 * rbpf-slam and pf-localization write, each written here in MRPT's own
 * printf layout and read back into the world frame. */
#include <rfir/eval/input_formats.h>

#include "test_eval_mrpt.h"
#include "test_tmpdir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace fs = std::filesystem;
using mrpt::poses::CPose2D;
using rfir::common::TPath2D;
using rfir::eval::InputFormat;

namespace {
using rfir_test::curve;
using rfir_test::writeRbpfSlam;

std::string problemOf(const std::string& f, const std::string& text) {
    std::ofstream(f) << text;
    return rfir::eval::tumShapeProblem(f);
}
}  // namespace

TEST(EvalFormats, TumShapeAndWhatOtherFilesLookLike) {
    rfir_test::TmpDir d;
    EXPECT_EQ(problemOf(d / "a.tum", "# t x y z qx qy qz qw\n1 0 0 0 0 0 0.6 0.8\n"), "");
    writeRbpfSlam(d / "rbpf.txt", curve(20), CPose2D(0.5, 0.5, 0));
    EXPECT_EQ(rfir::eval::tumShapeProblem((d / "rbpf.txt")),
              "it looks like MRPT rbpf-slam's log_estimated_path.txt (step x y z yaw "
              "pitch roll t): use --path-format mrpt");
    EXPECT_NE(problemOf(d / "odo.txt",
                        "% time_step x y z yaw pitch roll\n0\t0\t0\t0\t0\t0\t0\n"
                        "1\t0.1\t0\t0\t0\t0\t0\n")
                  .find("log_odometry_path.txt"),
              std::string::npos);
    EXPECT_NE(problemOf(d / "p.txt", "% x y yaw[rad] log_weight\n1 2 0.1 -1.5\n")
                  .find("particles_NNNNN.txt"),
              std::string::npos);
    EXPECT_NE(problemOf(d / "xyphi.txt", "1 2 0.1\n").find("3 numbers a row"),
              std::string::npos);
    EXPECT_NE(problemOf(d / "m.txt", "tag a 1 2\n").find("give it with --map"),
              std::string::npos);
    EXPECT_NE(problemOf(d / "q.tum", "5 0 0 0 0 0 0.5 0.5\n").find("no unit quaternion"),
              std::string::npos);
    EXPECT_NE(rfir::eval::tumShapeProblem(d.p.string()).find("folder"),
              std::string::npos);
    // Refused whole, naming the file.
    try {
        rfir::eval::loadTumChecked((d / "rbpf.txt"));
        FAIL() << "read as TUM";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind((d / "rbpf.txt") + ": not a TUM path", 0),
                  0u)
            << e.what();
    }
}

// A known path written in rbpf-slam's format with a start pose, read back
// with the start pose: the same path (to the file's 6 decimals).
TEST(EvalFormats, RbpfSlamPathRoundTrip) {
    rfir_test::TmpDir d;
    const TPath2D truth = curve(200);
    const CPose2D start(2.5, -1.25, 2.6);
    writeRbpfSlam(d / "log_estimated_path.txt", truth, start);
    rfir::eval::TMrptFrame frame;
    EXPECT_THROW(
        rfir::eval::loadPath((d / "log_estimated_path.txt"), InputFormat::Mrpt, frame),
        std::runtime_error);  // no start pose
    frame.start = start;
    const TPath2D p =
        rfir::eval::loadPath((d / "log_estimated_path.txt"), InputFormat::Mrpt, frame);
    ASSERT_EQ(p.size(), truth.size());  // the header pair's row folded into the first
    for (size_t i = 0; i < p.size(); i++) {
        EXPECT_NEAR(p[i].t, truth[i].t, 1e-6);
        EXPECT_NEAR(p[i].pose.x(), truth[i].pose.x(), 1e-5) << i;
        EXPECT_NEAR(p[i].pose.y(), truth[i].pose.y(), 1e-5) << i;
        EXPECT_NEAR(rfir::common::wrapToPi(p[i].pose.phi() - truth[i].pose.phi()), 0,
                    1e-5)
            << i;
    }
}

// pf-localization's particle files: the weighted mean of each, at the time
// of its step's instant (step 1 is the first instant after the header pair).
TEST(EvalFormats, PfLocalizationParticles) {
    rfir_test::TmpDir d;
    fs::create_directories(d / "out/particles");
    std::ofstream(d / "out/particles/particles_0_initial.txt") << "9 9 0 0\n";
    // Weights 3:1 (log weights differ by log 3): mean x 0.75.
    std::ofstream(d / "out/particles/particles_00003.txt")
        << "% x  y  yaw[rad] log_weight\n1.000000 2.000000 0.100000 "
        << std::setprecision(17) << std::log(3.0) - 50
        << "\n0.000000 2.000000 -0.300000 -50\n";
    std::ofstream(d / "out/particles/particles_00001.txt") << "5 6 0.5 -1\n";
    rfir::eval::TMrptFrame frame;
    frame.instantTimes = {10, 10.5, 11, 11.5};
    frame.firstInstantStep = 1;
    const TPath2D p = rfir::eval::loadPath((d / "out"), InputFormat::Mrpt, frame);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_DOUBLE_EQ(p[0].t, 10);  // step 1: instant 0
    EXPECT_NEAR(p[0].pose.x(), 5, 1e-12);
    EXPECT_DOUBLE_EQ(p[1].t, 11);  // step 3: instant 2
    EXPECT_NEAR(p[1].pose.x(), 0.75, 1e-12);
    EXPECT_NEAR(p[1].pose.y(), 2, 1e-12);
    EXPECT_NEAR(p[1].pose.phi(),
                std::atan2(3 * std::sin(0.1) + std::sin(-0.3),
                           3 * std::cos(0.1) + std::cos(-0.3)),
                1e-12);
    frame.instantTimes.resize(2);  // step 3 is no instant of a shorter rawlog
    EXPECT_THROW(rfir::eval::loadPath((d / "out"), InputFormat::Mrpt, frame),
                 std::runtime_error);
}

// The maps rbpf-slam saves, from the origin, composed with the start pose.
TEST(EvalFormats, MrptMapsInTheWorldFrame) {
    rfir_test::TmpDir d;
    const CPose2D start(1, 2, M_PI / 2);
    rfir::eval::TMrptFrame frame;
    frame.start = start;
    // CBeaconMap::saveToTextFile: "%i %f %f %f %e %e %e %e %e %e %e %e".
    FILE* o = std::fopen((d / "covs.txt").c_str(), "w");
    std::fprintf(o, "%i %f %f %f %e %e %e %e %e %e %e %e\n", 7, 1.0, 0.0, 0.0, 0.04, 0.01,
                 0.0, 4e-4, 0.0, 0.0, 0.0, 0.0);
    std::fclose(o);
    auto m = rfir::eval::loadMap((d / "covs.txt"), InputFormat::Mrpt, frame);
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].kind, rfir::common::TMapEntry::Kind::Landmark);
    EXPECT_EQ(m[0].id, "7");
    EXPECT_NEAR(m[0].x, 1, 1e-9);  // (1, 0) turned by 90 degrees, moved by (1, 2)
    EXPECT_NEAR(m[0].y, 3, 1e-9);
    EXPECT_NEAR(*m[0].sx, 0.1, 1e-9);  // the variances swap with the axes
    EXPECT_NEAR(*m[0].sy, 0.2, 1e-9);
    // CLandmarksMap::saveToTextFile: "%10f %10f %10f %4i %4u %10f", " %i ".
    o = std::fopen((d / "landmarks.txt").c_str(), "w");
    std::fprintf(o, "%10f %10f %10f %4i %4u %10f %i \n", 0.0, 1.0, 0.0, 3, 5u, 0.0, 12);
    std::fclose(o);
    m = rfir::eval::loadMap((d / "landmarks.txt"), InputFormat::Mrpt, frame);
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].id, "12");
    EXPECT_NEAR(m[0].x, 0, 1e-9);
    EXPECT_NEAR(m[0].y, 2, 1e-9);
    // rfir's tag map inside rbpf-slam writes rfir's records.
    std::ofstream(d / "tags.txt") << "# rfir tag map\ntag A 1 0 0.01 0.02 3 0\n";
    m = rfir::eval::loadMap((d / "tags.txt"), InputFormat::Mrpt, frame);
    ASSERT_EQ(m.size(), 1u);
    EXPECT_EQ(m[0].kind, rfir::common::TMapEntry::Kind::Tag);
    EXPECT_NEAR(m[0].y, 3, 1e-9);
    EXPECT_EQ(m[0].reads, 3u);
    // The same file as rfir's own map: not moved.
    EXPECT_NEAR(rfir::eval::loadMap((d / "tags.txt"), InputFormat::Rfir, {})[0].y, 0,
                1e-12);
    std::ofstream(d / "bad.txt") << "1 2 3\n";
    try {
        rfir::eval::loadMap((d / "bad.txt"), InputFormat::Mrpt, frame);
        FAIL() << "read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.txt:1: not a map MRPT's apps save"),
                  std::string::npos)
            << e.what();
    }
}
