// rfir-bench smoke test: a tiny run completes and reports every case; bad
// options fail with a message. Nothing here depends on how fast the machine is.
#include <gtest/gtest.h>

#include "test_tmpdir.h"

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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
    // Two rounds: the whole processes below are compared with their start-up
    // alone, each the faster of two runs timed alternately.
    const TRun r =
        run("--quick --m 100 --n 10,100 --updates 5 --realtime-seconds 20 --rounds 2 "
            "--json " +
                dir + "/b.json --plots " + dir,
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
    const auto j = nlohmann::json::parse(js);
    std::vector<nlohmann::json> cases;
    for (const char* sweep : {"sweep_M", "sweep_N"})
        for (const auto& c : j.at(sweep)) cases.push_back(c);
    for (const auto& x : j.at("realtime")) cases.push_back(x);
    const auto methods = [&](const std::string& m) {
        return std::count_if(cases.begin(), cases.end(),
                             [&](const auto& c) { return c.at("method") == m; });
    };
    EXPECT_EQ(methods("ps"), 5) << js;
    EXPECT_EQ(methods("pf"), 5);
    EXPECT_EQ(methods("fastslam"), 5);
    size_t run = 0, floorOrCase = j.at("floor").size();
    for (const char* sweep : {"sweep_M", "sweep_N"})
        for (const auto& c : j.at(sweep))
            if (!c.at("skipped").get<bool>()) {
                run++;
                floorOrCase += c.contains("median_us");
                EXPECT_TRUE(c.contains("state_bytes")) << c;
            }
    EXPECT_EQ(run, 9u);
    EXPECT_EQ(floorOrCase, 9u + 2u);  // cases + floor at M = 100, 500
    ASSERT_EQ(j.at("targets").size(), 10u);
    for (const auto& t : j.at("targets")) EXPECT_TRUE(t.contains("result")) << t;
    ASSERT_EQ(j.at("plain_reference").size(), 1u);
    // The plain reference maps every tag read, as the engines do.
    const auto& plain = j.at("plain_reference")[0];
    EXPECT_TRUE(plain.contains("plain_us_per_step"));
    EXPECT_GT(plain.at("plain_tags").get<long>(), 0);
    EXPECT_EQ(plain.at("plain_tags"), plain.at("ps_tags"));
    EXPECT_EQ(plain.at("plain_tags"), plain.at("pf_tags"));
    EXPECT_EQ(j.at("realtime").size(), 6u);
    for (const auto& x : j.at("realtime")) EXPECT_TRUE(x.contains("x_realtime")) << x;
    // Two whole rfir-slam processes (the floor, the 300 mm log), each more
    // than its binary's start-up alone.
    ASSERT_EQ(j.at("process").size(), 2u) << js;
    for (const auto& p : j.at("process")) {
        EXPECT_GT(p.at("startup_cpu_seconds").get<double>(), 0.0) << p;
        EXPECT_GT(p.at("cpu_seconds").get<double>(),
                  p.at("startup_cpu_seconds").get<double>())
            << p;
        // rfir-plain-ps ran side by side on the same log, exported as text.
        EXPECT_GT(p.at("plain_cpu_seconds").get<double>(), 0.0) << p;
        // MRPT's rawlog-edit is timed when it is on PATH, else reported as 0.
        const bool rawlogEdit =
            std::system("command -v rawlog-edit > /dev/null 2>&1") == 0;
        EXPECT_EQ(p.at("mrpt_startup_cpu_seconds").get<double>() > 0.0, rawlogEdit) << p;
    }
    // Every case mapped the tags it was built with (N, or N = 10 / 100).
    size_t mapped10 = 0, mapped100 = 0;
    for (const auto& c : cases)
        if (c.contains("landmarks")) {
            mapped10 += c.at("landmarks") == 10;
            mapped100 += c.at("landmarks") == 100;
        }
    EXPECT_EQ(mapped10, 3u) << js;
    EXPECT_EQ(mapped100, 3u);
    EXPECT_EQ(js.find("null"), std::string::npos);  // every number finite
    for (const char* png :
         {"bench_time_vs_M.png", "bench_time_vs_N.png", "bench_memory_vs_N.png"})
        EXPECT_GT(fileSize(dir + "/" + png), 1000) << png;
}

TEST(BenchSmoke, BadOptionsAreRejected) {
    const rfir_test::TmpDir tmp;
    const std::string dir = tmp.p.string();
    // Each a command-line error: exit 2 naming the option, before any work.
    for (const auto& [args, said] : std::vector<std::pair<std::string, std::string>>{
             {"--quick --n 5", "--n"},
             {"--quick --methods ps,ekf", "'ekf'"},
             {"--quick --m 10,x", "'x'"},
             {"--quick --plots /nonexistent_dir_for_rfir_bench",
              "nonexistent_dir_for_rfir_bench"},
             {"--m 100", "--full"},  // neither --quick nor --full
             {"", "usage:"}}) {
        const TRun r = run(args, dir);
        EXPECT_EQ(r.status, 2) << args << ": " << r.err;
        EXPECT_NE(r.err.find(said), std::string::npos) << args << ": " << r.err;
    }
}
