/* rfir: FastSLAM 1.0 (SPEC section 6), the baseline of both papers, on MRPT's
 * particle-filter machinery. Each robot particle carries one EKF per landmark
 * in a copy-on-write trie (persistent_vector.h): resampling copies pointers,
 * an update copies one EKF and its trie path. */
#pragma once

#include <rfir/models/random.h>

#include <rfir/slam/CParticlePose2D.h>
#include <rfir/slam/detections.h>
#include <rfir/slam/landmark_ekf.h>
#include <rfir/slam/motion_model.h>
#include <rfir/slam/persistent_vector.h>

#include <mrpt/bayes/CParticleFilterCapable.h>
#include <mrpt/bayes/CParticleFilterData.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose2D.h>

#include <map>
#include <string>
#include <vector>

namespace rfir::slam {
struct TFastSLAMParticle {
    CParticlePose2D pose;
    CPersistentVector<TLandmarkEKF> landmarks;  //!< by CFastSLAMParticles index
    double drift = 0;  //!< heading drift, rad/m (TMotionOptions::heading_drift_std)
};

/** INI section [fastslam]. */
struct TFastSLAMOptions : public mrpt::config::CLoadableOptions {
    TGaussianMeasurementParams meas;
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                            const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c,
                          const std::string& s) const override;
};

class CFastSLAMParticles
    : public mrpt::bayes::CParticleFilterData<TFastSLAMParticle,
                                              mrpt::bayes::particle_storage_mode::VALUE>,
      public mrpt::bayes::CParticleFilterDataImpl<
          CFastSLAMParticles,
          mrpt::bayes::CParticleFilterData<
              TFastSLAMParticle,
              mrpt::bayes::particle_storage_mode::VALUE>::CParticleList> {
  public:
    explicit CFastSLAMParticles(const TFastSLAMOptions& o = {}) : model_(o.meas) {}

    /** M particles at `start`, with Gaussian spread (std) in xy and heading;
     * `rng` (the engine's, outliving this set) draws their motion too. */
    void reset(const mrpt::poses::CPose2D& start, size_t M, double stdXY, double stdPhi,
               rfir::models::TRandom& rng);
    /** The per-particle heading drift (TMotionOptions::heading_drift_std,
     * heading_drift_walk), used from the next reset on. */
    void setHeadingDrift(const THeadingDrift& d) { drift_ = d; }
    /** The detections the next CParticleFilter::executeOn step weighs with. */
    void setDetections(const std::vector<TDetection>* d) { detections_ = d; }

    /** Weighted mean of the robot particles. */
    mrpt::poses::CPose2D meanPose() const;
    struct TLandmarkEstimate {
        std::string id;
        bool isTag;  //!< RFID tag, else range-bearing landmark
        Eigen::Vector2d mean;
        Eigen::Matrix2d cov;
    };
    /** Per landmark, the weighted mixture of the particles' EKFs. */
    std::vector<TLandmarkEstimate> landmarks() const;
    size_t landmarkCount() const { return names_.size(); }

  protected:
    void prediction_and_update_pfStandardProposal(
        const mrpt::obs::CActionCollection* action,
        const mrpt::obs::CSensoryFrame* observation,
        const mrpt::bayes::CParticleFilter::TParticleFilterOptions& o) override;

  private:
    size_t indexOf(const TDetection& d);
    double updateParticle(TFastSLAMParticle& p, const std::vector<size_t>& idx);

    CGaussianLandmarkModel model_;
    rfir::models::TRandom* rng_ = nullptr;  //!< the engine's generator
    unsigned moves_ = 0;                    //!< motion draws (drawMotion)
    THeadingDrift drift_;                   //!< setHeadingDrift
    const std::vector<TDetection>* detections_ = nullptr;
    std::map<std::string, size_t> index_;
    std::vector<std::string> names_;
    std::vector<bool> isTag_;
};

}  // namespace rfir::slam
