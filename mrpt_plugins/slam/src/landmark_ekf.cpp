#include <rfir/slam/landmark_ekf.h>

#include <mrpt/core/bits_math.h>

#include <cmath>

namespace rfir::slam {
namespace {
Eigen::Matrix2d rot(double phi) {
    Eigen::Matrix2d r;
    r << std::cos(phi), -std::sin(phi), std::sin(phi), std::cos(phi);
    return r;
}
}  // namespace

Eigen::Matrix2d CGaussianLandmarkModel::noise(const TDetection& d) const {
    Eigen::Matrix2d R = Eigen::Matrix2d::Zero();
    if (d.kind == TDetection::Kind::RFID) {
        R(0, 0) = mrpt::square(p_.rfidStdFactor * d.halfX);
        R(1, 1) = mrpt::square(p_.rfidStdFactor * d.halfY);
    } else {
        R(0, 0) = mrpt::square(d.stdRange > 0 ? d.stdRange : p_.rbStdRange);
        R(1, 1) = mrpt::square(d.stdBearing > 0 ? d.stdBearing : p_.rbStdBearing);
    }
    return R;
}

TLinearMeasurement CGaussianLandmarkModel::linearize(const TDetection& d,
                                                     const mrpt::poses::CPose2D& robot,
                                                     const Eigen::Vector2d& m) const {
    TLinearMeasurement z;
    z.R = noise(d);
    if (d.kind == TDetection::Kind::RFID) {
        // h(m) = Rot(phi)^T (m - t): the tag in the robot frame.
        const Eigen::Matrix2d Rt = rot(robot.phi()).transpose();
        const Eigen::Vector2d h = Rt * (m - Eigen::Vector2d(robot.x(), robot.y()));
        z.innovation = Eigen::Vector2d(d.a, d.b) - h;
        z.H = Rt;
        return z;
    }
    const mrpt::poses::CPose2D s = robot + d.sensor;
    const double dx = m.x() - s.x(), dy = m.y() - s.y();
    const double q = std::max(dx * dx + dy * dy, 1e-12), r = std::sqrt(q);
    z.innovation = Eigen::Vector2d(
        d.a - r, mrpt::math::wrapToPi(d.b - (std::atan2(dy, dx) - s.phi())));
    z.H << dx / r, dy / r, -dy / q, dx / q;
    return z;
}

TLandmarkEKF CGaussianLandmarkModel::initialize(const TDetection& d,
                                                const mrpt::poses::CPose2D& robot) const {
    TLandmarkEKF lm;
    const Eigen::Matrix2d R = noise(d);
    if (d.kind == TDetection::Kind::RFID) {
        const Eigen::Matrix2d Rr = rot(robot.phi());
        lm.mean = Eigen::Vector2d(robot.x(), robot.y()) + Rr * Eigen::Vector2d(d.a, d.b);
        lm.cov = Rr * R * Rr.transpose();
        return lm;
    }
    const mrpt::poses::CPose2D s = robot + d.sensor;
    const double a = s.phi() + d.b, c = std::cos(a), sn = std::sin(a);
    lm.mean = Eigen::Vector2d(s.x() + d.a * c, s.y() + d.a * sn);
    Eigen::Matrix2d G;  // d(mean)/d(range, bearing)
    G << c, -d.a * sn, sn, d.a * c;
    lm.cov = G * R * G.transpose();
    return lm;
}

double ekfUpdate(TLandmarkEKF& lm, const TLinearMeasurement& z) {
    const Eigen::Matrix2d S = z.H * lm.cov * z.H.transpose() + z.R;
    const Eigen::Matrix2d Sinv = S.inverse();
    const Eigen::Matrix<double, 2, 2> K = lm.cov * z.H.transpose() * Sinv;
    lm.mean += K * z.innovation;
    lm.cov = (Eigen::Matrix2d::Identity() - K * z.H) * lm.cov;
    lm.cov = 0.5 * (lm.cov + lm.cov.transpose());
    const double maha = z.innovation.dot(Sinv * z.innovation);
    return -0.5 * maha - 0.5 * std::log(S.determinant()) - std::log(2 * M_PI);
}

}  // namespace rfir::slam
