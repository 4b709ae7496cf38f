/* rfir-slam end to end: a short simulated rawlog through the program, every
 * output written, ground truth found beside the rawlog; bad settings refused
 * with the INI key named. */
#include "test_slam_sim.h"
#include "test_tmpdir.h"

#include <rfir/common/trajectory_io.h>
#include <rfir/sim/simulator.h>

#include <gtest/gtest.h>
#include <mrpt/system/filesystem.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {
const std::string kExe = std::string(RFIR_BINARY_DIR) + "/bin/rfir-slam";

struct TRun {
    int code;
    std::string out;
};
TRun run(const std::string& args) {
    const std::string cmd = kExe + " " + args + " 2>&1";
    FILE* p = ::popen(cmd.c_str(), "r");
    std::string out;
    char buf[4096];
    while (p && std::fgets(buf, sizeof buf, p)) out += buf;
    const int st = p ? ::pclose(p) : -1;
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}
std::string slurp(const std::string& f) {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
/** The 30 s run every test uses, simulated once per process. */
const rfir::sim::TSimOutput& simulated() {
    static const rfir::sim::TSimOutput out = [] {
        auto cfg = rfir::sim::TSimConfig();
        cfg.maxDuration = 30;
        return rfir::sim::simulate(cfg, 2);
    }();
    return out;
}
/** The simulated run's files, in a folder removed when the process exits. */
std::string dataDir() {
    static const rfir_test::TmpDir tmp;
    static const std::string dir = [] {
        const std::string d = tmp.p.string();
        rfir::sim::writeOutputs(simulated(), d, "run");
        return d;
    }();
    return dir;
}
}  // namespace

TEST(SlamApp, WritesEveryOutput) {
    ASSERT_TRUE(mrpt::system::fileExists(kExe)) << kExe;
    const std::string d = dataDir(), out = d + "/out_pf";
    const auto r = run("--rawlog " + d + "/run.rawlog --out-dir " + out + " --seed 3");
    ASSERT_EQ(r.code, 0) << r.out;
    for (const char* f : {"path.tum", "map.txt", "settings.ini", "stats.json",
                          "path_map.png", "errors.json"})
        EXPECT_TRUE(mrpt::system::fileExists(out + "/" + f)) << f;
    EXPECT_NE(r.out.find("Robot localization"), std::string::npos) << r.out;
    EXPECT_EQ(nlohmann::json::parse(slurp(out + "/stats.json")).at("steps"), 301);
    EXPECT_NE(slurp(out + "/settings.ini").find("robot_update"), std::string::npos);
    // Each key line has its meaning and unit as a comment above it.
    EXPECT_NE(slurp(out + "/settings.ini").find("[particles]\nrobot_particles = "),
              std::string::npos);
    EXPECT_NE(slurp(out + "/map.txt").find("\ntag "), std::string::npos);  // tag lines
    // The effective settings reproduce the run exactly.
    const std::string out2 = d + "/out_again";
    const auto r2 = run("--rawlog " + d + "/run.rawlog --out-dir " + out2 +
                        " --seed 3 --config " + out + "/settings.ini");
    ASSERT_EQ(r2.code, 0) << r2.out;
    EXPECT_EQ(slurp(out + "/path.tum"), slurp(out2 + "/path.tum"));
}

// --help-keys: the keys of the configuration with --set applied, each with
// its meaning; nothing read or written, a bad edit a command-line error.
TEST(SlamApp, HelpKeysListsTheConfiguration) {
    const auto r = run("--help-keys --method ps --set slam.robot_particles=200");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("[slam]\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("robot_particles = 200\n    robot particles M"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\nmethod = ps\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nlag = "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("(no description)"), std::string::npos) << r.out;
    const auto bad = run("--help-keys --set slam.nosuch=1");
    EXPECT_EQ(bad.code, 2) << bad.out;
    EXPECT_NE(bad.out.find("slam.nosuch"), std::string::npos) << bad.out;
}

// The program on the simulator's rawlog gives the run of the in-memory
// simulation (what rfir-experiments scores), pose for pose: the rawlog adds
// nothing, e.g. no motion noise drawn for the first odometry record.
TEST(SlamApp, TheRawlogRunIsTheInMemoryRun) {
    const std::string d = dataDir(), out = d + "/out_same";
    const auto& sim = simulated();
    for (const char* m : {"pf", "ps"}) {
        const std::string ini =
            std::string(RFIR_SOURCE_DIR) + "/config_ini/slam_" + m + ".ini";
        const auto r = run("--rawlog " + d + "/run.rawlog --out-dir " + out +
                           " --seed 5 --method " + m + " --config " + ini);
        ASSERT_EQ(r.code, 0) << r.out;
        const auto file = rfir::common::loadTUM(out + "/path.tum");
        auto cfg = slam_test::stockConfig(m);
        cfg.seed = 5;
        mrpt::random::getRandomGenerator().randomize(5);
        auto engine = rfir::slam::makeEngine(cfg, sim.header);
        const auto mem = rfir::slam::runEngine(*engine, *sim.header.startPose,
                                               slam_test::toInputs(sim));
        ASSERT_EQ(file.size(), mem.path.size()) << m;
        for (size_t i = 0; i < file.size(); i++) {
            ASSERT_NEAR(file[i].pose.x(), mem.path[i].second.x(), 1e-6)
                << m << " pose " << i;
            ASSERT_NEAR(file[i].pose.y(), mem.path[i].second.y(), 1e-6)
                << m << " pose " << i;
        }
    }
}

