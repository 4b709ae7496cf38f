/* rfir-experiments: the papers' experiments in one process: each row
 * simulates its data sets (rfir_sim), runs PS-SLAM, PF-SLAM, FastSLAM and dead
 * reckoning on the same data (rfir_slam), scores them (rfir_eval) and
 * aggregates over seeds into results.json, results.md and img/exp_*.png. */
#include <rfir/experiments/report.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/cli.h>
#include <rfir/common/install_paths.h>
#include <rfir/common/text_input.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/filesystem.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
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

/** Every (point, sub-run, seed, method) of a row. */
TRowResults runRow(const TRow& row, std::vector<uint64_t> seeds, const TSetup& setup,
                   size_t idx, size_t nRows, bool quiet) {
    FILE* log = quiet ? nullptr : stderr;
    if (row.maxSeeds && seeds.size() > row.maxSeeds) seeds.resize(row.maxSeeds);
    TRowResults res;
    res.row = row;
    for (size_t p = 0; p < row.points.size(); p++)
        for (size_t k = 0; k < row.runs.size(); k++)
            for (uint64_t seed : seeds) {
                const auto t0 = Clock::now();
                auto data = simulateDataSet(setup, row.runs[k], row.points[p], seed);
                const bool first = p == 0 && k == 0 && seed == seeds.front();
                if (log)
                    std::fprintf(
                        log, "[%zu/%zu] %s %s%s%s seed %llu (%zu steps):", idx + 1, nRows,
                        row.id.c_str(), row.points[p].label.c_str(),
                        row.points[p].label.empty() ? "" : " ", row.runs[k].label.c_str(),
                        (unsigned long long)seed, data.sim.steps.size());
                for (const auto& m : row.methods) {
                    auto r = runMethod(setup, data, m, row.points[p], seed, first);
                    r.point = p;
                    r.run = k;
                    if (log)
                        std::fprintf(log, " %s %.0f/%.0f mm", m.label.c_str(),
                                     1e3 * robotMeanDist(r), 1e3 * tagMeanDist(r));
                    if (first) res.firstRuns.push_back(r);
                    r.estPath.clear();
                    r.estMap.clear();
                    r.eval.robot->perPose.clear();
                    res.runs.push_back(std::move(r));
                }
                if (log) std::fprintf(log, " (%.1f s)\n", since(t0));
                if (first) res.firstData = std::move(data);
            }
    return res;
}

void writeOutputs(const std::string& out, const std::vector<TRowResults>& results,
                  const TMeta& meta, const std::string& notesFile, bool figures,
                  bool quiet) {
    const std::string notes = notesFile.empty()
                                  ? std::string()
                                  : rfir::common::readSmallTextFile(notesFile, "--notes");
    if (figures)
        for (const auto& r : results) writeFigures(out, r);
    writeJson(out + "/results.json", results, meta);
    const std::string md = markdownReport(results, meta, notes);
    rfir::common::writeFileAtomically(out + "/results.md",
                                      [&](std::ostream& o) { o << md; });
    if (!quiet)
        std::cerr << "rfir-experiments: wrote " << out << "/results.md, results.json"
                  << (figures ? ", img/exp_*.png" : "") << "\n";
}
}  // namespace

