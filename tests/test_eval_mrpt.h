/* rfir tests: a known path, and the same path as MRPT's rbpf-slam writes it
 * (shared by the rfir_eval reader tests and the rfir-eval program's). */
#pragma once

#include <rfir/common/trajectory_io.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace rfir_test {
/** A curve with turning heading, 0.1 s apart, starting at t = 1. */
inline rfir::common::TPath2D curve(size_t n) {
    rfir::common::TPath2D p;
    for (size_t i = 0; i < n; i++) {
        const double t = 1 + 0.1 * double(i), a = 0.05 * double(i);
        p.push_back(
            {t, mrpt::poses::CPose2D(1 + 2 * std::sin(a), -1 + 1.5 * (1 - std::cos(a)),
                                     rfir::common::wrapToPi(0.3 + 1.7 * a))});
    }
    return p;
}

/** `path` as rbpf-slam writes log_estimated_path.txt (RBPF_SLAM_App's
 * "%u %f %f %f %f %f %f %f"): from the origin at `start`, a first row for the
 * header pair at the first instant's time. */
inline void writeRbpfSlam(const std::filesystem::path& f,
                          const rfir::common::TPath2D& path,
                          const mrpt::poses::CPose2D& start) {
    FILE* o = std::fopen(f.c_str(), "w");
    unsigned step = 0;
    std::fprintf(o, "%u %f %f %f %f %f %f %f\n", step++, 0.0, 0.0, 0.0, 0.0, -0.0, 0.0,
                 path[0].t);
    for (const auto& p : path) {
        const mrpt::poses::CPose2D r = p.pose - start;  // start^-1 + pose
        std::fprintf(o, "%u %f %f %f %f %f %f %f\n", step++, r.x(), r.y(), 0.0, r.phi(),
                     -0.0, 0.0, p.t);
    }
    std::fclose(o);
}

}  // namespace rfir_test
