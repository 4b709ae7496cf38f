#include <rfir/models/range_bearing.h>
#include <rfir/models/read_model.h>
#include <rfir/slam/landmark_ekf.h>

#include <mrpt/core/bits_math.h>

#include <cmath>

namespace rfir::slam {
namespace {
mrpt::math::TPose2D tpose(const mrpt::poses::CPose2D& p) {
    return {p.x(), p.y(), p.phi()};
}
template <class M>
Eigen::Matrix2d mat(const M& a) {
    Eigen::Matrix2d r;
    r << a[0][0], a[0][1], a[1][0], a[1][1];
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
        // The read model's e = tag - reader centre (a, b), robot frame: z - h = -e.
        rfir::models::TReadJacobians J;
        const auto e =
            rfir::models::readModel(tpose(robot), d.a, d.b, {m.x(), m.y()}, &J);
        z.innovation = Eigen::Vector2d(-e.x, -e.y);
        z.H = mat(J.tag);
        return z;
    }
    rfir::models::TRangeBearingJacobians J;
    const auto h =
        rfir::models::rangeBearingModel(tpose(robot + d.sensor), {m.x(), m.y()}, &J);
    z.innovation = Eigen::Vector2d(d.a - h.range, mrpt::math::wrapToPi(d.b - h.bearing));
    z.H = mat(J.landmark);
    return z;
}

TLandmarkEKF CGaussianLandmarkModel::initialize(const TDetection& d,
                                                const mrpt::poses::CPose2D& robot) const {
    TLandmarkEKF lm;
    const Eigen::Matrix2d R = noise(d);
    if (d.kind == TDetection::Kind::RFID) {
        // Inverse read model: the tag at the reader centre; d(tag)/d(offset)
        // = R(phi) = (dh/dtag)^T.
        const auto t = tpose(robot);
        const auto c = rfir::models::robotFrameToWorld(t, std::cos(t.phi),
                                                       std::sin(t.phi), d.a, d.b);
        rfir::models::TReadJacobians J;
        rfir::models::readModel(t, d.a, d.b, c, &J);
        const Eigen::Matrix2d Rr = mat(J.tag).transpose();
        lm.mean = Eigen::Vector2d(c.x, c.y);
        lm.cov = Rr * R * Rr.transpose();
        return lm;
    }
    double G[2][2];  // d(mean)/d(range, bearing)
    const auto p =
        rfir::models::rangeBearingToPoint(tpose(robot + d.sensor), d.a, d.b, G);
    lm.mean = Eigen::Vector2d(p.x, p.y);
    lm.cov = mat(G) * R * mat(G).transpose();
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
