// The rfir-eval program: outputs, rawlog geometry, malformed inputs, MRPT's
// rbpf-slam path.
#include <rfir/common/rawlog_io.h>
#include <rfir/eval/metrics.h>

#include "test_eval_mrpt.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using mrpt::poses::CPose2D;

namespace {
struct TRun {
    int rc = -1;
    std::string out, err;
};

std::string slurp(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

class EvalCli : public ::testing::Test {
  protected:
    fs::path dir;
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("rfir_eval_cli_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string file(const std::string& name, const std::string& text) {
        const auto p = dir / name;
        std::ofstream(p) << text;
        return p.string();
    }
    TRun run(const std::string& args) {
        const std::string cmd = std::string(RFIR_BINARY_DIR) + "/bin/rfir-eval " + args +
                                " > " + (dir / "out").string() + " 2> " +
                                (dir / "err").string();
        const int st = std::system(cmd.c_str());
        TRun r;
        r.rc = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
        r.out = slurp(dir / "out");
        r.err = slurp(dir / "err");
        return r;
    }
};

const char* kGt =
    "# t x y z qx qy qz qw\n"
    "0 0 0 0 0 0 0 1\n"
    "1 1 0 0 0 0 0 1\n"
    "2 2 0 0 0 0 0 1\n";
}  // namespace

TEST_F(EvalCli, HelpExitsZero) {
    const auto r = run("--help");
    EXPECT_EQ(r.rc, 0);
    EXPECT_NE(r.out.find("--gt-path"), std::string::npos);
}

TEST_F(EvalCli, TableAndJson) {
    const auto gt = file("gt.tum", kGt);
    // 30 mm off in y at t = 0 and t = 2, exact at t = 1.5 (interpolated truth).
    const auto est = file("est.tum",
                          "0 0 0.03 0 0 0 0 1\n1.5 1.5 0 0 0 0 0 1\n"
                          "2 2 -0.03 0 0 0 0 1\n");
    const auto gm = file("gt_map.txt", "tag a 0 0\ntag b 1 1\nemitter 39 0 0 2.4\n");
    const auto em = file("map.txt", "tag a 0.03 0.04 0.01 0.01\n");
    const auto png = (dir / "fig.png").string();
    auto r = run("--path " + est + " --gt-path " + gt + " --map " + em + " --gt-map " +
                 gm + " --label PS-SLAM --plot " + png);
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("Robot localization"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("PS-SLAM"), std::string::npos);
    EXPECT_NE(r.out.find("20.0"), std::string::npos) << r.out;  // mean |dy| mm
    EXPECT_NE(r.out.find("50.0"), std::string::npos) << r.out;  // tag distance mm
    EXPECT_NE(r.out.find("\"mean_dy\":0.02,"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"tags_mapped\":1,\"tags_total\":2"), std::string::npos);
    EXPECT_TRUE(fs::exists(png));

    r = run("--path " + est + " --gt-path " + gt + " --json-only");
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_EQ(r.out.rfind("{\"label\":\"estimate\",\"robot\":{", 0), 0u) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1);
}

TEST_F(EvalCli, SegmentsPerTimeWindow) {
    const auto gt = file("gt.tum", kGt);
    // 10 mm off at t = 0 and 1, 40 mm at t = 2: windows [0, 1) and [1, 2].
    const auto est =
        file("est.tum", "0 0 0.01 0 0 0 0 1\n1 1 0.01 0 0 0 0 1\n2 2 0.04 0 0 0 0 1\n");
    auto r = run("--path " + est + " --gt-path " + gt + " --segments 2");
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("time window"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"segments\":{\"t\":[0,1,2],\"robot_mean_dist\":[0.01,0.025]}"),
              std::string::npos)
        << r.out;
    for (const char* bad : {" --segments -1", " --segments x"}) {
        r = run("--path " + est + " --gt-path " + gt + bad);
        EXPECT_NE(r.rc, 0) << bad;
        EXPECT_NE(r.err.find("--segments"), std::string::npos) << r.err;
    }
    r = run("--map " + file("m.txt", "tag a 0 0 0 0\n") + " --gt-map " +
            file("g.txt", "tag a 0 0\n") + " --segments 2");
    EXPECT_EQ(r.rc, 2);  // a command-line error
    EXPECT_NE(r.err.find("--segments needs --path"), std::string::npos) << r.err;
}

TEST_F(EvalCli, MalformedInputsNameFileAndLine) {
    const auto gt = file("gt.tum", kGt);
    const auto bad = file("bad.tum", "0 0 0 0 0 0 0 1\n1 1 zero 0 0 0 0 1\n");
    auto r = run("--path " + bad + " --gt-path " + gt);
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.err.find(bad + ":2:"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;

    const auto est = file("est.tum", "0 0 0 0 0 0 0 1\n");
    const auto gm = file("gt_map.txt", "tag a 0 0\n");
    const auto badMap = file("map.txt", "tag a 0 0\n\ntag b 1\n");
    r = run("--path " + est + " --gt-path " + gt + " --map " + badMap + " --gt-map " +
            gm);
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.err.find(badMap + ":3:"), std::string::npos) << r.err;

    r = run("--path " + (dir / "nope.tum").string() + " --gt-path " + gt);
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.err.find("nope.tum"), std::string::npos) << r.err;

    r = run("--path " + est);  // no ground truth
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.err.find("--gt-path"), std::string::npos) << r.err;

    // An output that cannot be written: error, and no results printed.
    r = run("--path " + est + " --gt-path " + gt + " --plot " +
            (dir / "no/such/dir/f.png").string());
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.err.find("f.png"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;

    // No overlap in time between estimate and truth.
    const auto late = file("late.tum", "9 0 0 0 0 0 0 1\n");
    r = run("--path " + late + " --gt-path " + gt);
    EXPECT_NE(r.rc, 0);
    EXPECT_NE(r.err.find("time span"), std::string::npos) << r.err;
}

