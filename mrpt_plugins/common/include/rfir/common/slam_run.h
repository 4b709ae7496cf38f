/* rfir: a SLAM run's outputs in the file types: its path as a TUM trajectory,
 * its landmarks as map-file entries (textlog.md map format).
 * Header-only: rfir_appcommon does not link rfir_slam; every caller (rfir-slam,
 * rfir-experiments, the SLAM tests) links both. */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/slam/slam_engine.h>

#include <vector>

namespace rfir::common {
inline TPath2D stampedPath(const rfir::slam::TSlamRun& run) {
    TPath2D p;
    for (const auto& [t, pose] : run.path) p.push_back({t, pose});
    return p;
}

inline TMapFile landmarkEntries(const std::vector<rfir::slam::TLandmarkOut>& lms) {
    TMapFile m;
    for (const auto& l : lms) {
        TMapEntry e;
        e.kind = l.isTag ? TMapEntry::Kind::Tag : TMapEntry::Kind::Landmark;
        e.id = l.id;
        e.x = l.x;
        e.y = l.y;
        e.sx = l.sx;
        e.sy = l.sy;
        if (l.reads) e.reads = l.reads, e.contradicted = l.contradicted;
        m.push_back(e);
    }
    return m;
}
}  // namespace rfir::common
