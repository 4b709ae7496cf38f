/* One run's outputs: the staging folder and the renames of COutputFolder
 * (rfir-slam, rfir-localize) and COutputFiles (rfir-sim's NAME.* sets). */
#include <rfir/common/output_set.h>

#include "test_tmpdir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& f) {
    std::ifstream in(f);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
}  // namespace

TEST(OutputSet, FolderIsReplacedWholeOrNotAtAll) {
    rfir_test::TmpDir t;
    const std::string out = (t.p / "run").string();
    const std::vector<std::string> pats = {"path*.tum", "stats.json"};
    {
        rfir::common::COutputFolder f(out, pats, "prog");
        std::ofstream(f.file("path.tum")) << "a\n";
        std::ofstream(f.file("path_smoothed.tum")) << "a2\n";
        EXPECT_FALSE(fs::exists(out));  // nothing in place before commit
        f.commit();
    }
    {
        rfir::common::COutputFolder f(out, pats, "prog");
        std::ofstream(f.file("path.tum")) << "b\n";
        f.commit();
        EXPECT_EQ(f.files(), std::vector<std::string>{"path.tum"});
    }
    EXPECT_EQ(slurp(fs::path(out) / "path.tum"), "b\n");
    EXPECT_FALSE(fs::exists(fs::path(out) / "path_smoothed.tum"));
    {
        // A run that fails before commit leaves the earlier set.
        rfir::common::COutputFolder f(out, pats, "prog");
        std::ofstream(f.file("path.tum")) << "c\n";
    }
    EXPECT_EQ(slurp(fs::path(out) / "path.tum"), "b\n");
    for (const auto& e : fs::directory_iterator(t.p))
        EXPECT_EQ(e.path().filename(), "run") << e.path();  // no staging left
    std::ofstream(fs::path(out) / "notes.txt") << "x";
    EXPECT_THROW(rfir::common::COutputFolder(out, pats, "prog"), std::runtime_error);
}

TEST(OutputSet, FilesOfOneNameAreOneSet) {
    rfir_test::TmpDir t;
    const std::string d = t.p.string();
    std::ofstream(t.p / "other.rawlog") << "keep";
    const std::vector<std::string> pats = {"run.rawlog", "run.spots.tum"};
    {
        rfir::common::COutputFiles f(d, pats);
        std::ofstream(f.file("run.rawlog")) << "1";
        std::ofstream(f.file("run.spots.tum")) << "1";
        f.commit();
    }
    {
        rfir::common::COutputFiles f(d, pats);
        std::ofstream(f.file("run.rawlog")) << "2";
        f.commit();
    }
    EXPECT_EQ(slurp(t.p / "run.rawlog"), "2");
    EXPECT_FALSE(fs::exists(t.p / "run.spots.tum"));
    EXPECT_EQ(slurp(t.p / "other.rawlog"), "keep");
    {
        rfir::common::COutputFiles f(d, pats);
        std::ofstream(f.file("run.rawlog")) << "3";
    }  // not committed
    EXPECT_EQ(slurp(t.p / "run.rawlog"), "2");
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(t.p)) n += e.is_regular_file() ? 1 : 100;
    EXPECT_EQ(n, 2u);  // no staging folder left
}

TEST(OutputSet, RunIdentity) {
    rfir_test::TmpDir t;
    std::ofstream(t.p / "a.ini") << "[s]\nk = 1\n";
    const std::string j =
        rfir::common::runIdentityJson(7, (t.p / "a.ini").string(), {"x\"y", "z"});
    EXPECT_NE(j.find("\"seed\":7"), std::string::npos) << j;
    EXPECT_NE(j.find("\"files\":[\"x\\\"y\",\"z\"]"), std::string::npos) << j;
    EXPECT_NE(j.find("test_output_set"), std::string::npos) << j;  // the command
    EXPECT_EQ(rfir::common::fileMD5((t.p / "a.ini").string()).size(), 32u);
}

// A run killed between the two renames of the fallback commit left outDir
// missing and the earlier set in "<outDir>.old.<pid>": the next run puts it
// back, and removes staging folders of dead processes.
TEST(OutputSet, LeftoversOfKilledRunsAreCleaned) {
    rfir_test::TmpDir t;
    const std::string out = (t.p / "run").string();
    const std::vector<std::string> pats = {"path.tum"};
    // A pid that is not running (pid_max is far below it on Linux).
    const std::string dead = "999999999";
    fs::create_directories(out + ".old." + dead);
    std::ofstream(out + ".old." + dead + "/path.tum") << "earlier\n";
    fs::create_directories(out + ".tmp." + dead);
    {
        rfir::common::COutputFolder f(out, pats, "prog");
        EXPECT_EQ(slurp(fs::path(out) / "path.tum"), "earlier\n");
        std::ofstream(f.file("path.tum")) << "new\n";
        f.commit();
    }
    EXPECT_EQ(slurp(fs::path(out) / "path.tum"), "new\n");
    for (const auto& e : fs::directory_iterator(t.p))
        EXPECT_EQ(e.path().filename(), "run") << e.path();
}
