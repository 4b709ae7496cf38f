/* rfir-localize and rfir-ids as programs: outputs, reproducibility, errors
 * that name the file and line or the INI section and key; the ID arithmetic
 * and the layout planner. */
#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/ir/emitter_set.h>
#include <rfir/ir/id_planner.h>
#include <rfir/sim/simulator.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {
const std::string kBin = std::string(RFIR_BINARY_DIR) + "/bin/";
// Per process: ctest runs every test case as its own process, in parallel.
// Removed when the process ends.
const rfir_test::TmpDir kTmp;
const std::string kDir = kTmp.p.string();

std::string slurp(const std::string& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/** Runs a command line; returns its exit code, stdout and stderr. */
int sh(const std::string& cmd, std::string* out = nullptr, std::string* err = nullptr) {
    const std::string o = kDir + "/stdout.txt", e = kDir + "/stderr.txt";
    const int rc = std::system((cmd + " > '" + o + "' 2> '" + e + "'").c_str());
    if (out) *out = slurp(o);
    if (err) *err = slurp(e);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/** A short simulated run (30 s of the IR loop) written once. */
const std::string& rawlog() {
    static std::string path;
    if (!path.empty()) return path;
    fs::create_directories(kDir);
    auto cfg = rfir::sim::loadSimConfig(std::string(RFIR_SOURCE_DIR) +
                                        "/config_ini/sim_ir_loop.ini");
    cfg.maxDuration = 30;
    cfg.trajectory.spots = 5;
    rfir::sim::writeOutputs(rfir::sim::simulate(cfg, 3), kDir, "run");
    path = kDir + "/run.rawlog";
    return path;
}

std::string localize(const std::string& args) {
    return kBin + "rfir-localize -q --rawlog '" + rawlog() + "' " + args;
}
}  // namespace

TEST(IRApps, LocalizeWritesOutputsAndReproduces) {
    const std::string out = kDir + "/out_a", out2 = kDir + "/out_b";
    fs::remove_all(out);
    fs::remove_all(out2);
    ASSERT_EQ(sh(localize("--emitters '" + kDir + "/run.gt_map.txt' --out-dir '" + out +
                          "' --seed 5")),
              0);
    // rfir-slam's names where the files are the same.
    for (const char* f :
         {"path.tum", "stats.json", "settings.ini", "path_map.png", "errors.json",
          "errors_spots.json", "error_time.png", "emitter_health.txt"})
        EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
    const auto path = rfir::common::loadTUM(out + "/path.tum");
    EXPECT_GT(path.size(), 200u);
    const auto stats = nlohmann::json::parse(slurp(out + "/stats.json"));
    EXPECT_TRUE(stats.contains("first_unique_time")) << stats;
    EXPECT_TRUE(stats.contains("path_errors"));
    EXPECT_TRUE(stats.contains("spot_errors"));
    // A clean run: no lost track, no failed or inconsistent emitter.
    EXPECT_EQ(stats.at("lost_events"), nlohmann::json::array());
    EXPECT_EQ(stats.at("emitters_failed"), nlohmann::json::array());
    EXPECT_EQ(stats.at("emitters_inconsistent"), nlohmann::json::array());
    {
        // One line per emitter of the map after the two comment lines.
        std::istringstream h(slurp(out + "/emitter_health.txt"));
        size_t lines = 0;
        for (std::string l; std::getline(h, l);)
            if (!l.empty() && l[0] != '#') lines++;
        EXPECT_EQ(
            lines,
            rfir::ir::TEmitterSet::load(kDir + "/run.gt_map.txt").emitters().size());
    }
    // errors*.json: the rows of stats.json, as rfir-slam's errors.json.
    const auto errors = nlohmann::json::parse(slurp(out + "/errors.json"));
    EXPECT_EQ(errors.at("label"), "IR MCL (path)");
    EXPECT_EQ(errors, stats.at("path_errors"));
    EXPECT_EQ(nlohmann::json::parse(slurp(out + "/errors_spots.json")),
              stats.at("spot_errors"));
    // settings.ini + the same seed gives the same path, byte for byte.
    ASSERT_EQ(sh(localize("--config '" + out + "/settings.ini' --out-dir '" + out2 +
                          "' --seed 5")),
              0);
    EXPECT_EQ(slurp(out + "/path.tum"), slurp(out2 + "/path.tum"));
}

// --gt-path as rfir-slam's: a ground truth that is not <stem>.gt.tum beside
// the rawlog scores the run; without either there is no error file.
TEST(IRApps, LocalizeGroundTruthByOption) {
    const std::string alone = kDir + "/alone", gt = kDir + "/elsewhere.tum";
    fs::create_directories(alone);
    fs::copy_file(rawlog(), alone + "/run.rawlog", fs::copy_options::overwrite_existing);
    fs::copy_file(kDir + "/run.gt.tum", gt, fs::copy_options::overwrite_existing);
    const std::string base = kBin + "rfir-localize -q --rawlog '" + alone +
                             "/run.rawlog' --emitters '" + kDir +
                             "/run.gt_map.txt' --seed 5 --out-dir '";
    ASSERT_EQ(sh(base + kDir + "/no_gt'"), 0);
    EXPECT_TRUE(fs::exists(kDir + "/no_gt/path_map.png"));
    EXPECT_FALSE(fs::exists(kDir + "/no_gt/errors.json"));
    EXPECT_FALSE(fs::exists(kDir + "/no_gt/error_time.png"));
    ASSERT_EQ(sh(base + kDir + "/by_option' --gt-path '" + gt + "'"), 0);
    const auto e = nlohmann::json::parse(slurp(kDir + "/by_option/errors.json"));
    EXPECT_TRUE(fs::exists(kDir + "/by_option/error_time.png"));
    // The same numbers as the automatic lookup beside the rawlog (same seed).
    ASSERT_EQ(sh(localize("--emitters '" + kDir +
                          "/run.gt_map.txt' --seed 5 --out-dir '" + kDir + "/auto'")),
              0);
    EXPECT_EQ(e, nlohmann::json::parse(slurp(kDir + "/auto/errors.json")));
    // A --gt-path that is no file: an error before any output.
    std::string err;
    EXPECT_EQ(
        sh(base + kDir + "/bad_gt' --gt-path '" + kDir + "/nosuch.tum'", nullptr, &err),
        1);
    EXPECT_NE(err.find("nosuch.tum"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(kDir + "/bad_gt"));
}

namespace {
/** rfir-localize into kDir/`name` with the ground-truth emitters and `args`;
 * expects a pose for every instant (from the start); returns stats.json. */
nlohmann::json localizeEveryInstant(const std::string& name, const std::string& args) {
    const std::string out = kDir + "/" + name;
    EXPECT_EQ(sh(localize("--emitters '" + kDir + "/run.gt_map.txt' --out-dir '" + out +
                          "' " + args)),
              0);
    const auto gt = rfir::common::loadTUM(kDir + "/run.gt.tum");
    const auto p = rfir::common::loadTUM(out + "/path.tum");
    EXPECT_EQ(p.size(), gt.size());
    return nlohmann::json::parse(slurp(out + "/stats.json"));
}
}  // namespace

TEST(IRApps, LocalizeOdometryOnly) {
    EXPECT_EQ(localizeEveryInstant("out_odo", "--odometry-only").at("mode"),
              "odometry-only");
}

// A robot that starts at a known place (start_pose = log): the estimate from
// the first instant, drawn about the log's start pose; a log without one is
// an error naming the key, not a silent global start.
TEST(IRApps, LocalizeKnownStartFromTheLog) {
    const auto stats =
        localizeEveryInstant("out_known", "--set localization.start_pose=log");
    EXPECT_EQ(stats.at("start_pose"), "log");
    EXPECT_LT(stats.at("path_errors").at("robot").at("max_dist").get<double>(), 0.1)
        << stats.at("path_errors");

    const std::string txt = kDir + "/no_start.txt", raw = kDir + "/no_start.rawlog";
    std::ofstream(txt) << "format textlog 1\nreceiver left 0.1 0.2 0.35\n"
                          "odom 0 0 0 0\nir 0 left 3,9 1.82\nodom 0.1 0.05 0 0.01\n";
    ASSERT_EQ(sh(kBin + "rfir-import -q --input '" + txt + "' --output '" + raw + "'"),
              0);
    std::string err;
    EXPECT_EQ(sh(kBin + "rfir-localize -q --rawlog '" + raw + "' --emitters '" + kDir +
                     "/run.gt_map.txt' --out-dir '" + kDir +
                     "/o_ns' --set localization.start_pose=log",
                 nullptr, &err),
              1);
    EXPECT_NE(err.find(raw + ": [localization] start_pose = log"), std::string::npos)
        << err;
    EXPECT_FALSE(fs::exists(kDir + "/o_ns/path.tum"));
}

TEST(IRApps, LocalizeRejectsUnknownIniKeyAndSection) {
    std::string ini = slurp(std::string(RFIR_SOURCE_DIR) + "/config_ini/ir_localize.ini");
    const std::string bad = kDir + "/bad_key.ini";
    std::ofstream(bad) << ini << "\n[motion]\nk_xyz = 0.1\n";
    std::string err;
    EXPECT_EQ(sh(localize("--config '" + bad + "' --emitters '" + kDir +
                          "/run.gt_map.txt' --out-dir '" + kDir + "/o'"),
                 nullptr, &err),
              1);
    EXPECT_NE(err.find("[motion] k_xyz: unknown key"), std::string::npos) << err;
    EXPECT_NE(err.find("[motion]"), std::string::npos) << err;
    const std::string bad2 = kDir + "/bad_section.ini";
    std::ofstream(bad2) << ini << "\n[localisation]\nnum_particles = 5\n";
    EXPECT_EQ(sh(localize("--config '" + bad2 + "' --emitters '" + kDir +
                          "/run.gt_map.txt' --out-dir '" + kDir + "/o'"),
                 nullptr, &err),
              1);
    EXPECT_NE(err.find("[localisation]: unknown section"), std::string::npos) << err;
    const std::string bad3 = kDir + "/bad_value.ini";
    std::ofstream(bad3) << ini << "\n[MetricMap_irEmitterMap_00_likelihoodOpts]\n"
                        << "association = nearest\n";
    EXPECT_EQ(sh(localize("--config '" + bad3 + "' --emitters '" + kDir +
                          "/run.gt_map.txt' --out-dir '" + kDir + "/o'"),
                 nullptr, &err),
              1);
    EXPECT_NE(err.find("] association: unknown value 'nearest'"), std::string::npos)
        << err;
}

// --help-keys (rfir-localize, rfir-sim): the INI's keys with --set applied
// and their meanings, exit 0, nothing read or written; a bad edit exits 2.
TEST(IRApps, HelpKeysListTheConfiguration) {
    std::string out, err;
    ASSERT_EQ(sh(kBin + "rfir-localize --help-keys --set localization.num_particles=300",
                 &out, &err),
              0)
        << err;
    EXPECT_NE(out.find("[localization]\nassociation_max_std = "), std::string::npos)
        << out;
    EXPECT_NE(out.find("\nnum_particles = 300\n    robot particles M"), std::string::npos)
        << out;
    EXPECT_NE(out.find("\nsigma_volts = "), std::string::npos) << out;
    EXPECT_EQ(out.find("(no description)"), std::string::npos) << out;
    EXPECT_EQ(
        sh(kBin + "rfir-localize --help-keys --set localization.nosuch=1", &out, &err),
        2);
    EXPECT_NE(err.find("localization.nosuch"), std::string::npos) << err;
    ASSERT_EQ(
        sh(kBin + "rfir-sim --help-keys --config sim_kidnap --set trajectory.speed=0.3",
           &out, &err),
        0)
        << err;
    EXPECT_NE(out.find("\nspeed = 0.3\n    the robot's constant speed"),
              std::string::npos)
        << out;
    EXPECT_NE(out.find("[kidnap]\n"), std::string::npos) << out;
    EXPECT_EQ(out.find("(no description)"), std::string::npos) << out;
}

TEST(IRApps, LocalizeBadEmitterFileNamesLine) {
    const std::string em = kDir + "/bad_emitters.txt";
    std::ofstream(em)
        << "emitter 1 0 0 1.5\nemitter 12 0.4 0.4 1.5\nemitter 21 1 1 1.5\n";
    std::string err;
    EXPECT_EQ(
        sh(localize("--emitters '" + em + "' --out-dir '" + kDir + "/o'"), nullptr, &err),
        1);
    EXPECT_NE(err.find(em + ":3: emitter ID '21'"), std::string::npos) << err;
    EXPECT_EQ(sh(localize("--out-dir '" + kDir + "/o'"), nullptr, &err), 1);
    EXPECT_NE(err.find("no emitter file"), std::string::npos) << err;
    EXPECT_EQ(sh(kBin + "rfir-localize -q --rawlog /nonexistent.rawlog --emitters '" +
                     em + "' --out-dir '" + kDir + "/o'",
                 nullptr, &err),
              1);
}

TEST(IRIds, CountsAndCodes) {
    std::string out;
    ASSERT_EQ(sh(kBin + "rfir-ids count", &out), 0);
    EXPECT_EQ(out, "511\n");
    ASSERT_EQ(sh(kBin + "rfir-ids count --frequencies 30 --max-codes 6", &out), 0);
    EXPECT_EQ(out, "768211\n");  // thesis 5.3
    ASSERT_EQ(sh(kBin + "rfir-ids encode --codes 3,9", &out), 0);
    EXPECT_EQ(out, "39\n");
    ASSERT_EQ(sh(kBin + "rfir-ids decode --id 39", &out), 0);
    EXPECT_NE(out.find("frequencies_hz 250 1150"), std::string::npos);
    EXPECT_NE(out.find("type unique"), std::string::npos);
    std::string err;
    // Command-line errors: exit 2 naming the option or the command.
    EXPECT_EQ(sh(kBin + "rfir-ids encode --codes 9,3", &out, &err), 2);
    EXPECT_NE(err.find("--codes: '9,3'"), std::string::npos) << err;
    EXPECT_EQ(sh(kBin + "rfir-ids frobnicate", &out, &err), 2);
    EXPECT_NE(err.find("unknown command 'frobnicate'"), std::string::npos) << err;
    EXPECT_EQ(sh(kBin + "rfir-ids --frobnicate", &out, &err), 2);
    EXPECT_NE(err.find("--frobnicate"), std::string::npos) << err;
}

// Thesis 5.3: L_r = 600, W_r = 400, 9 repeated IDs: 239,010 against 479,001.
TEST(IRIds, MemorySizes) {
    EXPECT_EQ(rfir::ir::mixedLayoutRecords(600, 400, 9), 239010u);
    EXPECT_EQ(rfir::ir::uniqueOnlyLayoutRecords(600, 400), 479001u);
    std::string out;
    ASSERT_EQ(sh(kBin + "rfir-ids memory --grid '600 400'", &out), 0);
    EXPECT_NE(out.find("239010"), std::string::npos);
    EXPECT_NE(out.find("479001"), std::string::npos);
}

// The planner on the simulator's room: 5 x 4 repeated (4 codes) + 4 x 3 unique
// emitters = 32 emitters, 16 IDs, against 32 with unique IDs only.
TEST(IRIds, PlannerCountsAndFile) {
    rfir::ir::TRoom room{0, 0, 3.2, 2.4};
    const auto r = rfir::ir::planLattice(room, {});
    EXPECT_EQ(r.emitters.size(), 32u);
    EXPECT_EQ(r.repeatedEmitters, 20u);
    EXPECT_EQ(r.uniqueEmitters, 12u);
    EXPECT_EQ(r.repeatedGridX, 5u);
    EXPECT_EQ(r.repeatedGridY, 4u);
    EXPECT_EQ(r.distinctIds, 16u);
    EXPECT_EQ(r.uniqueOnlyIds, 32u);
    const std::string f = kDir + "/planned.txt";
    fs::create_directories(kDir);
    std::string out;
    ASSERT_EQ(sh(kBin + "rfir-ids plan --room '0 0 3.2 2.4' --output '" + f + "'", &out),
              0);
    EXPECT_NE(out.find("IDs used:          16"), std::string::npos) << out;
    const auto m = rfir::common::loadMapFile(f);
    EXPECT_EQ(m.size(), 32u);
    // A room too large for 9 codes is refused.
    std::string err;
    EXPECT_EQ(sh(kBin + "rfir-ids plan --room '0 0 40 40'", &out, &err), 1);
    EXPECT_NE(err.find("more unique IDs"), std::string::npos) << err;
}
