/* rfir-experiments: the papers' experiments: each row simulates its
 * data sets (rfir_sim), runs PS-SLAM, PF-SLAM, FastSLAM and dead reckoning on
 * the same data (rfir_slam), scores them (rfir_eval) and aggregates over seeds
 * into results.json, results.md and img/exp_*.png. A row on one seed is one
 * run: in this process, on --jobs processes, or as the lines of --manifest
 * for GNU parallel or a Slurm array, gathered by --merge (rfir_experiments). */
#include <rfir/experiments/sweep.h>

#include <rfir/common/cli.h>
#include <rfir/common/install_paths.h>
#include <rfir/common/text_input.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/filesystem.h>

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

using namespace rfir::experiments;

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::vector<TRow> selectRows(const std::string& list, bool quick) {
    auto rows = allRows(quick);
    if (list.empty() || list == "all") return rows;
    std::set<std::string> want;
    std::stringstream ss(list);
    for (std::string s; std::getline(ss, s, ',');)
        if (!s.empty()) want.insert(s);
    std::vector<TRow> out;
    for (const auto& r : rows)
        if (want.erase(r.id)) out.push_back(r);
    if (!want.empty())
        throw rfir::common::CUsageError("--rows: unknown row '" + *want.begin() +
                                        "' (see --list)");
    return out;
}

/** --run ROW:SEED: the row (of allRows(quick)) and the seed. */
std::pair<TRow, uint64_t> parseRun(const std::string& v, bool quick) {
    const auto colon = v.rfind(':');
    const auto seed = colon == std::string::npos
                          ? std::nullopt
                          : rfir::common::parseNumber<uint64_t>(v.substr(colon + 1));
    if (!seed) throw rfir::common::CUsageError("--run: '" + v + "' is not ROW:SEED");
    for (const auto& r : allRows(quick))
        if (r.id == v.substr(0, colon)) return {r, *seed};
    throw rfir::common::CUsageError("--run: unknown row '" + v.substr(0, colon) +
                                    "' (see --list)");
}

/** Of the options, at most one may be given. */
void atMostOne(const std::vector<std::pair<const TCLAP::Arg*, const char*>>& given) {
    std::vector<const char*> set;
    for (const auto& [arg, name] : given)
        if (arg->isSet()) set.push_back(name);
    if (set.size() > 1)
        throw rfir::common::CUsageError(std::string(set[0]) + " and " + set[1] +
                                        " do not go together");
}

/** What the command line asks for. */
struct TArgs {
    std::vector<TRow> rows;
    TSetup setup;
    TMeta meta;
    std::string out, notes, merge;
    bool list = false, manifest = false, runOne = false, figures = true, quiet = false;
};

