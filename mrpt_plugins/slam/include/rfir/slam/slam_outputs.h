/* rfir: a SLAM run's outputs in the file types (rfir_io): its path as a TUM
 * trajectory, its landmarks as map-file entries (textlog.md map format). */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/slam/slam_engine.h>

#include <vector>

namespace rfir::slam {
/** The run's robot path, one stamped pose per step. */
rfir::common::TPath2D stampedPath(const TSlamRun& run);

/** One map-file entry per landmark (tag or range-bearing landmark), with its
 * standard deviations and, for tags, its read counts when known. */
rfir::common::TMapFile landmarkEntries(const std::vector<TLandmarkOut>& lms);
}  // namespace rfir::slam
