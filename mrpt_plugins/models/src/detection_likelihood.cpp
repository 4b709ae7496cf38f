/* rfir: HF RFID detection likelihood (SPEC section 2; 003 eq. 5; thesis eq. 3.7). */
#include <rfir/models/detection_likelihood.h>

#include <cmath>

namespace rfir::models {
namespace {
double stepLogLik(double ex, double ey, double hx, double hy, double logBeta) {
    // Thesis eq. 3.7: flat (w = 1) inside the square |e_x|,|e_y| < sigma;
    // outside, a Gaussian tail scaled by beta so w is about 1 at the edge.
    // Rectangular readers: sigma per axis = half-size.
    if (std::abs(ex) < hx && std::abs(ey) < hy) return 0.0;
    return logBeta - 0.5 * (ex * ex / (hx * hx) + ey * ey / (hy * hy));
}
}  // namespace

double stepDetectionLogLikelihood(double ex, double ey, double hx, double hy,
                                  double beta) {
    return stepLogLik(ex, ey, hx, hy, std::log(beta));
}

double gaussianDetectionLogLikelihood(double ex, double ey, double sx, double sy) {
    return -0.5 * (ex * ex / (sx * sx) + ey * ey / (sy * sy));
}

double DetectionLikelihood::logLikelihoodOffset(double ex, double ey, double hx,
                                                double hy) const {
    if (m_p.model == DetectionModel::Step) return stepLogLik(ex, ey, hx, hy, m_logBeta);
    const double k = m_p.gaussianSigmaScale;
    return gaussianDetectionLogLikelihood(ex, ey, k * hx, k * hy);
}

mrpt::math::TPoint2D readerCentreInWorld(const mrpt::math::TPose2D& robot,
                                         const ReaderArea& r) {
    // 003 eq. 6: reader centre = robot position + R(theta) * reader offset.
    const double c = std::cos(robot.phi), s = std::sin(robot.phi);
    return {robot.x + c * r.x - s * r.y, robot.y + s * r.x + c * r.y};
}

double DetectionLikelihood::logLikelihood(const mrpt::math::TPose2D& robot,
                                          const ReaderArea& r,
                                          const mrpt::math::TPoint2D& tag) const {
    return logLikelihood(robot, std::cos(robot.phi), std::sin(robot.phi), r, tag);
}

double DetectionLikelihood::logLikelihood(const mrpt::math::TPose2D& robot, double c,
                                          double s, const ReaderArea& r,
                                          const mrpt::math::TPoint2D& tag) const {
    // e = tag - reader centre, expressed in the robot frame (thesis eq. 3.7).
    const double dx = tag.x - robot.x, dy = tag.y - robot.y;
    const double ex = c * dx + s * dy - r.x;
    const double ey = -s * dx + c * dy - r.y;
    return logLikelihoodOffset(ex, ey, r.halfX, r.halfY);
}

double DetectionLikelihood::likelihood(const mrpt::math::TPose2D& robot,
                                       const ReaderArea& r,
                                       const mrpt::math::TPoint2D& tag) const {
    return std::exp(logLikelihood(robot, r, tag));
}

}  // namespace rfir::models
