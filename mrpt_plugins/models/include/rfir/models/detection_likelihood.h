/* rfir: likelihood of an HF RFID detection (SPEC section 2; eq. 5 of the PF-SLAM
 * paper, eq. 3.7 of the thesis): the read model (read_model.h) composed with
 * one of the noise models (read_noise.h). */
#pragma once

#include <rfir/models/read_model.h>
#include <rfir/models/read_noise.h>

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <cmath>

namespace rfir::models {
/** One reader's detection rectangle in the robot frame: centre (x, y) and
 * half-sizes (halfX, halfY), axis-aligned with the robot (metres). */
struct ReaderArea {
    double x = 0, y = 0;
    double halfX = 0.03, halfY = 0.03;
};

enum class DetectionModel {
    Step,     //!< the papers' model: flat inside the rectangle, Gaussian tail
    Gaussian  //!< a plain Gaussian around the reader centre
};

struct DetectionModelParams {
    DetectionModel model = DetectionModel::Step;
    /** Step model: gain of the tail so that w is about 1 at the edge. The papers
     * use 1.618 (sigma = 30 mm); exp(1/2) = 1.6487 would make it exactly 1. */
    double beta = 1.618;
    /** Gaussian model: sigma per axis = scale * half-size. */
    double gaussianSigmaScale = 1.0;
    /** Outlier mixture (COutlierMixture) over the model above: share eps of
     * reads from anywhere, with log-likelihood `outlierLogFloor` (relative to
     * the model's best, 0). 0 = off, the papers' model alone. INI
     * [tagmap_likelihood] outlier_weight, outlier_log_floor (docs/slam.md).
     * The floor also marks a read as contradicted (contradicts()). */
    double outlierWeight = 0.0;
    double outlierLogFloor = -10.0;
};

/** Functor over the models: e from readModel, then the noise model.
 * Likelihoods are unnormalised (max 1): only ratios between particles matter
 * to the filters. */
class DetectionLikelihood {
  public:
    DetectionLikelihood() = default;
    explicit DetectionLikelihood(const DetectionModelParams& p)
        : m_p(p),
          m_step(p.beta),
          m_gauss(p.gaussianSigmaScale),
          m_mix(p.outlierWeight, p.outlierLogFloor) {}

    /** (ex, ey) in the robot frame, half-sizes of the detecting reader. */
    double logLikelihoodOffset(double ex, double ey, double hx, double hy) const {
        return m_mix.mix(baseLogLikelihoodOffset(ex, ey, hx, hy));
    }
    /** The base model alone, without the outlier mixture. */
    double baseLogLikelihoodOffset(double ex, double ey, double hx, double hy) const {
        return m_p.model == DetectionModel::Step ? m_step.logLik(ex, ey, hx, hy)
                                                 : m_gauss.logLik(ex, ey, hx, hy);
    }
    /** The outlier mixture applied to a base log-likelihood (identity when
     * off); also to one already averaged over a tag's samples. */
    double withOutliers(double baseLogLik) const { return m_mix.mix(baseLogLik); }
    /** Tag at `tag` (world), reader `r` placed by the robot pose `robot` (eq. 6
     * of the PF-SLAM paper), offset rotated into the robot frame. */
    double logLikelihood(const mrpt::math::TPose2D& robot, const ReaderArea& r,
                         const mrpt::math::TPoint2D& tag) const;
    /** The same, given c = cos(robot.phi) and s = sin(robot.phi): a particle
     * weighed against several reads computes them once. */
    double logLikelihood(const mrpt::math::TPose2D& robot, double c, double s,
                         const ReaderArea& r, const mrpt::math::TPoint2D& tag) const;
    /** logLikelihood without the mixture: the robot's weighing mixes the
     * sum over a tag's samples, and the kidnap check reads the base terms
     * (a kidnapping is a drop the mixture would cap). */
    double baseLogLikelihood(const mrpt::math::TPose2D& robot, double c, double s,
                             const ReaderArea& r, const mrpt::math::TPoint2D& tag) const {
        const auto e = readModel(robot, c, s, r.x, r.y, tag);
        return baseLogLikelihoodOffset(e.x, e.y, r.halfX, r.halfY);
    }

    /** True if the base model (without the mixture) gives this read a
     * log-likelihood below outlierLogFloor: the mixture, at any weight, would
     * call it a random reading rather than a read of a tag at `tag`. */
    bool contradicts(const mrpt::math::TPose2D& robot, const ReaderArea& r,
                     const mrpt::math::TPoint2D& tag) const;
    /** The same, or `tag` lies more than `margin` (m; negative: off) outside
     * the reader's square along the farther axis of the reader's frame
     * ([tagmap] contradict_margin); one readModel for both tests. */
    bool contradicts(const mrpt::math::TPose2D& robot, const ReaderArea& r,
                     const mrpt::math::TPoint2D& tag, double margin) const;

  private:
    DetectionModelParams m_p;
    CStepReadNoise m_step;
    CGaussianReadNoise m_gauss;
    COutlierMixture m_mix;
};

/** World position of a reader's centre for a robot pose (eq. 6 of 003). */
inline mrpt::math::TPoint2D readerCentreInWorld(const mrpt::math::TPose2D& robot,
                                                const ReaderArea& r) {
    return robotFrameToWorld(robot, std::cos(robot.phi), std::sin(robot.phi), r.x, r.y);
}

}  // namespace rfir::models