int main(int argc, char** argv) {
    try {
        TCLAP::CmdLine cmd(
            "rfir-experiments: runs the experiment rows of the seeds' tables and figures "
            "(PS-SLAM, PF-SLAM, FastSLAM and dead reckoning on the same simulated data, "
            "several seeds each) and writes OUT/results.json (every raw number), "
            "OUT/results.md (tables beside the seeds' numbers) and OUT/img/exp_*.png.",
            ' ', RFIR_VERSION);
        TCLAP::ValueArg<std::string> rows("", "rows",
                                          "comma-separated row ids (default: all; "
                                          "see --list)",
                                          false, "all", "IDS", cmd);
        TCLAP::SwitchArg list("", "list", "list the rows and exit", cmd);
        rfir::common::CNumberArg<unsigned> seeds("", "seeds",
                                                 "seeds per row (default 8, --quick 1)",
                                                 false, 0, "N", cmd, 1, 100000);
        rfir::common::CNumberArg<uint64_t> firstSeed(
            "", "seed", "first seed: seeds are S, S+1, ... (default 1)", false, 1, "S",
            cmd);
        TCLAP::SwitchArg quick("", "quick",
                               "tiny runs: first sub-run, sweep end points, "
                               "40 s of simulated time",
                               cmd);
        TCLAP::ValueArg<std::string> out("", "out-dir",
                                         "output folder (required unless --list)", false,
                                         "", "DIR", cmd);
        TCLAP::ValueArg<std::string> cfgDir(
            "", "config-dir",
            "folder of the sim_*.ini and "
            "slam_*.ini (default: the installed stock INIs)",
            false, rfir::common::stockConfigDir(), "DIR", cmd);
        TCLAP::ValueArg<std::string> notes("", "notes", "markdown inserted in results.md",
                                           false, "", "FILE", cmd);
        TCLAP::ValueArg<std::string> revision("", "revision",
                                              "source revision to record in "
                                              "the report (e.g. git describe)",
                                              false, "", "TEXT", cmd);
        TCLAP::SwitchArg noFig("", "no-figures", "do not draw the PNG figures", cmd);
        TCLAP::MultiArg<std::string> sets(
            "", "set",
            "override an INI key in every INI of the run, after the rows' own edits: a "
            "simulation INI's (e.g. trajectory.speed=0.3) or a SLAM INI's (e.g. "
            "slam.robot_particles=200); [kidnap] is in both: sim:kidnap.KEY=VALUE or "
            "slam:kidnap.KEY=VALUE (repeatable)",
            false, "SECTION.KEY=VALUE", cmd);
        TCLAP::SwitchArg quiet("q", "quiet", rfir::common::kQuietHelp, cmd);
        if (const auto code = rfir::common::parseCommandLine(
                cmd, argc, argv, {{"--out", "--out-dir"}, {"--first-seed", "--seed"}}))
            return *code;

        std::vector<TRow> selected;
        TSetup setup;
        try {  // usage errors: exit as a parse error does
            using rfir::common::CUsageError;
            selected = selectRows(rows.getValue(), quick.getValue());
            if (!list.getValue() && out.getValue().empty())
                throw CUsageError("--out-dir DIR is required");
            if (notes.isSet() && !mrpt::system::fileExists(notes.getValue()))
                throw CUsageError("--notes: cannot read '" + notes.getValue() + "'");
            rfir::common::checkFolderOption("--config-dir", cfgDir.getValue());
            setup = makeSetup(cfgDir.getValue(), sets.getValue());
            // Every INI with every edit, before hours of work (an INI's own
            // error passes on: exit 1 naming the file).
            if (!list.getValue()) checkConfigs(setup, selected);
        } catch (const rfir::common::CUsageError& e) {
            std::cerr << "rfir-experiments: error: " << e.what() << "\n";
            return rfir::common::kUsageExitCode;
        }
        if (list.getValue()) {
            if (quiet.getValue()) return 0;
            for (const auto& r : allRows(false))
                std::cout << r.id << "\t" << r.source << ": " << r.title << "\n";
            return 0;
        }
        const unsigned n = seeds.isSet() ? seeds.getValue() : quick.getValue() ? 1 : 8;
        TMeta meta;
        meta.quick = quick.getValue();
        meta.revision = revision.getValue();
        meta.sets = sets.getValue();
        for (unsigned i = 0; i < n; i++) meta.seeds.push_back(firstSeed.getValue() + i);
        for (int i = 0; i < argc; i++)
            meta.commandLine +=
                (i ? " " + std::string(argv[i]) : mrpt::system::extractFileName(argv[0]));
        // Fail before hours of work, not after.
        std::error_code ec;
        std::filesystem::create_directories(out.getValue() + "/img", ec);
        if (ec || !mrpt::system::directoryExists(out.getValue() + "/img"))
            throw std::runtime_error("cannot create the folder '" + out.getValue() +
                                     "/img'");
        const auto t0 = Clock::now();
        std::vector<TRowResults> results;
        for (size_t i = 0; i < selected.size(); i++)
            results.push_back(runRow(selected[i], meta.seeds, setup, i, selected.size(),
                                     quiet.getValue()));
        meta.wallSeconds = since(t0);
        writeOutputs(out.getValue(), results, meta, notes.getValue(), !noFig.getValue(),
                     quiet.getValue());
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "rfir-experiments: error: " << e.what() << "\n";
        return 1;
    }
}
