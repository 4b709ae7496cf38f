#include <rfir/slam/slam_outputs.h>

namespace rfir::slam {
rfir::common::TPath2D stampedPath(const TSlamRun& run) {
    rfir::common::TPath2D p;
    for (const auto& [t, pose] : run.path) p.push_back({t, pose});
    return p;
}

rfir::common::TMapFile landmarkEntries(const std::vector<TLandmarkOut>& lms) {
    using rfir::common::TMapEntry;
    rfir::common::TMapFile m;
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
}  // namespace rfir::slam
