/* rfir-localize: the output files. */
#pragma once

#include <rfir/localize/localize_run.h>

#include <string>

namespace rfir::localize {
/** Writes OUT/path.tum, stats.json, settings.ini, path.png and, when
 * `<stem>.gt.tum` lies beside the rawlog, errors.txt (also at the marked spots
 * of `<stem>.spots.tum` when present). Each file is written whole or not at
 * all. Returns the error table (empty without ground truth). */
std::string writeOutputs(const TConfig& cfg, const TRunResult& res,
                         const std::string& commandLine);

/** The path's pose at each spot time (the latest pose not after it); spots
 * before the path's start are left out. */
rfir::common::TPath2D atSpots(const rfir::common::TPath2D& path,
                              const rfir::common::TPath2D& spots);

}  // namespace rfir::localize
