// The README's demo (scripts/demo_run.sh) on its bundled loop dataset, seed
// 1: the bar it is there to show. PF-SLAM and PS-SLAM at least 30 % below the
// odometry's mean robot error, the smoothed run below both.
#include <rfir/eval/scene3d.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "test_tmpdir.h"

namespace {
std::string slurp(const std::string& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/** "robot" mean_dist of the row labelled `label` in demo.json. */
double robotMean(const std::string& j, const std::string& label) {
    const auto a = j.find("{\"label\":\"" + label + "\",\"robot\":{");
    if (a == std::string::npos) throw std::runtime_error("no row " + label + " in " + j);
    const std::string key = "\"mean_dist\":";
    const auto b = j.find(key, a);
    return std::stod(j.substr(b + key.size()));
}
}  // namespace

TEST(DemoBar, SlamBeatsOdometryOnTheLoop) {
    rfir_test::TmpDir d;
    const std::string cmd = "bash " + std::string(RFIR_SOURCE_DIR) +
                            "/scripts/demo_run.sh " + d.p.string() + " " +
                            RFIR_BINARY_DIR + "/bin > " + (d / "out") + " 2>&1";
    const int st = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << slurp(d / "out");
    const std::string j = slurp(d / "demo.json");
    const double odo = robotMean(j, "odometry"), pf = robotMean(j, "PF-SLAM"),
                 ps = robotMean(j, "PS-SLAM"), fs = robotMean(j, "FastSLAM"),
                 sm = robotMean(j, "PS-SLAM smoothed");
    std::cout << "mean robot error [mm]: odometry " << 1e3 * odo << ", PF " << 1e3 * pf
              << ", PS " << 1e3 * ps << ", FastSLAM " << 1e3 * fs << ", PS smoothed "
              << 1e3 * sm << "\n";
    EXPECT_LE(pf, 0.7 * odo);
    EXPECT_LE(ps, 0.7 * odo);
    EXPECT_LT(sm, pf);
    EXPECT_LT(sm, ps);
    EXPECT_LT(fs, odo);
    // What the README shows: one table, one picture of every path.
    const std::string table = slurp(d / "demo_table.txt");
    for (const char* row : {"odometry", "PF-SLAM", "PS-SLAM", "FastSLAM",
                            "PS-SLAM smoothed", "al. rmse dr", "Tag localization"})
        EXPECT_NE(table.find(row), std::string::npos) << row << " not in\n" << table;
    EXPECT_GT(slurp(d / "demo_paths.png").size(), 10000u);
    EXPECT_GT(slurp(d / "demo_error_time.png").size(), 10000u);
    // rfir-slam's own figures and 3D scene, one tag ellipse per mapped tag.
    EXPECT_GT(slurp(d / "ps/error_time.png").size(), 10000u);
    mrpt::opengl::COpenGLScene scene;
    mrpt::io::CFileGZInputStream in(d / "ps/scene.3Dscene");
    mrpt::serialization::archiveFrom(in) >> scene;
    auto tags = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(
        scene.getByName(rfir::eval::scene_names::kEstTags));
    ASSERT_TRUE(tags);
    std::istringstream map(slurp(d / "ps/map.txt"));
    size_t n = 0;
    for (std::string line; std::getline(map, line);) n += line.rfind("tag ", 0) == 0;
    EXPECT_EQ(tags->size(), n);
    EXPECT_GT(n, 50u);
    EXPECT_TRUE(scene.getByName(rfir::eval::scene_names::kReaders));
    EXPECT_TRUE(scene.getByName(rfir::eval::scene_names::kGtPath));
}
