// librfir_mrpt_plugin.so: MRPT's own rawlog-edit reads project rawlogs with
// it, and cannot without it.
#include "test_import_util.h"

#include <dlfcn.h>
#include <sys/wait.h>

#include <mrpt/rtti/CObject.h>

#include <cstdlib>
#include <regex>
#include <set>

using rfir_test::TmpDir;

namespace {
const std::string kPlugin = std::string(RFIR_BINARY_DIR) + "/lib/librfir_mrpt_plugin.so";

std::string findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    for (size_t i = 0; i <= dirs.size();) {
        const size_t j = std::min(dirs.find(':', i), dirs.size());
        const fs::path p = fs::path(dirs.substr(i, j - i)) / name;
        if (!p.parent_path().empty() && fs::exists(p)) return p.string();
        i = j + 1;
    }
    return "";
}

/** Runs a command, stdout and stderr together. In the sanitizer build
 * (scripts/sanitize.sh) MRPT's uninstrumented programs get the sanitizer
 * runtimes preloaded, else they cannot load the instrumented plugin. */
std::string run(const TmpDir& d, const std::string& cmd, int& code) {
    const char* preload = std::getenv("RFIR_SANITIZER_PRELOAD");
    const std::string env =
        preload && *preload ? "LD_PRELOAD='" + std::string(preload) + "' " : "";
    const int st = std::system((env + cmd + " >" + d / "out.log" + " 2>&1").c_str());
    code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return rfir_test::slurp(d / "out.log");
}

size_t countOf(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1))
        n++;
    return n;
}

std::set<std::string> rfirClasses() {
    std::set<std::string> s;
    for (const auto* c : mrpt::rtti::getAllRegisteredClasses())
        if (std::string(c->className).rfind("rfir::", 0) == 0) s.insert(c->className);
    return s;
}

TEST(Plugin, LoadingItRegistersEveryLinkedLibrarysClasses) {
    ASSERT_TRUE(fs::exists(kPlugin)) << kPlugin;
    void* h = dlopen(kPlugin.c_str(), RTLD_NOW | RTLD_GLOBAL);
    ASSERT_TRUE(h) << dlerror();
    using Fn = const char* (*)();
    const auto libs = reinterpret_cast<Fn>(dlsym(h, "rfir_mrpt_plugin_libraries"));
    ASSERT_TRUE(libs);
    const std::string list = libs();
    const auto cls = rfirClasses();
    for (const char* c :
         {"rfir::obs::CObservationRFIDReaders", "rfir::obs::CObservationIRSignals",
          "rfir::obs::CObservationLogHeader"})
        EXPECT_TRUE(cls.count(c)) << c;
    // The other libraries it carries bring their own classes (the maps that
    // pf-localization / rbpf-slam INI files name).
    const std::pair<const char*, const char*> expected[] = {
        {"rfir_maps", "rfir::maps::CRFIDTagParticleMap"},
        {"rfir_ir", "rfir::maps::CIREmitterMap"}};
    for (const auto& [lib, c] : expected) {
        if (list.find(lib) != std::string::npos) {
            EXPECT_TRUE(cls.count(c)) << lib << ": " << c;
        }
    }
    std::cerr << "plugin libraries: " << list
              << "; rfir classes registered: " << cls.size() << "\n";
}

class RawlogEdit : public ::testing::Test {
  protected:
    void SetUp() override {
        tool_ = findProgram("rawlog-edit");
        if (tool_.empty())
            GTEST_SKIP() << "rawlog-edit (package mrpt-apps) is not installed";
        rfir::common::convertTextLogToRawlog(rfir_test::kFull, d_ / "f.rawlog");
    }
    std::string edit(const std::string& op, bool plugin, int& code) {
        return run(d_,
                   tool_ + " " + op + " -i " + d_ / "f.rawlog" +
                       (plugin ? " -p " + kPlugin : std::string()),
                   code);
    }
    TmpDir d_;
    std::string tool_;
};

TEST_F(RawlogEdit, InfoListsTheProjectsSensorsWithThePlugin) {
    int code = 0;
    const auto out = edit("--info", true, code);
    EXPECT_EQ(code, 0) << out;
    EXPECT_EQ(out.find("not registered"), std::string::npos) << out;
    EXPECT_TRUE(std::regex_search(out, std::regex("Overall number of objects *: 14")))
        << out;
    EXPECT_TRUE(std::regex_search(out, std::regex("Actions/SensoryFrame format *: Yes")));
    EXPECT_TRUE(std::regex_search(
        out, std::regex("All sensor labels *: HEADER, IR, ODOMETRY, RB, RFID")));
    // Label / occurrences, one line per sensor.
    for (const auto& [label, n] : std::vector<std::pair<std::string, int>>{
             {"HEADER", 1}, {"RFID", 3}, {"IR", 4}, {"RB", 2}, {"ODOMETRY", 5}})
        EXPECT_TRUE(std::regex_search(
            out, std::regex(" " + label + " / +" + std::to_string(n) + " /")))
            << label << "\n"
            << out;
}

TEST_F(RawlogEdit, DescribeShowsEveryObservationClass) {
    int code = 0;
    const auto out = edit("--describe", true, code);
    EXPECT_EQ(code, 0);
    EXPECT_EQ(countOf(out, "ClassName: rfir::obs::CObservationLogHeader"), 1u);
    EXPECT_EQ(countOf(out, "ClassName: rfir::obs::CObservationRFIDReaders"), 3u);
    EXPECT_EQ(countOf(out, "ClassName: rfir::obs::CObservationIRSignals"), 4u);
    EXPECT_EQ(countOf(out, "ClassName: mrpt::obs::CObservationBearingRange"), 2u);
    EXPECT_EQ(countOf(out, "ClassName: mrpt::obs::CObservationOdometry"), 5u);
    // The classes' own descriptions.
    EXPECT_NE(out.find("Start pose (world): x=1.2500 m, y=-0.5000 m"), std::string::npos);
    EXPECT_NE(out.find("R0             0.1500, -0.0500    0.0300, 0.0300    "
                       "E0040150A1B2C3D4 tag:17"),
              std::string::npos);
    EXPECT_NE(out.find("raw window: 1024 samples at 5000.0 Hz"), std::string::npos);
}

TEST_F(RawlogEdit, WithoutThePluginTheClassesAreNotRead) {
    int code = 0;
    const auto info = edit("--info", false, code);
    EXPECT_NE(info.find("rfir::obs::CObservationLogHeader"), std::string::npos) << info;
    EXPECT_NE(info.find("not registered"), std::string::npos);
    EXPECT_FALSE(std::regex_search(info, std::regex(" RFID / +3 /")));
    EXPECT_FALSE(std::regex_search(info, std::regex("Overall number of objects *: 14")));
    const auto desc = edit("--describe", false, code);
    EXPECT_EQ(countOf(desc, "ClassName: rfir::obs::"), 0u);
}

}  // namespace
