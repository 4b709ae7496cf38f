/* rfir: the robot filter of PF-SLAM and PS-SLAM (SPEC section 4; 003
 * Algorithm 1 lines 2-4 and 19-28; 004 Algorithm 1) on MRPT's particle-filter
 * machinery: CParticleFilter::executeOn drives this class, which moves the
 * particles with the odometry model (the engine's generator) and weighs them
 * with the engine's IStepModel: the landmark map's reads resolved once per
 * step, the same sum as the map's computeObservationLikelihood for the ROBOT
 * pose. Resampling follows executeOn (robot_resampling.h). */
#pragma once

#include <mrpt/bayes/CParticleFilterCapable.h>
#include <mrpt/bayes/CParticleFilterData.h>
#include <mrpt/poses/CPose2D.h>

#include <rfir/models/random.h>
#include <rfir/slam/CParticlePose2D.h>
#include <rfir/slam/motion_model.h>
#include <rfir/slam/tag_correlation.h>

#include <optional>
#include <vector>

namespace rfir::slam {
using TPoseParticleData =
    mrpt::bayes::CParticleFilterData<CParticlePose2D,
                                     mrpt::bayes::particle_storage_mode::VALUE>;

class CRobotPoseParticles
    : public TPoseParticleData,
      public mrpt::bayes::CParticleFilterDataImpl<CRobotPoseParticles,
                                                  TPoseParticleData::CParticleList> {
  public:
    /** M particles at `start`, with Gaussian spread (std) in xy and heading;
     * `rng` (the engine's, outliving this set) draws their motion too. */
    void reset(const mrpt::poses::CPose2D& start, size_t M, double stdXY, double stdPhi,
               rfir::models::TRandom& rng);

    /** The engine's stages inside CParticleFilter::executeOn, fixed for the
     * run (setStepModel), not installed per step. */
    class IStepModel {
      public:
        virtual ~IStepModel() = default;
        /** After the motion, before the weighing: the reads resolved once
         * and, under the literal policy, the tag update. */
        virtual void afterMotion() = 0;
        /** Whether this step's observation weighs the robot. */
        virtual bool weighs() const = 0;
        /** Log-likelihood of particle i at its moved pose. */
        virtual double logLikelihood(size_t i, const CParticlePose2D& pose) const = 0;
    };
    void setStepModel(IStepModel* m) { m_model = m; }
    /** The per-particle heading drift (TMotionOptions::heading_drift_std,
     * heading_drift_walk), used from the next reset on (drawMotion). */
    void setHeadingDrift(const THeadingDrift& d) { m_headingDrift = d; }

    mrpt::poses::CPose2D meanPose() const;
    /** Weighted mean pose and covariance of the particles (one pass). */
    TPoseMoments poseMoments() const;
    /** @name The moments of a step's weighing (the map correction's input),
     * summed in one pass each while trackMoments is on: the moved particles
     * under the weights before the weighing (prior), and under the
     * normalised weights after it (posterior, before any resampling). Empty
     * when this step did not weigh.
     * @{ */
    void trackMoments(bool on) { m_track = on; }
    std::optional<TPoseMoments> priorMoments() const;
    std::optional<TPoseMoments> posteriorMoments() const;
    /** @} */

    /** @name The last step's weighing, as it weighed: per-particle
     * log-likelihoods and the log of their mean under the weights before it
     * (the step's evidence). Empty / 0 when the step did not weigh.
     * @{ */
    const std::vector<double>& stepLogLik() const { return m_stepLogLik; }
    /** The evidence of other per-particle terms under this step's prior
     * weights (log_w before the weighing): e.g. the weighing without its
     * outlier mixture. terms.size() must be the particle count. */
    double stepLogEvidence(const std::vector<double>& terms) const;
    /** @} */

    /** Replaces particle i's pose (sensor resetting), with the log-weight
     * `logW` and this step's weighing term `stepLogLik` at the new pose. The
     * particle keeps its drift hypothesis. */
    void replacePose(size_t i, const mrpt::poses::CPose2D& p, double logW,
                     double stepLogLik);
    /** The highest prior log-weight of this step (log_w minus its weighing
     * term); the current best log-weight when the step did not weigh. */
    double bestPriorLogW() const;

    /** @name CParticleFilterCapable, on m_particles directly: the same
     * arithmetic as MRPT's CParticleFilterDataImpl, without its dynamic_cast
     * per particle access.
     * @{ */
    double getW(size_t i) const override;
    void setW(size_t i, double w) override;
    size_t particlesCount() const override { return m_particles.size(); }
    double normalizeWeights(double* out_max_log_w = nullptr) override;
    double ESS() const override;
    void performSubstitution(const std::vector<size_t>& indx) override;
    /** @} */

  protected:
    rfir::models::TRandom* m_rng = nullptr;  //!< the engine's generator
    IStepModel* m_model = nullptr;           //!< the engine (motion only if none)
    unsigned m_moves = 0;                    //!< motion draws (drawMotion)
    THeadingDrift m_headingDrift;            //!< setHeadingDrift
    /** Particle i's heading drift (rad/m), empty without a drift state. */
    std::vector<double> m_drift;
    double m_ess = -1;                 //!< ESS computed by normalizeWeights; < 0: stale
    std::vector<double> m_stepLogLik;  //!< this step's weighing terms
    /** The last normalizeWeights' log-weights and their exp, which meanPose
     * reuses while the particles still hold those log-weights (checked: a
     * comparison per particle instead of an exp). */
    std::vector<double> m_normLogW, m_normW;
    bool m_track = false;             //!< accumulate the weighing's moments
    CPoseMomentSums m_prior, m_post;  //!< this step's, when m_*Valid
    bool m_priorValid = false, m_postValid = false;
    /** Linear weight of particle i (log-weight lw) before this step's weighing. */
    double priorWeight(size_t i, double lw) const;
    /** sums := the moments of the particles under weight(i, log_w). */
    template <class W>
    void accumulate(CPoseMomentSums& sums, W weight) const;

    void prediction_and_update_pfStandardProposal(
        const mrpt::obs::CActionCollection* action,
        const mrpt::obs::CSensoryFrame* observation,
        const mrpt::bayes::CParticleFilter::TParticleFilterOptions& o) override;
};

}  // namespace rfir::slam
