/* The command-line helpers every program uses: strict numbers, lists, the
 * parse outcome (help / version / error / no argument), --start folding, stock
 * INIs by name, subcommands, --set edits split between the kinds of INI a
 * program reads and blamed when an INI refuses them. */
#include <rfir/common/cli.h>
#include <rfir/common/ini_override.h>
#include <rfir/common/install_paths.h>
#include <rfir/models/ini_reader.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace rfir::common;

TEST(Cli, IntegersAreParsedStrictly) {
    EXPECT_EQ(parseNumber<uint64_t>("42"), 42u);
    EXPECT_EQ(parseNumber<uint64_t>("0"), 0u);
    EXPECT_EQ(parseNumber<uint64_t>("18446744073709551615"), UINT64_MAX);
    EXPECT_EQ(parseNumber<int>("-3"), -3);
    for (const char* bad : {"", "abc", "-3", "1.5", "5e2", "500x", " 5", "5 ", "+5",
                            "nan", "inf", "18446744073709551616", "0x10"})
        EXPECT_FALSE(parseNumber<uint64_t>(bad)) << "'" << bad << "'";
    for (const char* bad : {"2147483648", "1.0", "--1"})
        EXPECT_FALSE(parseNumber<int>(bad)) << bad;
}

TEST(Cli, RealsMustBeFinite) {
    EXPECT_DOUBLE_EQ(*parseNumber<double>("0.25"), 0.25);
    EXPECT_DOUBLE_EQ(*parseNumber<double>("-1e-3"), -1e-3);
    EXPECT_DOUBLE_EQ(*parseNumber<double>("5e2"), 500);
    for (const char* bad :
         {"", "nan", "NaN", "inf", "-inf", "infinity", "1e400", "1x", "1,5", " 1", "abc"})
        EXPECT_FALSE(parseNumber<double>(bad)) << "'" << bad << "'";
}

TEST(Cli, RangesAndListsNameTheOption) {
    EXPECT_EQ(parseNumberOrThrow<int>("--k", "5", 2, 9), 5);
    try {
        parseNumberOrThrow<int>("--k", "10", 2, 9);
        FAIL() << "10 accepted in [2, 9]";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "--k: '10' is not a whole number in [2, 9]");
    }
    EXPECT_EQ(parseNumberList<size_t>("--m", "100,500", ',', 0, 1),
              (std::vector<size_t>{100, 500}));
    EXPECT_THROW(parseNumberList<size_t>("--m", "100,,500", ',', 0, 1),
                 std::invalid_argument);
    EXPECT_THROW(parseNumberList<size_t>("--m", "100,0", ',', 0, 1),
                 std::invalid_argument);
    EXPECT_EQ(parseNumberList<double>("--start", " 1  -2\t0.5 ", ' ', 3),
              (std::vector<double>{1, -2, 0.5}));
    EXPECT_THROW(parseNumberList<double>("--start", "1 2", ' ', 3),
                 std::invalid_argument);
    EXPECT_THROW(parseNumberList<double>("--start", "1 2 3 4", ' ', 3),
                 std::invalid_argument);
    EXPECT_THROW(parseNumberList<double>("--start", "", ' ', 3), std::invalid_argument);
    EXPECT_THROW(parseNumberList<double>("--start", "1 2 nan", ' ', 3),
                 std::invalid_argument);
}

namespace {
struct TCmd {
    TCLAP::CmdLine cmd{"test", ' ', "9.9"};
    CNumberArg<uint64_t> seed{"", "seed", "seed", false, 7, "N", cmd};
    CNumberArg<double> gain{"", "gain", "gain", false, 1.5, "G", cmd, 0, 10};
    TCLAP::ValueArg<std::string> out{"", "out-dir", "folder", true, "", "DIR", cmd};
};
std::optional<int> parse(TCmd& c, std::vector<std::string> args) {
    args.insert(args.begin(), "prog");
    return parseCommandLine(c.cmd, args, {{"-o", "--out-dir"}});
}
}  // namespace

