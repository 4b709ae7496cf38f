// Bounded text input: a file that is not text (5 GB of NUL bytes, sparse) is
// refused after one bounded line with an error naming file and line, by every
// text reader; a directory given as a file is named as such.
#include "test_tmpdir.h"

#include <rfir/common/log_convert.h>
#include <rfir/common/map_io.h>
#include <rfir/common/text_input.h>
#include <rfir/common/textlog.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/ir/emitter_set.h>
#include <rfir/localize/localize_config.h>
#include <rfir/models/ini_reader.h>
#include <rfir/sim/simulator.h>
#include <rfir/slam/slam_config.h>

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>

using namespace rfir::common;
using rfir_test::TmpDir;

namespace {
/** A sparse file of `size` NUL bytes (no disk blocks are written). */
std::string sparseNulFile(const TmpDir& d, uint64_t size) {
    const std::string p = d / "nul.txt";
    { std::ofstream(p, std::ios::binary); }
    if (truncate(p.c_str(), off_t(size)) != 0)
        throw std::runtime_error("truncate failed");
    return p;
}

/** The message of what `f` throws ("" if nothing), and that it took < 10 s. */
std::string errorOf(const std::function<void()>& f) {
    const auto t0 = std::chrono::steady_clock::now();
    std::string msg;
    try {
        f();
    } catch (const std::exception& e) {
        msg = e.what();
    }
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(10));
    return msg;
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

std::vector<std::string> allLines(std::istream& in, bool bounded) {
    std::vector<std::string> v;
    std::string l;
    if (bounded)
        for (size_t n = 1; getBoundedLine(in, l, "s", n); n++) v.push_back(l);
    else
        while (std::getline(in, l)) v.push_back(l);
    return v;
}

const std::vector<std::pair<const char*, std::function<void(const std::string&)>>>
    kReaders = {
        {"text log", [](const std::string& p) { readTextLog(p); }},
        {"import",
         [](const std::string& p) { convertTextLogToRawlog(p, p + ".rawlog"); }},
        {"map file", [](const std::string& p) { loadMapFile(p); }},
        {"TUM", [](const std::string& p) { loadTUM(p); }},
        {"emitter file", [](const std::string& p) { rfir::ir::TEmitterSet::load(p); }},
};
}  // namespace

TEST(TextInput, BoundedLineSplitsAsGetline) {
    std::mt19937 rng(7);
    for (int i = 0; i < 200; i++) {
        std::string s(rng() % 40, 'a');
        for (auto& c : s) c = "ab\n\r\0"[rng() % 5];
        std::istringstream a(s), b(s);
        EXPECT_EQ(allLines(a, true), allLines(b, false)) << i;
    }
}

TEST(TextInput, LineAtTheBoundIsReadOneOverIsRefused) {
    std::string line;
    std::istringstream ok(std::string(kMaxTextLineBytes, 'x') + "\nend");
    ASSERT_TRUE(getBoundedLine(ok, line, "s", 1));
    EXPECT_EQ(line.size(), kMaxTextLineBytes);
    std::istringstream over("short\n" + std::string(kMaxTextLineBytes + 1, '\0'));
    ASSERT_TRUE(getBoundedLine(over, line, "f.txt", 1));
    const auto msg = errorOf([&] { getBoundedLine(over, line, "f.txt", 2); });
    EXPECT_TRUE(contains(msg, "f.txt:2: line longer than 1048576 bytes")) << msg;
    EXPECT_LE(line.capacity(), 2 * kMaxTextLineBytes);
}

TEST(TextInput, FiveGigabytesOfNulAreRefusedAtLineOne) {
    TmpDir d;
    const std::string p = sparseNulFile(d, uint64_t(5) << 30);
    for (const auto& [what, read] : kReaders) {
        const auto msg = errorOf([&, &read = read] { read(p); });
        EXPECT_TRUE(contains(msg, p + ":1: line longer than")) << what << ": " << msg;
    }
    EXPECT_EQ(d.count(), 1u);  // the import wrote nothing
    // ctest runs each case in its own process: its peak memory is this
    // case's. Reading the file into one line would take 5 GB.
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    EXPECT_LT(ru.ru_maxrss, 512L * 1024) << "peak RSS in KiB";
}

TEST(TextInput, TextLogStreamNamesTheLongLine) {
    std::istringstream in("format textlog 1\n# ok\n" + std::string(3 << 20, '\0'));
    const auto msg = errorOf([&] { readTextLog(in, "log.txt"); });
    EXPECT_TRUE(contains(msg, "log.txt:3: line longer than")) << msg;
}