/** The options (TCLAP registers each with cmd as it is built). */
struct TCli {
    template <typename T>
    using CNumberArg = rfir::common::CNumberArg<T>;
    TCLAP::CmdLine cmd{
        "rfir-experiments: runs the experiment rows of the papers' tables and figures "
        "(PS-SLAM, PF-SLAM, FastSLAM and dead reckoning on the same simulated data, "
        "several seeds each) and writes OUT/results.json (every raw number), "
        "OUT/timings.json (the times), OUT/results.md (tables beside the papers' "
        "numbers) and OUT/img/exp_*.png. A row on one seed is one run: --jobs N runs "
        "them on N processes; --manifest prints one command per run (for GNU "
        "parallel or a Slurm array) and --merge gathers their folders.",
        ' ', RFIR_VERSION};
    TCLAP::ValueArg<std::string> rows{
        "",    "rows", "comma-separated row ids (default: all; see --list)", false, "all",
        "IDS", cmd};
    TCLAP::SwitchArg list{"", "list", "list the rows and exit", cmd};
    CNumberArg<unsigned> seeds{"",    "seeds", "seeds per row (default 8, --quick 1)",
                               false, 0,       "N",
                               cmd,   1,       100000};
    CNumberArg<uint64_t> firstSeed{
        "", "seed", "first seed: seeds are S, S+1, ... (default 1)", false, 1, "S", cmd};
    TCLAP::SwitchArg quick{
        "", "quick", "tiny runs: first sub-run, sweep end points, 40 s of simulated time",
        cmd};
    TCLAP::ValueArg<std::string> out{
        "",
        "out-dir",
        "output folder (required unless --list); with --manifest, the folder the runs "
        "write into (DIR/ROW/seedS); with --run, the run's folder",
        false,
        "",
        "DIR",
        cmd};
    CNumberArg<unsigned> jobs{
        "",
        "jobs",
        "run the rows and seeds on N processes (default 1); the results are the same",
        false,
        1,
        "N",
        cmd,
        1,
        1024};
    TCLAP::SwitchArg manifest{
        "", "manifest",
        "print one command per run (a row on one seed) on stdout, each writing under "
        "--out-dir, and do nothing else: for GNU parallel or a Slurm array",
        cmd};
    TCLAP::ValueArg<std::string> merge{
        "",
        "merge",
        "gather the run folders the manifest's commands wrote in DIR (give the sweep "
        "options given to --manifest) into --out-dir's results",
        false,
        "",
        "DIR",
        cmd};
    TCLAP::ValueArg<std::string> runOne{
        "",
        "run",
        "run one row on one seed and write its folder (run.json) to --out-dir, for "
        "--merge (the lines of --manifest)",
        false,
        "",
        "ROW:SEED",
        cmd};
    TCLAP::ValueArg<std::string> cfgDir{
        "",
        "config-dir",
        "folder of the sim_*.ini and slam_*.ini (default: the installed stock INIs)",
        false,
        rfir::common::stockConfigDir(),
        "DIR",
        cmd};
    TCLAP::ValueArg<std::string> notes{
        "", "notes", "markdown inserted in results.md", false, "", "FILE", cmd};
    TCLAP::ValueArg<std::string> revision{
        "",    "revision", "source revision to record in the report (e.g. git describe)",
        false, "",         "TEXT",
        cmd};
    TCLAP::SwitchArg noFig{"", "no-figures", "do not draw the PNG figures", cmd};
    TCLAP::MultiArg<std::string> sets{
        "",
        "set",
        "override an INI key in every INI of the run, after the rows' own edits: a "
        "simulation INI's (e.g. trajectory.speed=0.3) or a SLAM INI's (e.g. "
        "slam.robot_particles=200); [kidnap] is in both: sim:kidnap.KEY=VALUE or "
        "slam:kidnap.KEY=VALUE (repeatable)",
        false,
        "SECTION.KEY=VALUE",
        cmd};
    TCLAP::SwitchArg quiet{"q", "quiet", rfir::common::kQuietHelp, cmd};
};

/** Reads the command line into `a`, every check before any work: std::nullopt
 * to go on, else the exit code (--help, or 2 after a usage error). */
std::optional<int> parseArgs(int argc, char** argv, TArgs& a) {
    TCli c;
    if (const auto code = rfir::common::parseCommandLine(
            c.cmd, argc, argv, {{"--out", "--out-dir"}, {"--first-seed", "--seed"}}))
        return code;

    atMostOne({{&c.list, "--list"},
               {&c.runOne, "--run"},
               {&c.manifest, "--manifest"},
               {&c.merge, "--merge"},
               {&c.jobs, "--jobs"}});
    a.meta.quick = c.quick.getValue();
    a.meta.sets = c.sets.getValue();
    a.meta.jobs = c.merge.isSet() ? 0 : c.jobs.getValue();
    a.meta.revision = c.revision.getValue();
    if (c.runOne.isSet()) {
        for (const auto& [arg, name] :
             std::vector<std::pair<const TCLAP::Arg*, const char*>>{
                 {&c.rows, "--rows"}, {&c.seeds, "--seeds"}, {&c.firstSeed, "--seed"}})
            atMostOne({{&c.runOne, "--run"}, {arg, name}});
        const auto [row, seed] = parseRun(c.runOne.getValue(), c.quick.getValue());
        a.rows = {row};
        a.meta.seeds = {seed};
    } else {
        a.rows = selectRows(c.rows.getValue(), c.quick.getValue());
        const unsigned n = c.seeds.isSet()      ? c.seeds.getValue()
                           : c.quick.getValue() ? 1
                                                : 8;
        for (unsigned i = 0; i < n; i++)
            a.meta.seeds.push_back(c.firstSeed.getValue() + i);
    }
    a.out = c.out.getValue(), a.notes = c.notes.getValue(), a.merge = c.merge.getValue();
    a.list = c.list.getValue(), a.manifest = c.manifest.getValue(),
    a.runOne = c.runOne.isSet();
    a.figures = !c.noFig.getValue(), a.quiet = c.quiet.getValue();
    if (!a.list && a.out.empty())
        throw rfir::common::CUsageError("--out-dir DIR is required");
    if (c.notes.isSet() && !mrpt::system::fileExists(a.notes))
        throw rfir::common::CUsageError("--notes: cannot read '" + a.notes + "'");
    if (c.merge.isSet() && !mrpt::system::directoryExists(a.merge))
        throw rfir::common::CUsageError("--merge: no folder '" + a.merge + "'");
    rfir::common::checkFolderOption("--config-dir", c.cfgDir.getValue());
    a.setup = makeSetup(c.cfgDir.getValue(), c.sets.getValue());
    // Every INI with every edit, before hours of work (an INI's own error
    // passes on: exit 1 naming the file).
    if (!a.list) checkConfigs(a.setup, a.rows);
    a.meta.commandLine = sweepCommand(a.rows, a.meta);
    for (int i = 0; i < argc; i++)
        a.meta.invocation +=
            (i ? " " + std::string(argv[i]) : mrpt::system::extractFileName(argv[0]));
    return std::nullopt;
}

