/* rfir: HF RFID detection likelihood (SPEC section 2; 003 eq. 5; thesis eq. 3.7):
 * readModel's e, then the noise model. */
#include <rfir/models/detection_likelihood.h>

#include <algorithm>
#include <cmath>

namespace rfir::models {
double DetectionLikelihood::logLikelihood(const mrpt::math::TPose2D& robot,
                                          const ReaderArea& r,
                                          const mrpt::math::TPoint2D& tag) const {
    return logLikelihood(robot, std::cos(robot.phi), std::sin(robot.phi), r, tag);
}

double DetectionLikelihood::logLikelihood(const mrpt::math::TPose2D& robot, double c,
                                          double s, const ReaderArea& r,
                                          const mrpt::math::TPoint2D& tag) const {
    const auto e = readModel(robot, c, s, r.x, r.y, tag);
    return logLikelihoodOffset(e.x, e.y, r.halfX, r.halfY);
}

bool DetectionLikelihood::contradicts(const mrpt::math::TPose2D& robot,
                                      const ReaderArea& r,
                                      const mrpt::math::TPoint2D& tag) const {
    return contradicts(robot, r, tag, -1);
}

bool DetectionLikelihood::contradicts(const mrpt::math::TPose2D& robot,
                                      const ReaderArea& r,
                                      const mrpt::math::TPoint2D& tag,
                                      double margin) const {
    const auto e = readModel(robot, r.x, r.y, tag);
    if (baseLogLikelihoodOffset(e.x, e.y, r.halfX, r.halfY) < m_p.outlierLogFloor)
        return true;
    return margin >= 0 &&
           std::max(std::abs(e.x) - r.halfX, std::abs(e.y) - r.halfY) > margin;
}

}  // namespace rfir::models
