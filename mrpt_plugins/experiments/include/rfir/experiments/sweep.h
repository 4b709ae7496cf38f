/* rfir-experiments: a sweep as independent runs, one row on one seed each.
 * Every run writes its own folder (run.json, and on a row's first seed that
 * seed's figures); the reports are merged from the folders. A direct run,
 * --jobs N, a manifest under GNU parallel or Slurm and --merge all take this
 * one path, so they give the same results.json. */
#pragma once

#include <rfir/experiments/results.h>

#include <cstdio>
#include <string>
#include <vector>

namespace rfir::experiments {
/** One run of a sweep: a row on one seed (every point, sub-run and method). */
struct TSweepRun {
    const TRow* row = nullptr;
    uint64_t seed = 0;
    bool first = false;  //!< the sweep's first seed: it draws the row's path figures
};

/** Every run of the rows, row by row, each row's seeds in order (at most
 * its maxSeeds). */
std::vector<TSweepRun> sweepRuns(const std::vector<TRow>& rows,
                                 const std::vector<uint64_t>& seeds);

/** A run's folder under `dir`: DIR/<row id>/seed<S>. */
std::string runFolder(const std::string& dir, const TSweepRun& run);

/** "<row id> seed <S>", the name of a run in messages. */
std::string runName(const TSweepRun& run);

/** The options that decide the numbers, as a command: rfir-experiments
 * [--quick] [--rows IDS] --seed S --seeds N [--set EDIT]... */
std::string sweepCommand(const std::vector<TRow>& rows, const TMeta& meta);

/** MD5 of what decides a run's numbers: rfir's version, the row, the seed,
 * --quick, the --set edits and the bytes of every INI the row reads. */
std::string runFingerprint(const TSetup& setup, const TMeta& meta, const TRow& row,
                           uint64_t seed);

/** Runs the row on one seed and writes FOLDER/run.json (with `figures`, also
 * the row's first-seed figures) as one set (COutputFolder). Progress lines go
 * to `log` when not null. */
void runToFolder(const TSetup& setup, const TMeta& meta, const TRow& row, uint64_t seed,
                 bool figures, const std::string& folder, FILE* log);

/** Reads every run of the sweep back from DIR (runFolder's layout), in the
 * order of a sweep. Throws std::runtime_error naming the run and the file when
 * a run's folder is missing or unreadable, or holds a run of another sweep
 * (another fingerprint: other INIs, --set edits, --quick or rfir version). */
std::vector<TRowResults> loadRuns(const std::string& dir, const std::vector<TRow>& rows,
                                  const TSetup& setup, const TMeta& meta);

/** The command (argv) that runs `run` into runFolder(dir, run) on its own:
 * this program (absolute path) with --config-dir (absolute), --quick, the
 * --set edits, --run ROW:SEED, --out-dir and, but on the row's first seed or
 * without `figures`, --no-figures. What --jobs starts and --manifest prints. */
std::vector<std::string> runArgs(const TSetup& setup, const TMeta& meta,
                                 const TSweepRun& run, bool figures,
                                 const std::string& dir);

/** A command as one shell line: arguments quoted where the shell needs it.
 * Throws std::invalid_argument for an argument holding a newline. */
std::string shellLine(const std::vector<std::string>& args);

/** Runs every run of the sweep into its folder under `dir`: in this process
 * when `jobs` is 1, else as child processes of this program (runArgs), `jobs`
 * at a time. Progress on stderr unless `quiet`: each run's lines and
 * "[k/N] ROW seed S: T s" as it ends. The first run that fails stops the
 * sweep: std::runtime_error naming it (with its output). */
void runAll(const std::vector<TRow>& rows, const TSetup& setup, const TMeta& meta,
            bool figures, const std::string& dir, unsigned jobs, bool quiet);

/** OUT/results.json, timings.json, results.md and, with `figures`, OUT/img's
 * figures of the rows, written as one set: the sweeps' plots drawn from the
 * results, the first seed's figures copied from its run folder under
 * `runsDir`. `notes` (markdown) goes into results.md. */
void writeReports(const std::string& out, const std::string& runsDir,
                  const std::vector<TRowResults>& results, const TMeta& meta,
                  const std::string& notes, bool figures);

}  // namespace rfir::experiments