/** OUT/.runs.<pid> folders of earlier sweeps killed before their end. */
void removeStaleScratch(const std::string& out) {
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(out, ec)) {
        const std::string n = e.path().filename().string();
        const auto pid =
            rfir::common::parseNumber<int>(n.substr(std::min<size_t>(6, n.size())));
        if (n.rfind(".runs.", 0) == 0 && pid && *pid > 0 && ::kill(*pid, 0) != 0 &&
            errno == ESRCH)
            std::filesystem::remove_all(e.path(), ec);
    }
}

/** A scratch folder removed when it goes out of scope. */
struct TScratch {
    std::string dir;
    ~TScratch() {
        std::error_code ec;
        if (!dir.empty()) std::filesystem::remove_all(dir, ec);
    }
};

/** The sweep's runs (or, with --merge, their folders) into the reports. */
void runSweep(TArgs& a) {
    const std::string notes =
        a.notes.empty() ? "" : rfir::common::readSmallTextFile(a.notes, "--notes");
    const auto t0 = Clock::now();
    std::string runsDir = a.merge;
    TScratch scratch;
    if (a.merge.empty()) {
        // The runs' folders go to a scratch folder in OUT, removed after.
        runsDir = scratch.dir = a.out + "/.runs." + std::to_string(::getpid());
        removeStaleScratch(a.out);
        std::error_code ec;
        std::filesystem::remove_all(runsDir, ec);
        std::filesystem::create_directories(runsDir, ec);  // fail before the work
        if (ec || !mrpt::system::directoryExists(runsDir))
            throw std::runtime_error("cannot create the folder '" + runsDir + "'");
        runAll(a.rows, a.setup, a.meta, a.figures, runsDir, a.meta.jobs, a.quiet);
    }
    const auto results = loadRuns(runsDir, a.rows, a.setup, a.meta);
    a.meta.wallSeconds = since(t0);
    writeReports(a.out, runsDir, results, a.meta, notes, a.figures);
    if (!a.quiet)
        std::cerr << "rfir-experiments: wrote " << a.out
                  << "/results.md, results.json, timings.json"
                  << (a.figures ? ", img/exp_*.png" : "") << "\n";
}
}  // namespace

int main(int argc, char** argv) {
    try {
        TArgs a;
        try {  // usage errors: exit as a parse error does
            if (const auto code = parseArgs(argc, argv, a)) return *code;
            if (a.manifest) {
                std::string lines;  // whole, or nothing on an error
                for (const auto& r : sweepRuns(a.rows, a.meta.seeds))
                    lines +=
                        shellLine(runArgs(a.setup, a.meta, r, a.figures, a.out)) + "\n";
                if (!a.quiet) std::cout << lines;
                return 0;
            }
        } catch (const rfir::common::CUsageError& e) {
            std::cerr << "rfir-experiments: error: " << e.what() << "\n";
            return rfir::common::kUsageExitCode;
        }
        if (a.list) {
            if (a.quiet) return 0;
            for (const auto& r : allRows(false))
                std::cout << r.id << "\t" << r.source << ": " << r.title << "\n";
            return 0;
        }
        if (a.runOne)
            runToFolder(a.setup, a.meta, a.rows[0], a.meta.seeds[0], a.figures, a.out,
                        a.quiet ? nullptr : stderr);
        else
            runSweep(a);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "rfir-experiments: error: " << e.what() << "\n";
        return 1;
    }
}
