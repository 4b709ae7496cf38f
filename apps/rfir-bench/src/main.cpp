/* rfir-bench: time per SLAM update of PS-SLAM, PF-SLAM and FastSLAM against
 * the robot particles M and the mapped tags N, their memory, a floor loop, and
 * whole offline runs against real time. See docs/benchmark.md. */
#include <rfir/bench/bench.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/cli.h>
#include <rfir/common/ini_override.h>
#include <rfir/common/install_paths.h>
#include <rfir/sim/simulator.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

namespace {
using namespace rfir::bench;

std::string defaultConfigDir() {
    const std::string installed = rfir::common::stockConfigDir();
    if (mrpt::system::fileExists(installed + "/slam_ps.ini")) return installed;
    return std::string(RFIR_SOURCE_DIR) + "/config_ini";
}

std::string hostDescription() {
    std::ifstream f("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(f, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
}

double loadAverage() {
    std::ifstream f("/proc/loadavg");
    double l = 0;
    f >> l;
    return l;
}

std::vector<std::string> parseMethods(const std::string& s) {
    std::vector<std::string> v;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ',')) {
        if (item != "ps" && item != "pf" && item != "fastslam")
            throw rfir::common::CUsageError("--methods: '" + item +
                                            "' is not ps, pf or fastslam");
        v.push_back(item);
    }
    if (v.empty()) throw rfir::common::CUsageError("--methods: empty list");
    return v;
}

bool skipped(const TCaseResult& c) {
    return c.skipped;
}
bool skipped(const TFloorResult&) {
    return false;
}

/** v[i] keeps the fastest (median) of the rounds of one case or floor. */
template <typename T>
void keepFastest(std::vector<T>& v, size_t i, const T& c) {
    if (i >= v.size())
        v.push_back(c);
    else if (!skipped(c) && c.medianUs < v[i].medianUs)
        v[i] = c;
}

void runAll(TBenchReport& r, bool quiet) {
    const auto& o = r.options;
    auto progress = [quiet](const std::string& s) {
        if (!quiet) std::cerr << "rfir-bench: " << s << std::endl;
    };
    std::vector<size_t> floorM = o.sweepM;
    if (std::find(floorM.begin(), floorM.end(), o.fixedM) == floorM.end())
        floorM.push_back(o.fixedM);
    // Several rounds, each case and the floor keeping their fastest round: a
    // shared machine slows whole stretches of a run (other jobs on the other
    // core share the caches and the memory bus), so the rounds are spread over
    // time, and the floor is measured the same way as the figures it divides.
    for (size_t round = 0; round < o.rounds; round++) {
        const std::string tag =
            " (round " + std::to_string(round + 1) + "/" + std::to_string(o.rounds) + ")";
        for (size_t k = 0; k < floorM.size(); k++)
            keepFastest(r.floor, k, runFloor(o, floorM[k]));
        size_t i = 0;
        for (size_t M : o.sweepM)
            for (const auto& m : o.methods) {
                progress(m + " M=" + std::to_string(M) +
                         " N=" + std::to_string(o.fixedN) + tag);
                keepFastest(r.sweepM, i++, runCase(o, m, M, o.fixedN));
            }
        i = 0;
        for (size_t N : o.sweepN)
            for (const auto& m : o.methods) {
                progress(m + " M=" + std::to_string(o.fixedM) +
                         " N=" + std::to_string(N) + tag);
                keepFastest(r.sweepN, i++, runCase(o, m, o.fixedM, N));
            }
    }
    if (!o.realtime) return;
    progress("whole runs (simulating " + std::to_string(int(o.realtimeSeconds)) + " s)");
    std::vector<std::pair<std::string, size_t>> runs;
    for (const auto& m : o.methods) runs.push_back({m, 100});
    for (const auto& m : o.methods) runs.push_back({m, 500});
    r.realtime = runRealtime(o, runs);
    progress("side by side with the plain reference");
    r.plain = runPlainCompare(o);
    progress("whole rfir-slam processes");
    r.process = runProcesses(o);
}

/** The --set edits into o (by section), checked by loading every INI the
 * bench reads with them: a bad edit is a command-line error naming it, before
 * any work; an INI's own error names its file. */
