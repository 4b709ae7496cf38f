/* rfir-experiments: a sweep's runs, how each runs on its own (in this process,
 * as a child process, or from a manifest line), and the reports from their
 * folders. */
#include <rfir/experiments/process_pool.h>
#include <rfir/experiments/report.h>
#include <rfir/experiments/sweep.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/output_set.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace rfir::experiments {
namespace {
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/** This program, by absolute path (the runs' commands start it again). */
std::string selfPath() {
    std::error_code ec;
    const auto p = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw std::runtime_error("cannot find this program's path (/proc/self/exe)");
    return p.string();
}

std::string progressLine(size_t k, size_t n, const TSweepRun& r, double seconds) {
    char t[32];
    std::snprintf(t, sizeof t, "%.1f", seconds);
    return "[" + std::to_string(k) + "/" + std::to_string(n) + "] " + runName(r) + ": " +
           t + " s\n";
}

/** The first-seed figures of every row, from their run folders. */
void copyFirstSeedFigures(const std::string& runsDir, const std::vector<TSweepRun>& runs,
                          rfir::common::COutputFiles& img) {
    for (const auto& r : runs) {
        if (!r.first) continue;
        for (const auto& n : firstSeedFigureNames(*r.row)) {
            const std::string from = runFolder(runsDir, r) + "/" + n;
            if (!fs::is_regular_file(from))
                throw std::runtime_error("run " + runName(r) + ": no figure " + from +
                                         " (its command had --no-figures: merge with "
                                         "--no-figures, or rerun it "
                                         "without)");
            fs::copy_file(from, img.file(n));
        }
    }
}
}  // namespace

std::vector<TSweepRun> sweepRuns(const std::vector<TRow>& rows,
                                 const std::vector<uint64_t>& seeds) {
    std::vector<TSweepRun> v;
    for (const auto& row : rows)
        for (size_t i = 0; i < seeds.size() && (!row.maxSeeds || i < row.maxSeeds); i++)
            v.push_back({&row, seeds[i], i == 0});
    return v;
}

std::string runFolder(const std::string& dir, const TSweepRun& run) {
    return dir + "/" + run.row->id + "/seed" + std::to_string(run.seed);
}

std::string runName(const TSweepRun& run) {
    return run.row->id + " seed " + std::to_string(run.seed);
}

std::string sweepCommand(const std::vector<TRow>& rows, const TMeta& meta) {
    std::vector<std::string> a{"rfir-experiments"};
    if (meta.quick) a.push_back("--quick");
    std::string ids;
    for (const auto& r : rows) ids += (ids.empty() ? "" : ",") + r.id;
    const auto all = allRows(meta.quick);
    bool everyRow = rows.size() == all.size();
    for (size_t i = 0; everyRow && i < rows.size(); i++)
        everyRow = rows[i].id == all[i].id;
    if (!everyRow) a.insert(a.end(), {"--rows", ids});
    a.insert(a.end(), {"--seed", std::to_string(meta.seeds.empty() ? 1 : meta.seeds[0]),
                       "--seeds", std::to_string(meta.seeds.size())});
    for (const auto& s : meta.sets) a.insert(a.end(), {"--set", s});
    return shellLine(a);
}

std::vector<std::string> runArgs(const TSetup& setup, const TMeta& meta,
                                 const TSweepRun& run, bool figures,
                                 const std::string& dir) {
    std::vector<std::string> a{selfPath(), "--config-dir",
                               fs::absolute(setup.configDir).lexically_normal().string()};
    if (meta.quick) a.push_back("--quick");
    for (const auto& s : meta.sets) a.insert(a.end(), {"--set", s});
    if (!figures || !run.first) a.push_back("--no-figures");
    a.insert(a.end(), {"--run", run.row->id + ":" + std::to_string(run.seed), "--out-dir",
                       fs::absolute(runFolder(dir, run)).lexically_normal().string()});
    return a;
}

std::string shellLine(const std::vector<std::string>& args) {
    std::string line;
    for (const auto& a : args) {
        if (a.find('\n') != std::string::npos)
            throw std::invalid_argument("a command line argument holds a newline: '" + a +
                                        "'");
        const bool plain =
            !a.empty() && a.find_first_not_of(
                              "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                              "0123456789_-+=/.,:@%") == std::string::npos;
        std::string q = "'";
        for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        line += (line.empty() ? "" : " ") + (plain ? a : q + "'");
    }
    return line;
}

void runAll(const std::vector<TRow>& rows, const TSetup& setup, const TMeta& meta,
            bool figures, const std::string& dir, unsigned jobs, bool quiet) {
    const auto runs = sweepRuns(rows, meta.seeds);
    size_t finished = 0;
    if (jobs <= 1) {
        for (const auto& r : runs) {
            const auto t0 = Clock::now();
            try {
                runToFolder(setup, meta, *r.row, r.seed, figures && r.first,
                            runFolder(dir, r), quiet ? nullptr : stderr);
            } catch (const std::exception& e) {
                throw std::runtime_error("run " + runName(r) + " failed: " + e.what());
            }
            if (!quiet) std::cerr << progressLine(++finished, runs.size(), r, since(t0));
        }
        return;
    }
    std::vector<TChildCommand> cmds;
    for (const auto& r : runs) {
        fs::create_directories(dir + "/" + r.row->id);
        cmds.push_back({"run " + runName(r), runArgs(setup, meta, r, figures, dir),
                        runFolder(dir, r) + ".log"});
    }
    runChildren(cmds, jobs, [&](size_t i, double seconds) {
        if (quiet) return;
        // A run's lines at once, as it ends: runs that end together do not mix.
        std::cerr << fileTail(cmds[i].log, 100000)
                  << progressLine(++finished, runs.size(), runs[i], seconds);
    });
}

void writeReports(const std::string& out, const std::string& runsDir,
                  const std::vector<TRowResults>& results, const TMeta& meta,
                  const std::string& notes, bool figures) {
    std::vector<TRow> rows;
    for (const auto& r : results) rows.push_back(r.row);
    const auto runs = sweepRuns(rows, meta.seeds);
    std::vector<std::string> imgNames;
    for (const auto& r : rows)
        for (const auto& n : figureNames(r)) imgNames.push_back(n.substr(4));  // "img/"
    // Staged, then renamed into place together: no report of a half-written set.
    rfir::common::COutputFiles img(out + "/img",
                                   figures ? imgNames : std::vector<std::string>{});
    rfir::common::COutputFiles top(out, {"results.json", "timings.json", "results.md"});
    if (figures) {
        copyFirstSeedFigures(runsDir, runs, img);
        for (const auto& r : results)
            writeSweepFigures([&](const std::string& n) { return img.file(n); }, r);
    }
    writeJson(top.file("results.json"), results, meta);
    writeTimings(top.file("timings.json"), results, meta);
    const std::string md = markdownReport(results, meta, notes);
    rfir::common::writeFileAtomically(top.file("results.md"),
                                      [&](std::ostream& o) { o << md; });
    img.commit();
    top.commit();
}

}  // namespace rfir::experiments
