/* rfir: the IR localizer's particle set and its step likelihood. */
#include <rfir/ir/ir_particles.h>

#include <rfir/models/odometry_noise.h>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>
#include <stdexcept>

namespace rfir::ir {
double TIRStepLikelihood::logLikelihood(size_t i, const mrpt::math::TPose2D& p) const {
    if (!map || !obs || !map->genericMapParams.enableObservationLikelihood) return 0;
    return map->observationLogLikelihood(*obs, p, [&](size_t k) -> TTerm {
        if (k < terms.size() && i < terms[k].size() && terms[k][i].known)
            return terms[k][i].term;
        return map->readingTerm(obs->readings[k], p);
    });
}

void CIRParticles::prediction_and_update_pfStandardProposal(
    const mrpt::obs::CActionCollection* action, const mrpt::obs::CSensoryFrame* sf,
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions& o) {
    if (action) {
        const auto mv = action->getBestMovementEstimation();
        if (!mv || !mv->poseChange)
            throw std::invalid_argument("CIRParticles: the action has no 2D movement");
        const auto [C, mean] = mv->poseChange->getCovarianceAndMean();
        double c[9];
        for (int r = 0; r < 3; r++)
            for (int k = 0; k < 3; k++) c[3 * r + k] = C(r, k);
        const auto g = rfir::models::OdometryGaussian::fromCovariance(mean.x(), mean.y(),
                                                                      mean.phi(), c);
        for (auto& p : m_particles) g.propagate(*m_rng, p.d.x, p.d.y, p.d.phi);
    }
    if (!sf || sf->size() == 0) return;
    for (size_t i = 0; i < m_particles.size(); i++) {
        const double ll = m_step->logLikelihood(i, m_particles[i].d);
        if (!std::isfinite(ll))
            throw std::runtime_error(
                "the emitter map returned a non-finite log-likelihood");
        m_particles[i].log_w += ll * o.powFactor;
    }
}

}  // namespace rfir::ir
