// Helpers shared by the tag-map tests: observations and a simple pass simulator.
#pragma once

#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <cmath>
#include <string>
#include <vector>

namespace tagmaps_test {
inline rfir::obs::TRFIDReader reader(const std::string& id, double x, double y,
                                     double h) {
    rfir::obs::TRFIDReader r;
    r.id = id;
    r.x = x;
    r.y = y;
    r.halfX = r.halfY = h;
    return r;
}

/** An 8-reader ring (like the papers' robot), readers of half-size h. */
inline std::vector<rfir::obs::TRFIDReader> ring(double h) {
    std::vector<rfir::obs::TRFIDReader> v;
    const double d = std::max(0.1, 2.2 * h);
    for (int k = 0; k < 8; k++) {
        const double a = k * M_PI / 4;
        v.push_back(reader("R" + std::to_string(k), d * std::cos(a), d * std::sin(a), h));
    }
    return v;
}

struct Tag {
    std::string id;
    double x, y;
};

/** What each reader of `readers` reads at a robot pose (exact step detection). */
inline rfir::obs::CObservationRFIDReaders::Ptr sense(
    const std::vector<rfir::obs::TRFIDReader>& readers, const std::vector<Tag>& tags,
    const mrpt::math::TPose2D& pose) {
    auto o = rfir::obs::CObservationRFIDReaders::Create();
    o->sensorLabel = "RFID";
    const double c = std::cos(pose.phi), s = std::sin(pose.phi);
    for (const auto& r : readers) {
        rfir::obs::CObservationRFIDReaders::TReading rd;
        rd.reader = r;
        for (const auto& t : tags) {
            const double dx = t.x - pose.x, dy = t.y - pose.y;
            const double ex = c * dx + s * dy - r.x, ey = -s * dx + c * dy - r.y;
            if (std::abs(ex) < r.halfX && std::abs(ey) < r.halfY) rd.tags.push_back(t.id);
        }
        o->readings.push_back(rd);
    }
    return o;
}

/** Tags on a square grid of pitch p over [0, n*p)^2, offset by (ox, oy). */
inline std::vector<Tag> grid(int n, double p, double ox = 0.013, double oy = 0.027) {
    std::vector<Tag> v;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            v.push_back({"T" + std::to_string(i) + "_" + std::to_string(j), ox + i * p,
                         oy + j * p});
    return v;
}

/** Lawn-mower poses over a rectangle: rows `rowStep` apart, `step` m per pose,
 * heading along the rows (alternating), all at a fixed yaw offset. */
inline std::vector<mrpt::math::TPose2D> lawnmower(double x0, double x1, double y0,
                                                  double y1, double rowStep,
                                                  double step) {
    std::vector<mrpt::math::TPose2D> v;
    bool fwd = true;
    for (double y = y0; y <= y1 + 1e-9; y += rowStep, fwd = !fwd)
        for (double t = 0; t <= x1 - x0 + 1e-9; t += step)
            v.push_back({fwd ? x0 + t : x1 - t, y, fwd ? 0.0 : M_PI});
    return v;
}

inline mrpt::poses::CPose3D pose3(const mrpt::math::TPose2D& p) {
    return mrpt::poses::CPose3D(p.x, p.y, 0, p.phi, 0, 0);
}

}  // namespace tagmaps_test
