/* rfir: the per-landmark EKF of FastSLAM 1.0 (SPEC section 6) and its
 * Gaussian measurement models.
 * - RFID: the tag position in the robot frame is measured as the centre of
 *   the detecting reader, with the variance of a uniform position over the
 *   detection square (half side h: h^2/3) scaled by `rfidStdFactor^2 * 3`.
 * - Range-bearing (004, section 4.2): z = (|d|, atan2(d) - phi_s) with d the
 *   landmark minus the sensor position; the usual Jacobians. */
#pragma once

#include <rfir/slam/detections.h>

#include <mrpt/poses/CPose2D.h>
#include <Eigen/Dense>

#include <cstddef>

namespace rfir::slam {
struct TLandmarkEKF {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    Eigen::Matrix2d cov = Eigen::Matrix2d::Identity();

    TLandmarkEKF() = default;
    TLandmarkEKF(const TLandmarkEKF& o) : mean(o.mean), cov(o.cov) { ++copyCount(); }
    TLandmarkEKF& operator=(const TLandmarkEKF& o) = default;
    /** EKFs copied so far (the copy-on-write test counts them). */
    static size_t& copyCount() {
        static size_t n = 0;
        return n;
    }
};

/** Measurement noise of the Gaussian models (INI section [fastslam]). */
struct TGaussianMeasurementParams {
    /** RFID: std of the tag position about the reader centre, as a fraction
     * of the half side (1/sqrt(3) = 0.577 is the std of a uniform square). */
    double rfidStdFactor = 0.577;
    double rbStdRange = 0.01;       //!< m, used when the observation gives none
    double rbStdBearing = 0.05236;  //!< rad (3 deg), likewise
};

/** A detection linearised at a landmark estimate. */
struct TLinearMeasurement {
    Eigen::Vector2d innovation;  //!< z - h(mean), bearing wrapped to (-pi, pi]
    Eigen::Matrix2d H;           //!< dh/dm
    Eigen::Matrix2d R;           //!< measurement covariance
};

/** Gaussian measurement model for one detection seen from `robot`. */
class CGaussianLandmarkModel {
  public:
    explicit CGaussianLandmarkModel(const TGaussianMeasurementParams& p) : p_(p) {}

    /** Linearisation of detection d at landmark position m. */
    TLinearMeasurement linearize(const TDetection& d, const mrpt::poses::CPose2D& robot,
                                 const Eigen::Vector2d& m) const;
    /** The landmark EKF a first detection implies (inverse model). */
    TLandmarkEKF initialize(const TDetection& d, const mrpt::poses::CPose2D& robot) const;
    Eigen::Matrix2d noise(const TDetection& d) const;

  private:
    TGaussianMeasurementParams p_;
};

/** EKF update of `lm` (in place); returns log N(innovation; 0, H P H^T + R),
 * the FastSLAM 1.0 importance factor of the detection. */
double ekfUpdate(TLandmarkEKF& lm, const TLinearMeasurement& z);

}  // namespace rfir::slam
