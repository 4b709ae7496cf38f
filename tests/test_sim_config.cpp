// The simulator's INI files: strict keys, clear errors, the stock INIs, the CLI.
#include <rfir/sim/simulator.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using rfir::sim::loadSimConfig;
using rfir::sim::TSimConfig;

namespace {
/** This process's folder, removed when it ends. */
const fs::path& procDir() {
    static const rfir_test::TmpDir d;
    return d.p;
}

std::string tmpIni(const std::string& name, const std::string& text) {
    const auto p = (procDir() / name).string();
    std::ofstream(p) << text;
    return p;
}

std::string errorOf(const std::string& ini, const std::vector<std::string>& sets = {}) {
    try {
        loadSimConfig(ini, sets);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}
}  // namespace

TEST(SimConfig, DefaultsAreTheSeedsLoop) {
    TSimConfig c;
    EXPECT_EQ(c.readers.size(), 8u);
    for (const auto& r : c.readers) EXPECT_DOUBLE_EQ(r.halfX, 0.03);
    EXPECT_EQ(c.rfid.density, 16);
    EXPECT_EQ(c.trajectory.kind, rfir::sim::TTrajectoryConfig::Kind::Loop);
    EXPECT_EQ(c.trajectory.laps, 3);
    EXPECT_NO_THROW(c.validate());
}

TEST(SimConfig, ReadsKeys) {
    const auto p =
        tmpIni("ok.ini",
               "[simulation]\ndt = 0.05\narea = -1 -2 3 4\n"
               "[robot]\nreaders = 0.1 0.2, -0.1 -0.2 0.05 0.04\n"
               "reader_half_size = 0.02\n"
               "[trajectory]\ntype = random\nwaypoints = 7\nrotation = spin\n"
               "[rfid]\ndensity = 100\n"
               "[range_bearing]\nenabled = true\nfov_deg = 90\n"
               "sensor_pose = 0.1 0 45\n"
               "[ir]\nenabled = true\nrepeated_codes = 5, 6\nfailed = 12, 0 0\n");
    const auto c = loadSimConfig(p);
    EXPECT_DOUBLE_EQ(c.dt, 0.05);
    EXPECT_DOUBLE_EQ(c.areaMinY, -2);
    ASSERT_EQ(c.readers.size(), 2u);
    EXPECT_DOUBLE_EQ(c.readers[0].halfX, 0.02);
    EXPECT_DOUBLE_EQ(c.readers[1].halfY, 0.04);
    EXPECT_EQ(c.trajectory.kind, rfir::sim::TTrajectoryConfig::Kind::Random);
    EXPECT_EQ(c.trajectory.rotation, rfir::sim::TTrajectoryConfig::Rotation::Spin);
    EXPECT_EQ(c.trajectory.waypoints, 7);
    EXPECT_DOUBLE_EQ(c.rfid.density, 100);
    EXPECT_NEAR(c.rbSensor.fov, M_PI / 2, 1e-12);
    EXPECT_NEAR(c.rbSensor.yaw, M_PI / 4, 1e-12);
    EXPECT_EQ(c.ir.repeatedCodes, (std::vector<uint8_t>{5, 6}));
    EXPECT_EQ(c.ir.failed, (std::vector<std::string>{"12", "0 0"}));
}

TEST(SimConfig, UnknownKeyNamesSectionAndKey) {
    const auto p = tmpIni("typo.ini", "[rfid]\ndensty = 16\n");
    const auto e = errorOf(p);
    EXPECT_TRUE(contains(e, "typo.ini")) << e;
    EXPECT_TRUE(contains(e, "[rfid] densty: unknown key")) << e;
}

TEST(SimConfig, UnknownSectionRejected) {
    EXPECT_TRUE(contains(errorOf(tmpIni("sec.ini", "[rfdi]\ndensity = 16\n")),
                         "[rfdi]: unknown section"));
}

TEST(SimConfig, BadValuesNameTheKey) {
    struct Case {
        const char* text;
        const char* expect;
    };
    const Case cases[] = {
        {"[rfid]\ndensity = -3\n", "[rfid] density: must be in (0, 1000000]"},
        {"[rfid]\ndensity = abc\n",
         "[rfid] density: expected a finite number, got 'abc'"},
        {"[simulation]\ndt = nan\n", "[simulation] dt:"},
        {"[trajectory]\ntype = zigzag\n",
         "[trajectory] type: unknown value 'zigzag' (one of"},
        {"[trajectory]\npredefined = 6\n", "[trajectory] predefined: must be in [1, 5]"},
        {"[trajectory]\nlaps = 2.5\n",
         "[trajectory] laps: expected an integer, got '2.5'"},
        {"[trajectory]\nlaps = 2\x01\xd9\n",
         "[trajectory] laps: expected an integer, got '2\\x01\\xD9'"},
        {"[robot]\nreaders = 0.1 0.2 0.3\n", "[robot] readers: entry 1"},
        {"[robot]\nreaders = 0.1 0.2,\n", "[robot] readers: empty entry"},
        {"[rfid]\nenabled = maybe\n",
         "[rfid] enabled: expected true or false, got 'maybe'"},
        {"[rfid]\nmiss_probability = 1\n", "[rfid] miss_probability: must be < 1"},
        {"[ir]\nrepeated_codes = 1, 0\n", "[ir] repeated_codes: '0' is not a code"},
        {"[ir]\nfailed = banana\n", "[ir] failed: 'banana'"},
        {"[ir]\noutput = raw\nsamples = 100\n", "[ir] samples: the raw window"},
        {"[kidnap]\nenabled = true\ntime = 5\nto_time = 10\n", "[kidnap] to_time"},
        {"[kidnap]\nto_pose = 1 2\n", "[kidnap] to_pose: entry 1"},
        {"[trajectory]\nmargin = 2.5\n", "[trajectory] margin leaves no room"},
        {"[range_bearing]\nfov_deg = 400\n",
         "[range_bearing] fov_deg: must be in (0, 360]"},
    };
    for (const auto& c : cases) {
        const auto e = errorOf(tmpIni("bad.ini", c.text));
        EXPECT_TRUE(contains(e, c.expect)) << c.text << " -> " << e;
        EXPECT_TRUE(contains(e, "bad.ini")) << e;
    }
}

TEST(SimConfig, MissingFileAndOverrides) {
    EXPECT_TRUE(
        contains(errorOf("/nonexistent/x.ini"), "/nonexistent/x.ini: no such INI file"));
    const auto p = tmpIni("empty.ini", "");
    EXPECT_TRUE(contains(errorOf(p, {"rfid.densty=3"}), "[rfid] densty: unknown key"));
    EXPECT_TRUE(contains(errorOf(p, {"density=3"}), "expected section.key=value"));
    const auto c = loadSimConfig(p, {"rfid.density=4", "trajectory.speed=0.3"});
    EXPECT_DOUBLE_EQ(c.rfid.density, 4);
    EXPECT_DOUBLE_EQ(c.trajectory.speed, 0.3);
}

TEST(SimConfig, StockInisLoadAndRun) {
    int n = 0;
    for (const auto& f :
         fs::directory_iterator(std::string(RFIR_SOURCE_DIR) + "/config_ini")) {
        const auto name = f.path().filename().string();
        if (name.rfind("sim_", 0) != 0 || f.path().extension() != ".ini") continue;
        SCOPED_TRACE(name);
        TSimConfig c;
        ASSERT_NO_THROW(c = loadSimConfig(f.path().string()));
        c.maxDuration = 3;
        const auto out = rfir::sim::simulate(c, 1);
        if (c.asyncTiming())  // event-driven: at least every dt step
            EXPECT_GE(out.steps.size(), size_t(3 / c.dt + 1e-9) + 1);
        else
            EXPECT_EQ(out.steps.size(), size_t(3 / c.dt + 1e-9) + 1);
        EXPECT_FALSE(out.gtMap.empty());
        n++;
    }
    EXPECT_GE(n, 20);
}

TEST(SimCli, WritesFilesAndRejectsBadInput) {
    const std::string bin = std::string(RFIR_BINARY_DIR) + "/bin/rfir-sim";
    const auto dir = procDir() / "cli";
    const auto ini = tmpIni("cli_run.ini", "[simulation]\nmax_duration = 4\n");
    const std::string cmd =
        bin + " --config " + ini + " --out-dir " + dir.string() + " --seed 3 -q";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    for (const char* ext : {".rawlog", ".gt.tum", ".gt_map.txt"})
        EXPECT_TRUE(fs::exists(dir / (std::string("cli_run") + ext))) << ext;
    ASSERT_EQ(std::system((cmd + " --name other").c_str()), 0);
    EXPECT_TRUE(fs::exists(dir / "other.rawlog"));

    const auto bad = tmpIni("cli_bad.ini", "[rfid]\ndensty = 3\n");
    const std::string badCmd =
        bin + " --config " + bad + " --out-dir " + dir.string() + " 2>/dev/null";
    EXPECT_NE(std::system(badCmd.c_str()), 0);
    EXPECT_FALSE(fs::exists(dir / "cli_bad.rawlog"));
    EXPECT_NE(std::system((cmd + " --set foo 2>/dev/null").c_str()), 0);
}
