#include <rfir/slam/CRobotPoseParticles.h>

#include <rfir/slam/motion_model.h>
#include <rfir/slam/slam_options.h>

#include <mrpt/obs/CActionCollection.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace rfir::slam {
void CRobotPoseParticles::reset(const mrpt::poses::CPose2D& start, size_t M, double stdXY,
                                double stdPhi, rfir::models::TRandom& rng) {
    m_rng = &rng;
    m_ess = -1;
    m_moves = 0;
    m_particles.assign(M, {});
    for (auto& p : m_particles) {
        p.log_w = 0;
        p.d = start;
        if (stdXY > 0 || stdPhi > 0)
            p.d = mrpt::poses::CPose2D(start.x() + rng.drawGaussian1D(0, stdXY),
                                       start.y() + rng.drawGaussian1D(0, stdXY),
                                       start.phi() + rng.drawGaussian1D(0, stdPhi));
    }
    m_drift.clear();
    if (m_headingDrift.on()) {
        m_drift.assign(M, 0.0);
        drawDriftPrior(
            m_particles, [&](auto&, size_t i) -> double& { return m_drift[i]; },
            m_headingDrift.std, rng);
    }
}

mrpt::poses::CPose2D CRobotPoseParticles::meanPose() const {
    const size_t n = m_particles.size();
    bool normalised = n > 0 && m_normLogW.size() == n;
    for (size_t i = 0; normalised && i < n; i++)
        normalised = m_particles[i].log_w == m_normLogW[i];
    // Their largest log-weight is 0: exp(lw - 0) is the stored exp(lw).
    if (normalised)
        return weightedMeanPoseLinear(
            n, [&](size_t i) { return m_normW[i]; },
            [&](size_t i) -> const CParticlePose2D& { return m_particles[i].d; });
    // The weights are read in place: no copy of them per call (twice a step).
    return weightedMeanPose(
        m_particles.size(), [&](size_t i) { return m_particles[i].log_w; },
        [&](size_t i) -> const CParticlePose2D& { return m_particles[i].d; });
}

TPoseMoments CRobotPoseParticles::poseMoments() const {
    if (m_particles.empty()) return {};
    double top = -1e300;
    for (const auto& q : m_particles) top = std::max(top, q.log_w);
    CPoseMomentSums sums;
    accumulate(sums,
               [top](size_t, double lw) { return lw == top ? 1.0 : std::exp(lw - top); });
    return sums.moments();
}

template <class W>
void CRobotPoseParticles::accumulate(CPoseMomentSums& sums, W weight) const {
    const auto& r = m_particles.front().d;
    sums.start(r.x(), r.y(), r.phi());
    // Iterators, not indices: the particles live in MRPT's std::deque.
    size_t i = 0;
    for (const auto& q : m_particles) {
        // Through a const pose: CPose2D's non-const phi() resets the cached
        // cos and sin.
        const CParticlePose2D& d = q.d;
        sums.add(weight(i++, q.log_w), d.x(), d.y(), d.phi());
    }
}

double CRobotPoseParticles::priorWeight(size_t i, double lw) const {
    // The weights before a weighing are the last normalisation's (their exp
    // kept: a comparison instead of an exp) or, after a resampling, all 0;
    // their largest log is 0 either way.
    if (i < m_normLogW.size() && m_normLogW[i] == lw) return m_normW[i];
    return lw == 0 ? 1.0 : std::exp(lw);
}

std::optional<TPoseMoments> CRobotPoseParticles::priorMoments() const {
    if (!m_priorValid) return std::nullopt;
    return m_prior.moments();
}

std::optional<TPoseMoments> CRobotPoseParticles::posteriorMoments() const {
    if (!m_postValid) return std::nullopt;
    return m_post.moments();
}

void CRobotPoseParticles::replacePose(size_t i, const mrpt::poses::CPose2D& p,
                                      double logW, double stepLogLik) {
    m_particles.at(i).d = p;
    m_particles.at(i).log_w = logW;
    if (i < m_stepLogLik.size()) m_stepLogLik[i] = stepLogLik;
    m_postValid = false;
    m_ess = -1;
}

double CRobotPoseParticles::bestPriorLogW() const {
    const bool weighed = m_stepLogLik.size() == m_particles.size();
    double best = -std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < m_particles.size(); i++)
        best = std::max(best, m_particles[i].log_w - (weighed ? m_stepLogLik[i] : 0.0));
    return best;
}

double CRobotPoseParticles::getW(size_t i) const {
    return m_particles.at(i).log_w;
}

void CRobotPoseParticles::setW(size_t i, double w) {
    m_particles.at(i).log_w = w;
    m_ess = -1;
}

