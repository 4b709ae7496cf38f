/* rfir: the [slam] section shared by every method: the robot filter. */
#pragma once

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace rfir::slam {
enum class TMethod {
    PF,        //!< PF-SLAM: robot particle filter + per-tag particle filters
    PS,        //!< PS-SLAM: robot particle filter + per-tag fixed-lag smoothers
    FastSLAM,  //!< FastSLAM 1.0 baseline: one EKF per tag per robot particle
    Odometry   //!< dead reckoning (tags mapped from odometry poses), for comparison
};
TMethod parseMethod(const std::string& name);  //!< throws naming [slam] method
std::string methodName(TMethod m);

/** INI section [slam]. */
struct TSlamOptions : public mrpt::config::CLoadableOptions {
    /** Where the tags are updated from with a weigh-first policy. */
    enum class TTagUpdatePose { Posterior, Predicted };

    // Enums parsed once, here at load; saveToConfigFile writes their names.
    TMethod method = TMethod::PF;
    unsigned robot_particles = 500;  //!< M (SPEC section 4)
    mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm resampling =
        mrpt::bayes::CParticleFilter::prSystematic;
    /** Resample when the normalised effective sample size drops below this;
     * 1 resamples on every step, as the papers' algorithms do. */
    double resample_ess = 0.5;
    double start_std_xy = 0.0;   //!< m, initial spread about the start pose
    double start_std_phi = 0.0;  //!< rad
    /** PF/PS with a weigh-first policy: the robot pose the tags are updated
     * with, "posterior" (after weighing) or "predicted" (before). */
    TTagUpdatePose tag_update_pose = TTagUpdatePose::Posterior;
    /** PF/PS: tags mapped from an uncertain robot follow the robot's later
     * corrections through their cross-covariance with it (tag_correlation.h;
     * off: the papers' algorithm, the map keeps a first lap's drift). */
    bool map_correction = false;
    /** m: a tag whose share of the robot's position error falls below this
     * stops following the robot. */
    double map_correction_min_std = 0.002;
    /** At most this many tags follow the robot (the oldest leave first): a
     * correction's cost stays bounded whatever the map's size. */
    unsigned map_correction_max_tags = 1000;
    /** PF/PS, s: a read of a tag weighs the robot only if the same tag was
     * also read within this long before it (by any reader), so that a
     * single ghost read cannot pull a wide robot cloud (0: every read). */
    double read_confirm_window = 0;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                            const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c,
                          const std::string& s) const override;
    /** The CParticleFilter options these settings imply. */
    mrpt::bayes::CParticleFilter::TParticleFilterOptions pfOptions() const;
};

/** Weighted mean of poses (circular mean of the headings), weights given as
 * logs; `get(i)` returns pose i. */
template <class GetPose>
mrpt::poses::CPose2D weightedMeanPose(size_t n, const std::vector<double>& logw,
                                      GetPose get);
/** The same, log-weight i given by `logw(i)`. */
template <class GetLogW, class GetPose>
mrpt::poses::CPose2D weightedMeanPose(size_t n, GetLogW logw, GetPose get);
/** The same from linear weights `w(i)` (exp of the log-weight minus the
 * largest one: the same arithmetic as the log forms). */
template <class GetW, class GetPose>
mrpt::poses::CPose2D weightedMeanPoseLinear(size_t n, GetW w, GetPose get);

}  // namespace rfir::slam

#include <cmath>
namespace rfir::slam {
template <class GetPose>
mrpt::poses::CPose2D weightedMeanPose(size_t n, const std::vector<double>& logw,
                                      GetPose get) {
    return weightedMeanPose(
        n, [&](size_t i) { return logw[i]; }, get);
}

template <class GetLogW, class GetPose>
mrpt::poses::CPose2D weightedMeanPose(size_t n, GetLogW logw, GetPose get) {
    double mx = -1e300;
    for (size_t i = 0; i < n; i++) mx = std::max(mx, logw(i));
    return weightedMeanPoseLinear(
        n, [&](size_t i) { return std::exp(logw(i) - mx); }, get);
}

template <class GetW, class GetPose>
mrpt::poses::CPose2D weightedMeanPoseLinear(size_t n, GetW weight, GetPose get) {
    double sw = 0, x = 0, y = 0, c = 0, s = 0;
    for (size_t i = 0; i < n; i++) {
        const double w = weight(i);
        const auto& p = get(i);  // CParticlePose2D: its cos, sin read inline
        sw += w;
        x += w * p.x();
        y += w * p.y();
        c += w * p.phi_cos();  // cached in the pose
        s += w * p.phi_sin();
    }
    if (sw <= 0) return get(0);
    return {x / sw, y / sw, std::atan2(s, c)};
}
}  // namespace rfir::slam