TEST(SlamApp, EveryMethodWithItsStockIni) {
    const std::string d = dataDir();
    for (const char* m : {"ps", "fastslam", "odometry"}) {
        const auto r = run("--rawlog " + d + "/run.rawlog --out-dir " + d + "/out_" + m +
                           " --method " + m + " --start 0.5 0.5 0");
        EXPECT_EQ(r.code, 0) << m << ": " << r.out;
        EXPECT_EQ(
            nlohmann::json::parse(slurp(d + "/out_" + m + "/stats.json")).at("method"),
            m);
    }
}

// The command-line conventions (rfir/common/cli.h) on a real run: --start as
// one quoted argument is the same start; --set edits the INI (settings.ini
// shows it); --config finds a stock INI by name; -q prints nothing.
TEST(SlamApp, CommandLineConventions) {
    const std::string d = dataDir(), in = " --rawlog " + d + "/run.rawlog --method pf";
    auto r = run(in + " --out-dir " + d + "/c1 --start 0.5 0.5 0");
    ASSERT_EQ(r.code, 0) << r.out;
    r = run(in + " --out-dir " + d + "/c2 --start '0.5 0.5 0' --config slam_pf -q" +
            " --set slam.robot_particles=50 --set motion.a1=0.03");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out.find("rfir-slam:"), std::string::npos) << r.out;
    const std::string settings = slurp(d + "/c2/settings.ini");
    const size_t k = settings.find("robot_particles");
    ASSERT_NE(k, std::string::npos) << settings;
    const std::string line = settings.substr(k, settings.find('\n', k) - k);
    std::istringstream value(line.substr(line.find('=') + 1));
    int particles = 0;
    value >> particles;
    EXPECT_EQ(particles, 50) << line;
    // Same start, other settings: the first pose is the same.
    const auto p1 = rfir::common::loadTUM(d + "/c1/path.tum");
    const auto p2 = rfir::common::loadTUM(d + "/c2/path.tum");
    ASSERT_FALSE(p1.empty());
    ASSERT_FALSE(p2.empty());
    EXPECT_NEAR(p1.front().pose.x(), p2.front().pose.x(), 0.05);
    EXPECT_NEAR(p1.front().pose.y(), p2.front().pose.y(), 0.05);
    r = run(in + " --out-dir " + d + "/c3 --set slam.no_such_key=1");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.out.find("no_such_key"), std::string::npos) << r.out;
    EXPECT_FALSE(mrpt::system::directoryExists(d + "/c3"));
}

TEST(SlamApp, BadSettingsAreRefused) {
    const std::string d = dataDir(), ini = d + "/bad.ini";
    std::string text = slurp(std::string(RFIR_SOURCE_DIR) + "/config_ini/slam_pf.ini");
    text.replace(text.find("robot_particles = 500"), 21, "robot_particles = 0");
    std::ofstream(ini) << text;
    auto r = run("--rawlog " + d + "/run.rawlog --out-dir " + d + "/o1 --config " + ini);
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.out.find("robot_particles"), std::string::npos) << r.out;
    r = run("--rawlog " + d + "/run.rawlog --out-dir " + d + "/o2 --method slam9");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.out.find("method"), std::string::npos) << r.out;
    r = run("--rawlog " + d + "/missing.rawlog --out-dir " + d + "/o3");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.out.find("missing.rawlog"), std::string::npos) << r.out;
    r = run("--rawlog " + d + "/run.rawlog --out-dir " + d + "/o4 --start 1 2");
    EXPECT_NE(r.code, 0);
    EXPECT_FALSE(mrpt::system::directoryExists(d + "/o1"));
}