double CRobotPoseParticles::normalizeWeights(double* out_max_log_w) {
    if (m_particles.empty()) return 0;
    double minW = m_particles[0].log_w, maxW = minW;
    for (const auto& p : m_particles) {
        maxW = std::max<double>(maxW, p.log_w);
        minW = std::min<double>(minW, p.log_w);
    }
    // The ESS in the same pass (one exp per particle): CParticleFilter asks
    // for it right after, and the resampling stage once more.
    double s1 = 0, s2 = 0;
    m_normLogW.resize(m_particles.size());
    m_normW.resize(m_particles.size());
    for (size_t i = 0; i < m_particles.size(); i++) {
        auto& p = m_particles[i];
        p.log_w -= maxW;
        const double w = std::exp(p.log_w);
        m_normLogW[i] = p.log_w;
        m_normW[i] = w;
        s1 += w;
        s2 += w * w;
    }
    // The posterior moments in a loop of their own: the exp above is a call,
    // which would spill the accumulators on every particle.
    m_postValid = m_track && !m_particles.empty();
    if (m_postValid) accumulate(m_post, [&](size_t i, double) { return m_normW[i]; });
    m_ess = s2 > 0 ? s1 * s1 / (s2 * double(m_particles.size())) : 0;
    if (out_max_log_w) *out_max_log_w = maxW;
    return std::exp(maxW - minW);
}

double CRobotPoseParticles::ESS() const {
    if (m_ess >= 0) return m_ess;
    // One exp per particle (not two): this runs on every step.
    thread_local std::vector<double> lin;
    lin.resize(m_particles.size());
    double cum = 0, sumLinearWeights = 0;
    for (size_t i = 0; i < lin.size(); i++)
        sumLinearWeights += (lin[i] = std::exp(m_particles[i].log_w));
    for (const double l : lin) {
        const double w = l / sumLinearWeights;
        cum += w * w;
    }
    if (cum == 0) return 0;
    return 1.0 / (m_particles.size() * cum);
}

void CRobotPoseParticles::performSubstitution(const std::vector<size_t>& indx) {
    std::vector<size_t> sorted(indx);
    std::sort(sorted.begin(), sorted.end());
    CParticleList parts(sorted.size());
    for (size_t i = 0; i < sorted.size(); i++) parts[i] = m_particles[sorted[i]];
    m_particles = std::move(parts);
    if (!m_drift.empty()) {
        std::vector<double> drift(sorted.size());
        for (size_t i = 0; i < sorted.size(); i++) drift[i] = m_drift[sorted[i]];
        m_drift = std::move(drift);
    }
    m_ess = -1;
    m_stepLogLik.clear();  // no longer this set's
}

void CRobotPoseParticles::prediction_and_update_pfStandardProposal(
    const mrpt::obs::CActionCollection* action, const mrpt::obs::CSensoryFrame*,
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions&) {
    // Motion model (SPEC section 3): one draw of the odometry increment's
    // Gaussian per particle.
    const auto poseOf = [](auto& p) -> CParticlePose2D& { return p.d; };
    if (const auto g = motionOf(action)) {
        if (m_drift.empty())
            drawMotion(*g, m_particles, poseOf, *m_rng, m_moves);
        else
            drawMotion(
                *g, m_particles, poseOf,
                [&](auto&, size_t i) -> double& { return m_drift[i]; },
                m_headingDrift.walk, *m_rng, m_moves);
    }
    m_ess = -1;
    m_stepLogLik.clear();
    m_priorValid = m_postValid = false;
    if (!m_model) return;
    m_model->afterMotion();
    if (!m_model->weighs()) return;
    m_stepLogLik.resize(m_particles.size());
    // The prior moments before the weighing, in a loop of their own (the
    // weighing's virtual call would spill the accumulators per particle).
    m_priorValid = m_track && !m_particles.empty();
    if (m_priorValid)
        accumulate(m_prior, [&](size_t i, double lw) { return priorWeight(i, lw); });
    for (size_t i = 0; i < m_particles.size(); i++) {
        auto& q = m_particles[i];
        const double ll = m_model->logLikelihood(i, q.d);
        if (!std::isfinite(ll))
            throw std::runtime_error(
                "the landmark map returned a non-finite log-likelihood");
        m_stepLogLik[i] = ll;
        q.log_w += ll;
    }
}

double CRobotPoseParticles::stepLogEvidence(const std::vector<double>& terms) const {
    // log sum w exp(term) - log sum w over the weights before the weighing
    // (log_w - ll: the weighing's own terms, not a second likelihood pass).
    // Valid until the weights change again (normalising keeps it: a common
    // shift). Where term == ll, log_w itself (no rounding of -ll + ll).
    const size_t n = m_particles.size();
    if (m_stepLogLik.size() != n || terms.size() != n || n == 0) return 0;
    auto post = [&](size_t i) {
        const double lw = m_particles[i].log_w;
        return terms[i] == m_stepLogLik[i] ? lw : lw - m_stepLogLik[i] + terms[i];
    };
    double maxPrior = -1e300, maxPost = -1e300;
    for (size_t i = 0; i < n; i++) {
        maxPrior = std::max(maxPrior, m_particles[i].log_w - m_stepLogLik[i]);
        maxPost = std::max(maxPost, post(i));
    }
    double sPrior = 0, sPost = 0;
    for (size_t i = 0; i < n; i++) {
        sPrior += std::exp(m_particles[i].log_w - m_stepLogLik[i] - maxPrior);
        sPost += std::exp(post(i) - maxPost);
    }
    return maxPost + std::log(sPost) - maxPrior - std::log(sPrior);
}

}  // namespace rfir::slam