TEST(Cli, ParseOutcomes) {
    {
        TCmd c;
        EXPECT_EQ(parse(c, {"--out-dir", "x"}), std::nullopt);
        EXPECT_EQ(c.seed.getValue(), 7u);  // the default
        EXPECT_DOUBLE_EQ(c.gain.getValue(), 1.5);
    }
    {
        TCmd c;
        EXPECT_EQ(parse(c, {"--out-dir", "x", "--seed", "12", "--gain", "0.5"}),
                  std::nullopt);
        EXPECT_EQ(c.seed.getValue(), 12u);
        EXPECT_DOUBLE_EQ(c.gain.getValue(), 0.5);
    }
    {
        TCmd c;  // the deprecated spelling still works
        EXPECT_EQ(parse(c, {"-o", "y"}), std::nullopt);
        EXPECT_EQ(c.out.getValue(), "y");
    }
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"--help"}, {"--version"}, {"--out-dir", "x", "--help"}}) {
        TCmd c;
        testing::internal::CaptureStdout();
        EXPECT_EQ(parse(c, args), 0) << args[0];
        testing::internal::GetCapturedStdout();
    }
    for (const auto& args :
         std::vector<std::vector<std::string>>{{},
                                               {"--out-dir", "x", "--bogus"},
                                               {"--out-dir", "x", "--seed", "-3"},
                                               {"--out-dir", "x", "--seed", "abc"},
                                               {"--out-dir", "x", "--seed", "1.5"},
                                               {"--out-dir", "x", "--gain", "nan"},
                                               {"--out-dir", "x", "--gain", "11"},
                                               {"--out-dir", "x", "--seed"}}) {
        TCmd c;
        testing::internal::CaptureStderr();
        testing::internal::CaptureStdout();
        EXPECT_EQ(parse(c, args), kUsageExitCode) << (args.empty() ? "" : args.back());
        const std::string err = testing::internal::GetCapturedStderr();
        testing::internal::GetCapturedStdout();
        if (args.size() == 4) {  // a bad value: the message names the option
            EXPECT_NE(err.find(args[2]), std::string::npos) << err;
        }
    }
}

TEST(Cli, StartFoldsThreeTokensOrKeepsOneQuoted) {
    std::vector<std::string> a = {"p", "--start", "1", "-2", "0.5", "--seed", "3"};
    foldOptionValues(a, "--start", 3);
    EXPECT_EQ(a, (std::vector<std::string>{"p", "--start", "1 -2 0.5", "--seed", "3"}));
    std::vector<std::string> b = {"p", "--start", "1 -2 0.5", "--seed", "3"};
    foldOptionValues(b, "--start", 3);
    EXPECT_EQ(b, (std::vector<std::string>{"p", "--start", "1 -2 0.5", "--seed", "3"}));
    std::vector<std::string> c = {"p", "--start", "1", "2"};
    EXPECT_THROW(foldOptionValues(c, "--start", 3), CUsageError);
}

namespace {
/** parseCommandLine on `cmd`; the exit code (-1: run) and what went to stderr. */
std::pair<int, std::string> outcome(TCLAP::CmdLine& cmd, std::vector<std::string> args) {
    args.insert(args.begin(), "prog");
    testing::internal::CaptureStderr();
    testing::internal::CaptureStdout();
    const auto code = parseCommandLine(cmd, args);
    const std::string err = testing::internal::GetCapturedStderr();
    testing::internal::GetCapturedStdout();
    return {code.value_or(-1), err};
}
}  // namespace

TEST(Cli, NoArgumentPrintsTheUsage) {
    // Also for a program whose every option is optional (rfir-bench).
    TCLAP::CmdLine cmd("test", ' ', RFIR_VERSION);
    TCLAP::SwitchArg quick("", "quick", "quick", cmd);
    const auto [code, err] = outcome(cmd, {});
    EXPECT_EQ(code, kUsageExitCode);
    EXPECT_NE(err.find("usage:"), std::string::npos) << err;
    EXPECT_NE(err.find("[--quick]"), std::string::npos) << err;
    EXPECT_NE(err.find("prog --help"), std::string::npos) << err;
}

