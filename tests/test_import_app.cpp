// The rfir-import program: exit codes, messages, progress, and no output on
// error.
#include "test_import_util.h"

#include <sys/wait.h>

#include <cstdlib>

using rfir_test::TmpDir;

namespace {
const std::string kApp = std::string(RFIR_BINARY_DIR) + "/bin/rfir-import";

struct TRun {
    int code = -1;
    std::string out, err;
};

TRun run(const TmpDir& d, const std::string& args) {
    const std::string cmd =
        kApp + " " + args + " >" + d / "stdout.log" + " 2>" + d / "stderr.log";
    const int st = std::system(cmd.c_str());
    TRun r;
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.out = rfir_test::slurp(d / "stdout.log");
    r.err = rfir_test::slurp(d / "stderr.log");
    fs::remove(d / "stdout.log");
    fs::remove(d / "stderr.log");
    return r;
}

TEST(ImportApp, HelpAndUsageErrors) {
    TmpDir d;
    auto r = run(d, "--help");
    EXPECT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("--input"), std::string::npos);
    EXPECT_NE(r.out.find("textlog 1"), std::string::npos);
    EXPECT_EQ(run(d, "").code, 2);               // required arguments missing
    EXPECT_EQ(run(d, "--input a.txt").code, 2);  // no output
    EXPECT_EQ(run(d, "-i a.txt -o b.rawlog --frobnicate").code, 2);
    r = run(d, "-i " + rfir_test::kFull + " -o " + d / "out.csv");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("cannot tell the direction"), std::string::npos) << r.err;
    EXPECT_EQ(run(d, "-i " + rfir_test::kFull + " -o " + d / "out.txt").code, 2);
    EXPECT_EQ(run(d, "--lossy -i " + rfir_test::kFull + " -o " + d / "o.rawlog").code, 2);
    EXPECT_EQ(d.count(), 0u);
}

TEST(ImportApp, ImportsAndExports) {
    TmpDir d;
    auto r = run(d, "--input " + rfir_test::kFull + " --output " + d / "f.rawlog");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("6 sensing instant(s), 17 timed record(s)"), std::string::npos)
        << r.err;
    r = run(d, "-q -i " + d / "f.rawlog" + " -o " + d / "f.TXT");  // case-insensitive
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(rfir::common::readTextLog(d / "f.TXT").records.size(), 17u);
}

TEST(ImportApp, MalformedInputFailsWithFileLineAndWritesNothing) {
    TmpDir d;
    std::ofstream(d / "bad.txt") << "format textlog 1\nreader R0 0 0 0.03 0.03\n"
                                    "odom 0 0 0 0\nrfid 0.1 R1 T1\n";
    const auto r = run(d, "-i " + d / "bad.txt" + " -o " + d / "bad.rawlog");
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(d / "bad.txt" +
                         ":4: rfid names reader 'R1', which no 'reader' header record "
                         "declares"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(d.count(), 1u);  // bad.txt alone
    const auto missing = run(d, "-i " + d / "none.txt" + " -o " + d / "x.rawlog");
    EXPECT_EQ(missing.code, 1);
    EXPECT_NE(missing.err.find("none.txt"), std::string::npos);
    std::ofstream(d / "junk.rawlog") << "junk";
    const auto junk = run(d, "-i " + d / "junk.rawlog" + " -o " + d / "junk.txt");
    EXPECT_EQ(junk.code, 1);
    EXPECT_NE(junk.err.find("junk.rawlog"), std::string::npos);
    EXPECT_FALSE(fs::exists(d / "junk.txt"));
}

TEST(ImportApp, ProgressOnBigInputs) {
    // About 2 MB of raw IR windows.
    TmpDir d;
    std::ofstream f(d / "big.txt");
    f << "format textlog 1\nreceiver L 0 0 1\n";
    std::string window;
    for (int i = 0; i < 1000; i++)
        window += (i ? "," : "") + std::to_string(i % 7) + ".25";
    for (int k = 0; k < 350; k++) f << "ir_raw " << k << " L 4000 " << window << "\n";
    f.close();
    const auto r = run(d, "-i " + d / "big.txt" + " -o " + d / "big.rawlog");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("checking " + d / "big.txt" + ": 100%"), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("converting " + d / "big.txt" + ": 100%"), std::string::npos);
    EXPECT_EQ(run(d, "-q -i " + d / "big.rawlog" + " -o " + d / "big2.txt").code, 0);
    EXPECT_EQ(rfir::common::readTextLog(d / "big2.txt").records.size(), 350u);
}

}  // namespace