TEST_F(EvalCli, RawlogGivesPassedOverAndDeadReckoning) {
    // The robot drives 1 m along x in 0.1 s steps; its odometry over-reads 10 %.
    rfir::obs::CObservationLogHeader hdr;
    hdr.readers.push_back({"R1", 0.1, 0, 0.03, 0.03});
    const auto rawlog = (dir / "run.rawlog").string();
    std::ostringstream gt;
    {
        rfir::common::CRawlogWriter w(rawlog, hdr);
        for (int k = 0; k <= 10; k++) {
            w.writeStep(0.1 * k, CPose2D(0.11 * k, 0, 0), {});
            gt << 0.1 * k << " " << 0.1 * k << " 0 0 0 0 0 1\n";
        }
        w.close();
    }
    const auto gtPath = file("gt.tum", gt.str());
    // Reader 0.1 m ahead: tags on the line x in [0.07, 1.13] are passed over.
    const auto gm = file("gt_map.txt",
                         "tag a 0.5 0.01\ntag b 1.12 0\ntag c 0.5 0.05\n"
                         "tag d 0.05 0\ntag e 3 3\n");
    const auto em = file("map.txt", "tag a 0.5 0.0\ntag e 3 3\n");
    const auto r = run("--path " + gtPath + " --gt-path " + gtPath + " --map " + em +
                       " --gt-map " + gm + " --rawlog " + rawlog + " --json-only");
    ASSERT_EQ(r.rc, 0) << r.err;
    EXPECT_NE(r.out.find("\"tags_passed_over\":2,\"tags_mapped_of_passed_over\":1"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\"tags_mapped\":2,\"tags_total\":5"), std::string::npos)
        << r.out;
    // Dead reckoning: 10 % over-read, final error 0.1 m, mean 0.05 m over 11 poses.
    EXPECT_NE(r.out.find("\"dead_reckoning\":{\"poses\":11"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"max_dist\":0.1"), std::string::npos) << r.out;

    const auto info = rfir::eval::readRawlogInfo(rawlog);
    EXPECT_EQ(info.steps, 11u);
    ASSERT_EQ(info.readers.size(), 1u);
    EXPECT_EQ(info.readers[0].id, "R1");
    ASSERT_EQ(info.odometry.size(), 11u);
    EXPECT_NEAR(info.odometry.back().pose.x(), 1.1, 1e-9);
}

// A file that is not TUM is refused, saying what it looks like; rbpf-slam's
// path is read with --path-format mrpt and the log's start pose (--start, or
// a --run's "mrpt:"), equal to the path it was written from.
TEST_F(EvalCli, MrptPathFormat) {
    const auto truth = rfir_test::curve(150);
    const CPose2D start(2.5, -1.25, 2.6);
    const std::string gt = (dir / "truth.tum").string();
    const std::string est = (dir / "log_estimated_path.txt").string();
    rfir::common::saveTUM(gt, truth);
    rfir_test::writeRbpfSlam(est, truth, start);
    for (const std::string& args :
         {"--path " + est + " --gt-path " + gt, "--path " + gt + " --gt-path " + est,
          "--run rbpf=" + est + " --gt-path " + gt}) {
        const auto r = run(args);
        EXPECT_EQ(r.rc, 1) << args;  // the file's error
        EXPECT_NE(r.err.find(est + ": not a TUM path"), std::string::npos) << r.err;
        EXPECT_NE(
            r.err.find("it looks like MRPT rbpf-slam's log_estimated_path.txt (step "
                       "x y z yaw pitch roll t): use --path-format mrpt"),
            std::string::npos)
            << r.err;
    }
    // Command-line errors: no start pose for rbpf-slam's frame, an unknown format.
    auto r = run("--path " + est + " --gt-path " + gt + " --path-format mrpt");
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find("--start"), std::string::npos) << r.err;
    r = run("--path " + est + " --gt-path " + gt + " --path-format rbpf");
    EXPECT_EQ(r.rc, 2);
    EXPECT_NE(r.err.find("--path-format"), std::string::npos) << r.err;

    const std::string at = " --start 2.5 -1.25 2.6";
    r = run("--path " + est + " --gt-path " + gt + " --path-format mrpt --json-only" +
            at);
    ASSERT_EQ(r.rc, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out).at("robot");
    EXPECT_EQ(j.at("poses"), truth.size());
    EXPECT_LT(j.at("max_dist").get<double>(), 1e-5);  // the file's 6 decimals
    EXPECT_LT(j.at("max_dtheta").get<double>(), 1e-5);
    r = run("--run rbpf-slam=mrpt:" + est + " --run truth=" + gt + " --gt-path " + gt +
            " --json-only" + at);
    ASSERT_EQ(r.rc, 0) << r.err;
    const auto runs = nlohmann::json::parse(r.out).at("runs");
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].at("label"), "rbpf-slam");
    EXPECT_LT(runs[0].at("robot").at("max_dist").get<double>(), 1e-5);
}