// --smooth: the smoothed outputs beside the filter's, one more table row; a
// range-bearing rawlog is refused with a message (the smoother is RFID only).
TEST(SlamApp, SmoothWritesItsOutputs) {
    const std::string d = dataDir(), out = d + "/out_smooth";
    const auto r = run("--rawlog " + d + "/run.rawlog --out-dir " + out + " --smooth");
    ASSERT_EQ(r.code, 0) << r.out;
    for (const char* f : {"path.tum", "path_smoothed.tum", "map_smoothed.txt",
                          "path_map_smoothed.png", "errors_smoothed.json"})
        EXPECT_TRUE(mrpt::system::fileExists(out + "/" + f)) << f;
    EXPECT_NE(r.out.find("pf smoothed"), std::string::npos) << r.out;
    EXPECT_NE(slurp(out + "/map_smoothed.txt").find("tag "), std::string::npos);
    // The smoother's odometry bias and kidnap cuts: console and stats.json.
    EXPECT_NE(r.out.find("odometry systematic error"), std::string::npos) << r.out;
    const auto st = nlohmann::json::parse(slurp(out + "/stats.json"));
    ASSERT_TRUE(st.contains("smoother")) << st;
    EXPECT_EQ(st["smoother"].value("solver", ""), "ceres") << st;
    EXPECT_TRUE(st["smoother"].at("heading_drift_rad_per_m").is_number()) << st;
    EXPECT_TRUE(st["smoother"].at("odometry_cut_times_s").is_array()) << st;

    const std::string rb = d + "/rb";
    mrpt::system::createDirectory(rb);
    auto cfg = rfir::sim::TSimConfig();
    cfg.maxDuration = 10;
    cfg.rfid.enabled = false;
    cfg.rb.enabled = true;
    rfir::sim::writeOutputs(rfir::sim::simulate(cfg, 2), rb, "run");
    const auto r2 = run("--rawlog " + rb + "/run.rawlog --out-dir " + rb + "/o --smooth");
    EXPECT_NE(r2.code, 0) << r2.out;
    EXPECT_NE(r2.out.find("range-bearing"), std::string::npos) << r2.out;
    EXPECT_FALSE(mrpt::system::fileExists(rb + "/o/path.tum"));  // refused up front
}

// Outputs belong to one run (issue 15 item 3): a run without --smooth into the
// folder of a --smooth run leaves no *_smoothed* file; stats.json names the
// run and its files; a failing run leaves the earlier set as it was; a folder
// holding files rfir-slam does not write is refused before anything runs.
TEST(SlamApp, OutputsBelongToOneRun) {
    const std::string d = dataDir(), out = d + "/out_sets";
    auto r = run("--rawlog " + d + "/run.rawlog --out-dir " + out + " --smooth --seed 1");
    ASSERT_EQ(r.code, 0) << r.out;
    ASSERT_TRUE(mrpt::system::fileExists(out + "/path_smoothed.tum"));
    r = run("--rawlog " + d + "/run.rawlog --out-dir " + out + " --seed 2");
    ASSERT_EQ(r.code, 0) << r.out;
    for (const char* f : {"path_smoothed.tum", "map_smoothed.txt",
                          "path_map_smoothed.png", "errors_smoothed.json"})
        EXPECT_FALSE(mrpt::system::fileExists(out + "/" + f)) << f;
    const std::string stats = slurp(out + "/stats.json");
    const auto sj = nlohmann::json::parse(stats);
    EXPECT_EQ(sj.at("seed"), 2) << stats;
    EXPECT_FALSE(sj.contains("smoother")) << stats;  // not smoothed
    const auto& id = sj.at("run");
    EXPECT_EQ(id.at("seed"), 2) << stats;
    EXPECT_EQ(id.at("ini_md5").get<std::string>().size(), 32u) << stats;
    EXPECT_NE(id.at("command").get<std::string>().find("--seed 2"), std::string::npos)
        << stats;
    EXPECT_EQ(id.at("files"), nlohmann::json({"error_time.png", "errors.json", "map.txt",
                                              "path.tum", "path_map.png", "scene.3Dscene",
                                              "settings.ini", "stats.json"}))
        << stats;
    EXPECT_NE(
        slurp(out + "/settings.ini").find("# files: error_time.png errors.json map.txt"),
        std::string::npos);

    // A failing run (bad INI value) leaves the seed-2 set byte for byte.
    const std::string before = slurp(out + "/path.tum");
    const std::string bad = d + "/bad_motion.ini";
    std::ofstream(bad) << "[motion]\na1 = 1e308\n";
    r = run("--rawlog " + d + "/run.rawlog --out-dir " + out + " --seed 3 --config " +
            bad);
    EXPECT_NE(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("[motion] a1"), std::string::npos) << r.out;
    EXPECT_EQ(slurp(out + "/path.tum"), before);
    EXPECT_EQ(slurp(out + "/stats.json"), stats);
    EXPECT_FALSE(mrpt::system::directoryExists(out + ".tmp"));

    // Not rfir-slam's folder: refused, the foreign file kept.
    const std::string foreign = d + "/out_foreign";
    mrpt::system::createDirectory(foreign);
    std::ofstream(foreign + "/notes.txt") << "mine\n";
    r = run("--rawlog " + d + "/run.rawlog --out-dir " + foreign);
    EXPECT_NE(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("notes.txt"), std::string::npos) << r.out;
    EXPECT_EQ(slurp(foreign + "/notes.txt"), "mine\n");
    EXPECT_FALSE(mrpt::system::fileExists(foreign + "/path.tum"));
}