TEST(Cli, ListsConfigsAndSubcommandsAreCheckedWhileParsing) {
    {
        TCLAP::CmdLine cmd("test", ' ', RFIR_VERSION);
        CNumberListArg<double> start("", "start", "pose", false, "X Y PHI", cmd, ' ', 3);
        CConfigArg config("", "config", "INI", false, cmd, "slam_");
        EXPECT_EQ(outcome(cmd, {"--start", "1 -2 0.5", "--config", "slam_ps"}).first, -1);
        EXPECT_EQ(start.values(), (std::vector<double>{1, -2, 0.5}));
        EXPECT_EQ(std::filesystem::path(config.getValue()),
                  std::filesystem::path(stockConfigDir()) / "slam_ps.ini");
    }
    const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
        {{"--start", "1 2"}, "--start: expected 3 number(s)"},
        {{"--start", "1 2 nan"}, "--start: 'nan' is not a finite number"},
        {{"--config", "no_such"}, "--config: 'no_such' is no INI file and no stock INI"},
        {{"--config", "no_such"}, "slam_ps"},  // the stock INIs of that prefix
        {{"--config", "./slam_ps.ini"}, "--config"}};
    for (const auto& [args, said] : bad) {
        TCLAP::CmdLine cmd("test", ' ', RFIR_VERSION);
        CNumberListArg<double> start("", "start", "pose", false, "X Y PHI", cmd, ' ', 3);
        CConfigArg config("", "config", "INI", false, cmd, "slam_");
        const auto [code, err] = outcome(cmd, args);
        EXPECT_EQ(code, kUsageExitCode) << args[1];
        EXPECT_NE(err.find(said), std::string::npos) << err;
    }
    for (const auto& [args, said] :
         std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"plan"}, ""},
             {{"bogus"}, "unknown command 'bogus' (encode, plan)"},
             {{"--bogus"}, "--bogus: Couldn't find match"},
             {{"plan", "--bogus"}, "--bogus"}}) {
        TCLAP::CmdLine cmd("test", ' ', RFIR_VERSION);
        CSubcommandArg command("command", {"encode", "plan"}, cmd);
        const auto [code, err] = outcome(cmd, args);
        EXPECT_EQ(code, said.empty() ? -1 : kUsageExitCode) << args[0];
        EXPECT_NE(err.find(said), std::string::npos) << err;
        if (said.empty()) EXPECT_EQ(command.getValue(), "plan");
    }
}

namespace {
/** A loader of one section [s] with an integer key k in [0, 9], as the
 * programs' loaders check theirs. */
void loadTestIni(const std::string& text, const std::vector<std::string>& edits) {
    rfir::ini::CIniFile f("/some/dir/test.ini", text);
    applyIniOverrides(f, edits);
    rfir::ini::checkSections(f, {"s"});
    rfir::ini::CIniSection(f, "s", {"k"}).getInt("k", 1, 0, 9);
}

std::string blame(const std::string& text, const std::vector<std::string>& edits) {
    try {
        loadWithIniEdits(
            edits, [&](const std::vector<std::string>& e) { loadTestIni(text, e); });
    } catch (const CUsageError& e) {
        return std::string("usage: ") + e.what();
    } catch (const std::exception& e) {
        return std::string("file: ") + e.what();
    }
    return "loaded";
}
}  // namespace

TEST(Cli, IniEditsTheIniRefusesAreTheCommandLines) {
    EXPECT_EQ(blame("[s]\nk = 3\n", {"s.k=4"}), "loaded");
    // A value from the command line: named as the edit, not as the file's.
    EXPECT_EQ(blame("[s]\nk = 3\n", {"s.k=4", "s.k=abc", "s.k=99"}),
              "usage: --set s.k=abc: [s] k: expected an integer, got 'abc'");
    EXPECT_EQ(blame("[s]\nk = 3\n", {"t.k=1"}).rfind("usage: --set t.k=1: [t]: ", 0), 0u);
    EXPECT_EQ(blame("[s]\nk = 3\n", {"s.j=1"}).rfind("usage: --set s.j=1: [s] j: ", 0),
              0u);
    EXPECT_EQ(blame("[s]\nk = 3\n", {"sk=1"}),
              "usage: --set sk=1: expected section.key=value");
    // The file's own error stays the file's, edits or not (an edit of the
    // bad key itself replaces the file's value).
    for (const auto& edits :
         std::vector<std::vector<std::string>>{{}, {"s.k=4"}, {"s.k=abc"}})
        EXPECT_EQ(blame("[s]\nk = 3\nj = 1\n", edits)
                      .rfind("file: /some/dir/test.ini: [s] j: unknown key", 0),
                  0u);
    EXPECT_EQ(blame("[s]\nk = x\n", {"s.k=4"}), "loaded");
}

