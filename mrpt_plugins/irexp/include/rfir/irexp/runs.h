/* rfir-ir-experiments: one localization run on simulated data, its metrics,
 * and their aggregation over seeds. */
#pragma once

#include <rfir/eval/metrics.h>

#include <optional>
#include <string>
#include <vector>

namespace rfir::irexp {
struct TRunSpec {
    explicit TRunSpec(std::string ini = {}) : simIni(std::move(ini)) {}
    std::string simIni;                  //!< file name in the config folder
    std::vector<std::string> simSets;    //!< rfir-sim --set entries
    std::vector<std::string> locSets;    //!< rfir-localize --set entries
    std::vector<std::string> absentIds;  //!< emitter IDs left out of the map
    bool odometryOnly = false;
};

struct TRunMetrics {
    bool started = false;
    double tStart = 0;  //!< first unique ID (s from the first instant)
    std::optional<rfir::eval::TErrorStats> path;          //!< from the first unique ID
    std::optional<rfir::eval::TErrorStats> settled;       //!< from 10 s after it
    std::optional<rfir::eval::TErrorStats> spots;         //!< at the marked spots
    std::optional<rfir::eval::TErrorStats> spotsSettled;  //!< spots from 10 s after it
    size_t resetEvents = 0;
    double seconds = 0;  //!< filter wall-clock time
};

/** Settings shared by every run of one rfir-ir-experiments call. */
struct TExperimentRun {
    std::string configDir;  //!< config_ini of the source tree
    std::string workDir;    //!< rawlogs and per-run outputs
    bool verbose = true;
    uint64_t firstSeed = 1;  //!< --seed: rows run seeds firstSeed, firstSeed + 1, ...
    /** The user's --set edits, applied after a run's own: into every simulation
     * INI and into the localization INI. */
    std::vector<std::string> simSets, locSets;
};

/** The --set edits split between the simulation INIs and the localization
 * INI (by section), into s.simSets and s.locSets; then every simulation INI
 * the experiments read and ir_localize.ini are loaded with them, so that a
 * malformed edit, an unknown section or key or a bad value fails before any
 * run. Throws rfir::common::CUsageError naming the edit when an edit is to
 * blame, else the INI's own error "FILE: [section] key: why". */
void setEdits(TExperimentRun& s, const std::vector<std::string>& sets);

/** One line on stderr naming the experiment being run (unless quiet). */
void progress(const TExperimentRun& s, const std::string& what);

/** Simulates (once per spec and seed: cached in workDir), localizes through
 * the same code as rfir-localize, scores. `outDir` non-empty: also writes the
 * rfir-localize outputs there (path.tum, path_map.png, ...). */
TRunMetrics runOne(const TExperimentRun& s, const TRunSpec& spec, uint64_t seed,
                   const std::string& outDir = {});

/** Over seeds: means of the per-run means, max of the per-run maxima. */
struct TAggregate {
    size_t runs = 0, started = 0;
    rfir::eval::TErrorStats path, settled, spots, spotsSettled;
    bool hasSpots = false, hasPath = false;
    double meanStart = 0;
};
TAggregate aggregate(const std::vector<TRunMetrics>& runs);

/** Runs a spec over n seeds from s.firstSeed + offset (an offset keeps a row's
 * seeds apart from the others'). */
std::vector<TRunMetrics> runSeeds(const TExperimentRun& s, const TRunSpec& spec, int n,
                                  uint64_t offset = 0);

}  // namespace rfir::irexp