void setEdits(TBenchOptions& o, const std::vector<std::string>& sets) {
    const auto split = rfir::common::routeIniEdits(
        {{"slam", "SLAM INIs", rfir::slam::slamConfigSections()},
         {"sim", "simulation INI", rfir::sim::simConfigSections()}},
        sets);
    for (const auto& e : split[0])
        if (rfir::common::parseIniEdit(e).section == "slam" &&
            rfir::common::parseIniEdit(e).key == "robot_particles")
            throw rfir::common::CUsageError("--set " + e +
                                            ": the robot particles are what the bench "
                                            "varies; give them with --m");
    o.sets = sets;
    o.simSets = split[1];
    rfir::common::loadWithIniEdits(split[0], [&](const std::vector<std::string>& e) {
        TBenchOptions c = o;
        c.slamSets = e;
        for (const auto& m : c.methods) benchConfig(c, m, c.fixedM);
    });
    o.slamSets = split[0];
    // Also under --no-realtime: a bad edit is an error whether used or not.
    rfir::common::loadWithIniEdits(split[1], [&](const std::vector<std::string>& e) {
        rfir::sim::loadSimConfig(o.configDir + "/bench_floor_30x20.ini", e);
    });
}

/** --quick: a smoke run of seconds. */
void setQuick(TBenchOptions& o) {
    o.quick = true;
    o.sweepM = {100, 500};
    o.sweepN = {10, 1000};
    o.timedUpdates = 20;
    o.warmupUpdates = 4;
    o.realtimeSeconds = 60;
    o.rounds = 1;
    o.compareSeconds = 30;
    o.compareM = {500};
}

struct TOutputs {
    std::string json, markdown, plots;
    bool quiet = false;
};

