/* rfir: the IR localizer's particle set and its step likelihood. */
#include <rfir/ir/ir_particles.h>

#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>

namespace rfir::ir {
double TIRStepLikelihood::logLikelihood(size_t i, const mrpt::math::TPose2D& p) const {
    if (!map || !obs || !map->genericMapParams.enableObservationLikelihood) return 0;
    return map->observationLogLikelihood(*obs, p, [&](size_t k) -> TTerm {
        if (k < terms.size() && i < terms[k].size() && terms[k][i].known)
            return terms[k][i].term;
        return map->readingTerm(obs->readings[k], p);
    });
}

double CIRParticles::PF_SLAM_computeObservationLikelihoodForParticle(
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions&, size_t i,
    const mrpt::obs::CSensoryFrame& sf, const mrpt::poses::CPose3D& x) const {
    double ret = 1;
    if (sf.size() == 0) return ret;
    // The map receives the robot pose as x, y, yaw of the CPose3D: the
    // particle's own values exactly.
    ret += m_step->logLikelihood(i, mrpt::math::TPose2D(x.x(), x.y(), x.yaw()));
    return ret;
}

}  // namespace rfir::ir
