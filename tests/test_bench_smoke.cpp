// rfir-bench smoke test: a tiny run completes and reports every case; bad
// options fail with a message. Nothing here depends on how fast the machine is.
#include <gtest/gtest.h>

#include "test_tmpdir.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace {
const std::string kBench = std::string(RFIR_BINARY_DIR) + "/bin/rfir-bench";

struct TRun {
    int status = -1;
    std::string out, err;
};

std::string slurp(const std::string& path) {
    std::ifstream f(path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

TRun run(const std::string& args, const std::string& dir) {
    TRun r;
    const std::string cmd =
        kBench + " " + args + " > " + dir + "/out.txt 2> " + dir + "/err.txt";
    const int st = std::system(cmd.c_str());
    r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.out = slurp(dir + "/out.txt");
    r.err = slurp(dir + "/err.txt");
    return r;
}

size_t count(const std::string& s, const std::string& what) {
    size_t n = 0;
    for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) n++;
    return n;
}

long fileSize(const std::string& p) {
    struct stat st;
    return ::stat(p.c_str(), &st) == 0 ? long(st.st_size) : -1;
}
}  // namespace

TEST(BenchSmoke, TinyRunReportsEveryCase) {
    const rfir_test::TmpDir tmp;
    const std::string dir = tmp.p.string();
    const TRun r =
        run("--quick --m 100 --n 10,100 --updates 5 --realtime-seconds 20 --json " + dir +
                "/b.json --plots " + dir,
            dir);
    ASSERT_EQ(r.status, 0) << r.err;
    // Table: the floor, both sweeps, the whole runs, the plain reference side
    // by side, the whole rfir-slam processes and ten targets.
    EXPECT_NE(r.out.find("floor (1 fast Gaussian motion draw"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("per step against the plain reference"), std::string::npos);
    EXPECT_NE(r.out.find("time and memory against M"), std::string::npos);
    EXPECT_NE(r.out.find("time and memory against N"), std::string::npos);
    EXPECT_NE(r.out.find("whole offline runs"), std::string::npos);
    EXPECT_NE(r.out.find("whole rfir-slam processes"), std::string::npos);
    EXPECT_EQ(count(r.out, "PASS  ") + count(r.out, "FAIL  ") + count(r.out, "n/a   "),
              10u)
        << r.out;
    // One row per method in the sweep over M (1 value) and over N (2 values),
    // plus the whole runs (M = 100 and 500).
    for (const char* m : {"\nPS-SLAM ", "\nPF-SLAM ", "\nFastSLAM "})
        EXPECT_EQ(count(r.out, m), 1u + 2u + 2u) << m << "\n" << r.out;

    const std::string js = slurp(dir + "/b.json");
    ASSERT_FALSE(js.empty());
    EXPECT_EQ(count(js, "\"method\": \"ps\""), 5u) << js;
    EXPECT_EQ(count(js, "\"method\": \"pf\""), 5u);
    EXPECT_EQ(count(js, "\"method\": \"fastslam\""), 5u);
    EXPECT_EQ(count(js, "\"skipped\": false"), 9u);
    EXPECT_EQ(count(js, "\"median_us\": "), 9u + 2u);  // cases + floor at M = 100, 500
    EXPECT_EQ(count(js, "\"state_bytes\": "), 9u);
    EXPECT_EQ(count(js, "\"result\": "), 10u);
    EXPECT_EQ(count(js, "\"plain_us_per_step\": "), 1u);
    // The plain reference maps every tag read, as the engines do.
    const auto num = [&](const std::string& key) {
        const size_t at = js.find("\"" + key + "\": ");
        return at == std::string::npos ? -1L : std::stol(js.substr(at + key.size() + 4));
    };
    EXPECT_GT(num("plain_tags"), 0);
    EXPECT_EQ(num("plain_tags"), num("ps_tags"));
    EXPECT_EQ(num("plain_tags"), num("pf_tags"));
    EXPECT_EQ(count(js, "\"x_realtime\": "), 6u);
    // Two whole rfir-slam processes (the floor, the 300 mm log), each more
    // than its binary's start-up alone.
    EXPECT_EQ(count(js, "\"cpu_seconds\": "), 2u) << js;
    const auto real = [&](const std::string& key) {
        const size_t at = js.find("\"" + key + "\": ");
        return at == std::string::npos ? -1.0 : std::stod(js.substr(at + key.size() + 4));
    };
    EXPECT_GT(real("startup_cpu_seconds"), 0.0);
    EXPECT_GT(real("cpu_seconds"), real("startup_cpu_seconds"));
    // Every case mapped the tags it was built with (N, or N = 10 / 100).
    EXPECT_EQ(count(js, "\"landmarks\": 10}"), 3u) << js;
    EXPECT_EQ(count(js, "\"landmarks\": 100}"), 3u);
    EXPECT_EQ(js.find("nan"), std::string::npos);
    for (const char* png :
         {"bench_time_vs_M.png", "bench_time_vs_N.png", "bench_memory_vs_N.png"})
        EXPECT_GT(fileSize(dir + "/" + png), 1000) << png;
}

TEST(BenchSmoke, BadOptionsAreRejected) {
    const rfir_test::TmpDir tmp;
    const std::string dir = tmp.p.string();
    TRun r = run("--n 5", dir);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("--n"), std::string::npos) << r.err;
    r = run("--methods ps,ekf", dir);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("'ekf'"), std::string::npos) << r.err;
    r = run("--m 10,x", dir);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("'x'"), std::string::npos) << r.err;
    r = run("--plots /nonexistent_dir_for_rfir_bench", dir);
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("nonexistent_dir_for_rfir_bench"), std::string::npos) << r.err;
}