TEST(TextInput, DirectoryIsNamedAsSuch) {
    TmpDir d;
    const std::string dir = d / "sub";
    std::filesystem::create_directories(dir);
    for (const auto& [what, read] : kReaders) {
        const auto msg = errorOf([&, &read = read] { read(dir); });
        EXPECT_TRUE(contains(msg, dir + ": is a directory")) << what << ": " << msg;
    }
}

/** The message of the CIniError `f` throws; any other exception fails. */
std::string iniErrorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const rfir::ini::CIniError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a CIniError: " << e.what();
        return e.what();
    }
    ADD_FAILURE() << "no error";
    return {};
}

// Every INI loader of the programs: a file that is missing, a directory or
// too large is the same error type as a bad key, naming the file.
TEST(TextInput, IniReadersRefuseHugeFilesAndDirectories) {
    TmpDir d;
    const std::string big = sparseNulFile(d, uint64_t(5) << 30), dir = d / "sub";
    const std::string missing = d / "missing.ini";
    std::filesystem::create_directories(dir);
    for (const std::string& p : {big, dir, missing}) {
        const auto slam = iniErrorOf([&] { rfir::slam::loadSlamConfigFile(p); });
        const auto sim = iniErrorOf([&] { rfir::sim::loadSimConfig(p); });
        rfir::localize::TConfig cfg;
        cfg.iniPath = p;
        const auto loc = iniErrorOf([&] { rfir::localize::loadConfig(cfg, ""); });
        for (const auto& m : {slam, sim, loc}) {
            EXPECT_EQ(m.rfind(p + ": ", 0), 0u) << m;
            EXPECT_TRUE(contains(m, "limit") || contains(m, "directory") ||
                        contains(m, "no such INI file"))
                << m;
        }
    }
}

TEST(TextInput, SmallTextFileKeepsTheText) {
    TmpDir d;
    const std::string p = d / "a.ini";
    std::ofstream(p) << "[a]\nx = 1\n\n[b]\ny=2";
    EXPECT_EQ(readSmallTextFile(p, "INI file"), "[a]\nx = 1\n\n[b]\ny=2");
    std::ofstream(p) << "[a]\n";
    EXPECT_EQ(readSmallTextFile(p, "INI file"), "[a]\n");
}

TEST(TextInput, ImportProgramRefusesFiveGigabytesOfNul) {
    TmpDir d;
    const std::string p = sparseNulFile(d, uint64_t(5) << 30);
    const std::string cmd = std::string(RFIR_BINARY_DIR) + "/bin/rfir-import --input " +
                            p + " --output " + d / "out.rawlog" + " 2>" + d / "err.log";
    const auto t0 = std::chrono::steady_clock::now();
    const int st = std::system(cmd.c_str());
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(10));
    ASSERT_TRUE(WIFEXITED(st));  // no signal
    EXPECT_NE(WEXITSTATUS(st), 0);
    std::ifstream e(d / "err.log");
    const std::string err(std::istreambuf_iterator<char>(e), {});
    EXPECT_TRUE(contains(err, p + ":1: line longer than")) << err;
    EXPECT_FALSE(std::filesystem::exists(d / "out.rawlog"));
}

// Found by fuzz_mapfile: a coordinate of 1.8e114 m reached the emitter grid's
// double -> int64 conversion (undefined behaviour).
TEST(TextInput, EmitterFileRefusesFarCoordinates) {
    TmpDir d;
    const std::string p = d / "e.txt";
    std::ofstream(p) << "emitter 1 0 0 2\nemitter 2 1" << std::string(114, '8')
                     << " 0 2\n";
    const auto msg = errorOf([&] { rfir::ir::TEmitterSet::load(p); });
    EXPECT_TRUE(contains(msg, p + ":2: emitter '2': coordinates must be within")) << msg;
    std::ofstream(p) << "emitter 1 0 0 2\nemitter 2 1000000 -1000000 2\n";
    const auto set = rfir::ir::TEmitterSet::load(p);
    EXPECT_EQ(set.emitters().size(), 2u);
    // A query far outside the grid finds nothing (and converts no huge cell).
    EXPECT_FALSE(set.nearestIndexWithin(1e300, -1e300, 0.3));
    EXPECT_TRUE(set.nearestIndexWithin(0.1, 0, 0.3));
}
