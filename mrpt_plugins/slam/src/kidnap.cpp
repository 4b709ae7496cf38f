#include <rfir/models/ini_reader.h>
#include <rfir/models/range_bearing.h>
#include <rfir/models/read_model.h>
#include <rfir/slam/kidnap.h>

#include <mrpt/config/CConfigFileBase.h>

#include <cmath>

namespace rfir::slam {
void TKidnapOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s) {
    using R = rfir::ini::TRange;
    const rfir::ini::CIniSection sec(
        c, s,
        {"enabled", "collapse_loglik", "collapse_steps", "inject_fraction",
         "keep_heading_share", "heading_std"});
    enabled = sec.getBool("enabled", enabled);
    // A mean log-likelihood per detection beyond +-1000 means nothing: a
    // density of e^1000 or a collapse on every step.
    collapse_loglik =
        sec.getDouble("collapse_loglik", collapse_loglik, R::closed(-1000, 1000));
    collapse_steps =
        unsigned(sec.getInt("collapse_steps", int64_t(collapse_steps), 1, 1000000));
    inject_fraction = sec.getDouble("inject_fraction", inject_fraction, R::aboveZero(1));
    keep_heading_share =
        sec.getDouble("keep_heading_share", keep_heading_share, R::closed(0, 1));
    heading_std = sec.getDouble("heading_std", heading_std, R::closed(0, M_PI));
}

void TKidnapOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                      const std::string& s) const {
    c.write(s, "enabled", enabled, -1, -1, "sensor resetting on collapse");
    c.write(s, "collapse_loglik", collapse_loglik, -1, -1,
            "lost if best mean log-lik per known detection is below this...");
    c.write(s, "collapse_steps", int(collapse_steps), -1, -1,
            "...for this many steps in a row");
    c.write(s, "inject_fraction", inject_fraction, -1, -1,
            "share of robot particles redrawn from detections");
    c.write(s, "keep_heading_share", keep_heading_share, -1, -1,
            "share of those keeping the current heading");
    c.write(s, "heading_std", heading_std, -1, -1, "their heading std [rad]");
}

bool CKidnapMonitor::update(std::optional<double> bestMeanLogLik) {
    if (!o_.enabled || !bestMeanLogLik) return false;
    if (*bestMeanLogLik >= o_.collapse_loglik) {
        bad_ = 0;
        return false;
    }
    if (++bad_ < o_.collapse_steps) return false;
    bad_ = 0;
    ++resets_;
    return true;
}

mrpt::poses::CPose2D poseFromAnchor(const TAnchor& a, double phi,
                                    rfir::models::TRandom& rng) {
    const TDetection& d = a.det;
    double sx, sy;  // the landmark seen from the pose, robot frame
    if (d.kind == TDetection::Kind::RFID) {
        sx = d.a + rng.drawUniform(-d.halfX, d.halfX);
        sy = d.b + rng.drawUniform(-d.halfY, d.halfY);
    } else {
        const double r = d.a + rng.drawGaussian1D(0, std::max(d.stdRange, 1e-3));
        const double b = d.b + rng.drawGaussian1D(0, std::max(d.stdBearing, 1e-3));
        // The range-bearing inverse model, in the robot frame.
        const auto p = rfir::models::rangeBearingToPoint(
            {d.sensor.x(), d.sensor.y(), d.sensor.phi()}, r, b);
        sx = p.x;
        sy = p.y;
    }
    const auto t = rfir::models::robotPositionFromRead({a.x, a.y}, std::cos(phi),
                                                       std::sin(phi), sx, sy);
    return {t.x, t.y, phi};
}

std::vector<mrpt::poses::CPose2D> resettingPoses(const std::vector<TAnchor>& anchors,
                                                 size_t n, double currentPhi,
                                                 const TKidnapOptions& o,
                                                 rfir::models::TRandom& rng) {
    std::vector<mrpt::poses::CPose2D> out;
    if (anchors.empty()) return out;
    for (size_t i = 0; i < n; i++) {
        const TAnchor& a = anchors[rng.drawUniform32bit() % anchors.size()];
        const double phi = rng.drawUniform(0, 1) < o.keep_heading_share
                               ? currentPhi + rng.drawGaussian1D(0, o.heading_std)
                               : rng.drawUniform(-M_PI, M_PI);
        out.push_back(poseFromAnchor(a, mrpt::math::wrapToPi(phi), rng));
    }
    return out;
}

}  // namespace rfir::slam
