/* rfir-localize: the output files. */
#pragma once

#include <rfir/localize/localize_run.h>

#include <string>

namespace rfir::localize {
/** In memory, what writeOutputs writes into stats.json and errors.json
 * (empty without ground truth), and the error table. */
struct TRunSummary {
    std::string statsJson, errorsJson, errorTable;
};

/** Writes OUT/path.tum, stats.json, settings.ini, path_map.png,
 * emitter_health.txt and, with a ground-truth path (cfg.gtPath), errors.json
 * and error_time.png as rfir-slam's (and errors_spots.json at the marked spots
 * of `<stem>.spots.tum` when present). Each file is written whole or not at
 * all; the set replaces the folder's earlier one. Returns what it wrote. */
TRunSummary writeOutputs(const TConfig& cfg, const TRunResult& res,
                         const std::string& commandLine);

/** writeOutputs' summary without writing anything (stats.json's "files"
 * empty). */
TRunSummary summarize(const TConfig& cfg, const TRunResult& res);

/** A whole run of rfir-localize, for the program and the Python module
 * alike: prepareRun, runLocalization (progress and a summary line on stderr
 * unless cfg.quiet), the outputs into cfg.outDir unless it is empty. */
struct TLocalizeJob {
    TRunResult run;
    TRunSummary summary;
};
TLocalizeJob runLocalizeJob(TConfig& cfg, const std::string& emitters,
                            const std::string& commandLine,
                            const TStepObserver& onStep = {});

/** The path's pose at each spot time (the latest pose not after it); spots
 * before the path's start are left out. */
rfir::common::TPath2D atSpots(const rfir::common::TPath2D& path,
                              const rfir::common::TPath2D& spots);

}  // namespace rfir::localize
