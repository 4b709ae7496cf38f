/* rfir: instants placed at the odometry interpolated to their time (reader
 * polls out of step with the odometry, odometry latency). */
#include <rfir/slam/slam_inputs.h>

#include <stdexcept>

namespace rfir::slam {
namespace {
using mrpt::poses::CPose2D;
struct TRecord {
    double t;
    CPose2D pose;
};

/** The share f of increment u, taken along the increment (x, y, phi scaled). */
CPose2D partOf(const CPose2D& u, double f) {
    return {f * u.x(), f * u.y(), f * u.phi()};
}

/** The odometry at time t; `j` is a cursor (the last record at or before t)
 * that only moves forward, as the instants' times do. */
CPose2D poseAt(const std::vector<TRecord>& r, double t, size_t& j) {
    while (j + 1 < r.size() && r[j + 1].t <= t) j++;
    if (t <= r[j].t || j + 1 == r.size()) return r[j].pose;  // exact or clamped
    const double f = (t - r[j].t) / (r[j + 1].t - r[j].t);
    return r[j].pose + partOf(r[j + 1].pose - r[j].pose, f);
}

/** The parts of the odometry intervals that [a, b] covers. */
std::vector<TOdometryPart> partsOf(const std::vector<TRecord>& r, double a, double b,
                                   size_t& j) {
    std::vector<TOdometryPart> v;
    while (j + 1 < r.size() && r[j + 1].t <= a) j++;
    for (size_t k = j; k + 1 < r.size() && r[k].t < b; k++) {
        const double len = r[k + 1].t - r[k].t;
        const double lo = std::max(a, r[k].t), hi = std::min(b, r[k + 1].t);
        if (!(len > 0) || !(hi > lo)) continue;
        v.push_back({r[k + 1].pose - r[k].pose, len, (hi - lo) / len});
    }
    return v;
}
}  // namespace

std::vector<TSlamInput> interpolatedInputs(const std::vector<TRawInstant>& instants,
                                           double latency) {
    std::vector<TRecord> rec;
    for (const auto& s : instants)
        if (s.odometry) rec.push_back({s.t - latency, *s.odometry});
    std::vector<TSlamInput> out;
    out.reserve(instants.size());
    size_t jp = 0, jq = 0;
    CPose2D prev;
    for (size_t i = 0; i < instants.size(); i++) {
        const auto& s = instants[i];
        if (i > 0 && s.t < instants[i - 1].t)
            throw std::invalid_argument(
                "interpolate_polls: instant " + std::to_string(i) +
                " at t = " + std::to_string(s.t) + " s goes back in time");
        TSlamInput in;
        in.t = s.t;
        in.rfid = s.rfid;
        in.rb = s.rb;
        if (!rec.empty()) {
            const CPose2D p = poseAt(rec, s.t, jp);
            if (i > 0) {
                auto parts = partsOf(rec, instants[i - 1].t, s.t, jq);
                if (!parts.empty()) {
                    in.odometryIncrement = p - prev;
                    in.odometryDt = s.t - instants[i - 1].t;
                    // One whole interval: the plain model of that increment.
                    if (parts.size() == 1 && parts[0].fraction == 1) parts.clear();
                    in.odometryParts = std::move(parts);
                }
            }
            prev = p;
        }
        out.push_back(std::move(in));
    }
    return out;
}

}  // namespace rfir::slam
