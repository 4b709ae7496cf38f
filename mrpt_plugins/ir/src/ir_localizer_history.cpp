/* rfir: the IR localizer's start from the first unique ID, weighed by the
 * repeated-ID readings of the path before it ([localization] start_history).
 *
 * One unique emitter read by the receivers leaves a ring of robot poses
 * about it (any rotation about the emitter explains the voltages equally),
 * and the weighted mean of a ring sits near the emitter while the robot
 * drives on. The readings before it say where the robot came from: a pose on
 * the ring walked back along the odometry must put the receivers under
 * emitters of the IDs read then. This is the posterior given all the data
 * (eq. 5.2 with the belief of eq. 5.1 per particle), not a new model. */
#include <rfir/ir/ir_localizer.h>
#include <rfir/models/odometry_noise.h>

#include <cmath>
#include <vector>

namespace rfir::ir {
namespace {
/** At most this many instants are kept (a robot turning in place under
 * repeated emitters for minutes adds no path length). */
constexpr size_t kMaxHistory = 2000;
}  // namespace

void CIRLocalizer::remember(rfir::obs::CObservationIRSignals::Ptr early) {
    if (!m_params.startFromReading || m_params.startHistory <= 0) return;
    if (!early->readings.empty())
        m_history.push_back(THistoryEntry{m_odometry, m_path, std::move(early)});
    while (!m_history.empty() &&
           (m_history.size() > kMaxHistory ||
            m_history.front().path < m_path - m_params.startHistory))
        m_history.pop_front();
}

size_t CIRLocalizer::weighByHistory() {
    using TAssociation = rfir::maps::CIREmitterMap::TAssociation;
    auto& ps = m_pdf.m_particles;
    std::vector<mrpt::math::TPose2D> back(ps.size());
    for (size_t i = 0; i < ps.size(); i++) back[i] = ps[i].d;
    // Newest first: each interval's motion inverted and drawn with the
    // filter's noise (eq. 3.6), so that a particle's past pose carries the
    // odometry's uncertainty, as the forward filter would have.
    mrpt::poses::CPose2D from = m_odometry;
    size_t used = 0;
    for (auto it = m_history.rbegin(); it != m_history.rend(); ++it) {
        if (it->path < m_path - m_params.startHistory) break;
        const mrpt::poses::CPose2D u = it->odometry - from;  // from^-1 (+) odometry
        from = it->odometry;
        double c[9];
        const auto C = m_params.motion.covariance(u);
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++) c[3 * r + k] = C(r, k);
        const auto g =
            rfir::models::OdometryGaussian::fromCovariance(u.x(), u.y(), u.phi(), c);
        const auto& obs = *it->obs;
        used += obs.readings.size();
        for (size_t i = 0; i < ps.size(); i++) {
            auto& b = back[i];
            g.propagate(m_rng, b.x, b.y, b.phi);
            // Each particle attributes a repeated ID to its own likeliest
            // emitter: there is no estimate to attribute it against yet.
            ps[i].log_w += m_map->observationLogLikelihood(obs, b, [&](size_t k) {
                return m_map->readingTerm(obs.readings[k], b, TAssociation::Particle);
            });
        }
    }
    m_history.clear();
    return used;
}

}  // namespace rfir::ir
