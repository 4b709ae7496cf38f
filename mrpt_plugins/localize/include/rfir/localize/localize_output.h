/* rfir-localize: the output files. */
#pragma once

#include <rfir/localize/localize_run.h>

#include <string>

namespace rfir::localize {
/** Writes OUT/path.tum, stats.json, settings.ini, path_map.png,
 * emitter_health.txt and, with a ground-truth path (cfg.gtPath), errors.json
 * and error_time.png as rfir-slam's (and errors_spots.json at the marked spots
 * of `<stem>.spots.tum` when present). Each file is written whole or not at
 * all; the set replaces the folder's earlier one. Returns the error table
 * (empty without ground truth). */
std::string writeOutputs(const TConfig& cfg, const TRunResult& res,
                         const std::string& commandLine);

/** In memory, what writeOutputs writes into stats.json (its "files" empty)
 * and errors.json (empty without ground truth). */
struct TRunSummary {
    std::string statsJson, errorsJson, errorTable;
};
TRunSummary summarize(const TConfig& cfg, const TRunResult& res);

/** The path's pose at each spot time (the latest pose not after it); spots
 * before the path's start are left out. */
rfir::common::TPath2D atSpots(const rfir::common::TPath2D& path,
                              const rfir::common::TPath2D& spots);

}  // namespace rfir::localize