/** The command line; an exit code after --help, --version or an error. */
std::optional<int> parseArgs(int argc, char** argv, TBenchOptions& o, TOutputs& out) {
    TCLAP::CmdLine cmd(
        "rfir-bench: time per SLAM update of PS-SLAM, PF-SLAM and FastSLAM against the "
        "number of robot particles M and of mapped tags N, the state's memory, a floor "
        "loop, and a whole 20-minute offline run against real time. Prints a table; "
        "optionally writes JSON, Markdown and PNG plots. Single thread; fixed seeds. "
        "Give --quick (seconds) or --full (the whole sweeps: more than 10 minutes).",
        ' ', RFIR_VERSION);
    TCLAP::SwitchArg quick("", "quick", "smoke run: M 100,500; N 10,1000; 20 updates",
                           cmd);
    TCLAP::SwitchArg full(
        "", "full",
        "the whole benchmark: M 100..10000, N 10..1000000 (more than 10 "
        "minutes; docs/benchmark.md)",
        cmd);
    TCLAP::ValueArg<std::string> outDir(
        "", "out-dir",
        "write DIR/benchmark.json, DIR/results.md and DIR/bench_*.png (created)", false,
        "", "DIR", cmd);
    TCLAP::ValueArg<std::string> json("", "json", "write JSON", false, "", "FILE", cmd);
    TCLAP::ValueArg<std::string> md("", "markdown", "write Markdown tables", false, "",
                                    "FILE", cmd);
    TCLAP::ValueArg<std::string> plots("", "plots", "write bench_*.png there", false, "",
                                       "DIR", cmd);
    rfir::common::CNumberListArg<size_t> ms("", "m", "robot particle counts", false,
                                            "LIST", cmd, ',', 0, 1);
    rfir::common::CNumberListArg<size_t> ns("", "n", "mapped tag counts", false, "LIST",
                                            cmd, ',', 0, 8);
    using rfir::common::CNumberArg;
    CNumberArg<size_t> updates("", "updates", "timed updates per case (200)", false, 200,
                               "K", cmd, 1);
    CNumberArg<size_t> rounds("", "rounds", "rounds; each case keeps its fastest (3)",
                              false, 3, "R", cmd, 1);
    CNumberArg<double> maxMN("", "max-fastslam-mn", "skip FastSLAM above this M*N (5e7)",
                             false, 5e7, "X", cmd, 0);
    CNumberArg<double> rtSec("", "realtime-seconds",
                             "robot time of the whole runs (1200)", false, 1200, "S", cmd,
                             1e-3);
    TCLAP::ValueArg<std::string> methods("", "methods", "subset of ps,pf,fastslam", false,
                                         "", "LIST", cmd);
    TCLAP::SwitchArg noRealtime("", "no-realtime", "skip the whole offline runs", cmd);
    TCLAP::ValueArg<std::string> cfgDir("", "config-dir", "folder of the stock INIs",
                                        false, "", "DIR", cmd);
    CNumberArg<uint64_t> seed("", "seed", "random seed (1)", false, 1, "N", cmd);
    TCLAP::MultiArg<std::string> sets(
        "", "set",
        "override an INI key, after the bench's own: a SLAM INI's (e.g. "
        "tagmap.particles_per_tag=50; not slam.robot_particles: see --m) or the "
        "whole runs' simulation INI's (e.g. trajectory.speed=0.3); [kidnap] is in "
        "both: sim:kidnap.KEY=VALUE or slam:kidnap.KEY=VALUE (repeatable)",
        false, "SECTION.KEY=VALUE", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", rfir::common::kQuietHelp, cmd);
    if (const auto code = rfir::common::parseCommandLine(cmd, argc, argv)) return code;

    if (quick.getValue() == full.getValue())
        throw rfir::common::CUsageError(
            quick.getValue() ? "--quick and --full: give one"
                             : "give --quick (a smoke run of seconds) or --full (the "
                               "whole benchmark, more than 10 minutes)");
    if (quick.getValue()) setQuick(o);
    if (rounds.isSet()) o.rounds = rounds.getValue();
    if (ms.isSet()) o.sweepM = ms.values();
    if (ns.isSet()) o.sweepN = ns.values();
    if (updates.isSet()) o.timedUpdates = updates.getValue();
    if (rtSec.isSet()) o.realtimeSeconds = rtSec.getValue();
    if (!(o.realtimeSeconds > 0))
        throw rfir::common::CUsageError("--realtime-seconds must be > 0");
    o.maxFastSlamMN = maxMN.getValue();
    if (methods.isSet()) o.methods = parseMethods(methods.getValue());
    o.realtime = !noRealtime.getValue();
    o.seed = seed.getValue();
    o.configDir = cfgDir.isSet() ? cfgDir.getValue() : defaultConfigDir();
    if (cfgDir.isSet()) rfir::common::checkFolderOption("--config-dir", o.configDir);
    setEdits(o, sets.getValue());  // before --out-dir is created
    out = {json.getValue(), md.getValue(), plots.getValue(), quiet.getValue()};
    if (outDir.isSet()) {
        const std::string d = outDir.getValue();
        if (!mrpt::system::directoryExists(d) && !mrpt::system::createDirectory(d))
            throw rfir::common::CUsageError("--out-dir: cannot create '" + d + "'");
        if (out.json.empty()) out.json = d + "/benchmark.json";
        if (out.markdown.empty()) out.markdown = d + "/results.md";
        if (out.plots.empty()) out.plots = d;
    }
    if (!out.plots.empty() && !mrpt::system::directoryExists(out.plots))
        throw rfir::common::CUsageError("--plots: no folder '" + out.plots + "'");
    return std::nullopt;
}
}  // namespace

int main(int argc, char** argv) {
    try {
        TBenchReport r;
        TOutputs out;
        try {
            if (const auto code = parseArgs(argc, argv, r.options, out)) return *code;
        } catch (const rfir::common::CUsageError& e) {  // a bad value: before any work
            std::cerr << "rfir-bench: error: " << e.what() << "\n";
            return rfir::common::kUsageExitCode;
        }
        r.host = hostDescription();
        r.loadBefore = loadAverage();
        runAll(r, out.quiet);
        r.loadAfter = loadAverage();
        evaluate(r);
        if (!out.quiet) printTable(r, std::cout);
        using rfir::common::writeFileAtomically;
        if (!out.json.empty())
            writeFileAtomically(out.json, [&](std::ostream& f) { f << toJson(r); });
        if (!out.markdown.empty())
            writeFileAtomically(out.markdown,
                                [&](std::ostream& f) { f << toMarkdown(r); });
        if (!out.plots.empty()) writePlots(r, out.plots);
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "rfir-bench: error: " << e.what() << "\n";
        return 1;
    }
}