TEST(Cli, StockIniByBareName) {
    namespace fs = std::filesystem;
    const fs::path stock = fs::path(stockConfigDir()) / "slam_ps.ini";
    ASSERT_TRUE(fs::exists(stock)) << stock;
    EXPECT_EQ(fs::path(resolveConfigFile("slam_ps.ini")), stock);
    EXPECT_EQ(fs::path(resolveConfigFile("slam_ps")), stock);
    // A path is a path; an unknown name is left for the loader to report.
    EXPECT_EQ(resolveConfigFile("./slam_ps.ini"), "./slam_ps.ini");
    EXPECT_EQ(resolveConfigFile("no_such_config"), "no_such_config");
}

TEST(Cli, IniEditsAreSplitOnce) {
    const TIniEdit e = parseIniEdit("MetricMap_x.y.key=a=b");
    EXPECT_EQ(e.section, "MetricMap_x.y");
    EXPECT_EQ(e.key, "key");
    EXPECT_EQ(e.value, "a=b");
    for (const char* bad : {"slam_particles=5", ".k=1", "slam.=1", "slam.k", ""})
        EXPECT_THROW(parseIniEdit(bad), CUsageError) << bad;
    mrpt::config::CConfigFileMemory ini;
    applyIniOverrides(ini, {"slam.robot_particles=50", "slam.robot_particles=60"});
    EXPECT_EQ(ini.read_int("slam", "robot_particles", 0), 60);  // the last one wins
}

TEST(Cli, IniEditsAreRoutedBySection) {
    const std::vector<TIniKind> kinds = {
        {"sim", "simulation INIs", {"trajectory", "kidnap", "odometry"}},
        {"slam", "SLAM INIs", {"slam", "kidnap", "motion"}}};
    const auto r = routeIniEdits(
        kinds, {"slam.robot_particles=200", "trajectory.speed=0.3", "sim:kidnap.time=5",
                "slam:kidnap.enabled=false", "motion.a1=0.1"});
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0], (std::vector<std::string>{"trajectory.speed=0.3", "kidnap.time=5"}));
    EXPECT_EQ(r[1], (std::vector<std::string>{"slam.robot_particles=200",
                                              "kidnap.enabled=false", "motion.a1=0.1"}));
    EXPECT_TRUE(routeIniEdits(kinds, {})[0].empty());
    auto message = [&](const std::string& edit) {
        try {
            routeIniEdits(kinds, {"slam.robot_particles=1", edit});
        } catch (const CUsageError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    // Each names the edit and what is wrong with it.
    EXPECT_NE(message("nosuch.k=1").find("[nosuch]: unknown section"), std::string::npos);
    EXPECT_NE(message("kidnap.enabled=true")
                  .find("sim:kidnap.enabled=true or "
                        "slam:kidnap.enabled=true"),
              std::string::npos);
    EXPECT_NE(message("sim:slam.robot_particles=1").find("[slam]: unknown section"),
              std::string::npos);
    EXPECT_NE(message("ir:trajectory.speed=1").find("no INI kind 'ir:'"),
              std::string::npos);
    EXPECT_NE(message("slam_particles=5").find("--set slam_particles=5:"),
              std::string::npos);
    EXPECT_NE(message("slam_particles=5").find("expected section.key=value"),
              std::string::npos);
}

TEST(Cli, StockSlamIniAndRawlogStem) {
    using rfir::common::rawlogStem;
    using rfir::common::slamIniPath;
    EXPECT_EQ(slamIniPath("d", "ps"), "d/slam_ps.ini");
    EXPECT_EQ(slamIniPath("d", "fastslam"), "d/slam_fastslam.ini");
    EXPECT_EQ(slamIniPath("d", "pf"), "d/slam_pf.ini");
    EXPECT_EQ(slamIniPath("d", "rb"), "d/slam_pf.ini");  // no INI of its own
    EXPECT_EQ(slamIniPath("ps"), rfir::common::stockConfigDir() + "/slam_ps.ini");
    EXPECT_EQ(rawlogStem("a/run.rawlog"), "a/run");
    EXPECT_EQ(rawlogStem("a/run.rawlog.gz"), "a/run");
    EXPECT_EQ(rawlogStem("a/run.txt"), "a/run.txt");
    EXPECT_EQ(rawlogStem(".rawlog"), ".rawlog");  // no stem: left as it is
}
