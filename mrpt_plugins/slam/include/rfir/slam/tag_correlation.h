/* rfir: the tags of PF-SLAM's and PS-SLAM's one shared map that still move
 * with the robot. A tag mapped from an uncertain robot pose carries that
 * pose's error: tag = robot xy + R(phi) l, so its cross-covariance with the
 * robot pose is C = J P (J = [I2 | (-ly, lx)], P the robot's 3x3
 * covariance), and as the robot moves on C follows the motion's Jacobian,
 * which over any stretch is the shear of the mean displacement (EKF-SLAM's
 * robot-map terms). When a return to known tags corrects the robot by d, the
 * linear-Gaussian conditional moves each such tag by C P^-1 d and makes C
 * C P^-1 P+ (the Kalman update restricted to the robot-tag terms; tag-tag
 * terms are not kept). So the tags of a drifted first lap follow the loop
 * closure, as FastSLAM's per-particle maps do by resampling. C is kept
 * consistent with the tag's own share of the robot's error (C P^-1 C^T <= T),
 * so that a cloud narrower than the one C was built with cannot amplify a
 * small correction into a large shift. */
#pragma once

#include <Eigen/Core>

#include <cmath>

#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace rfir::slam {
/** Weighted mean and covariance of the robot particles' poses (x, y, phi;
 * the headings as deviations from a reference heading, wrapped). */
struct TPoseMoments {
    double x = 0, y = 0, phi = 0;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
};

/** TPoseMoments in one pass, accumulated inside loops that already visit
 * every particle: raw weighted sums of the deviations from a reference pose
 * (one of the particles, so that millimetre spreads on coordinates of tens
 * of metres lose nothing to cancellation). Headings are kept in [-pi, pi],
 * so one wrap of a difference suffices. */
class CPoseMomentSums {
  public:
    void start(double x, double y, double phi) {
        *this = CPoseMomentSums();
        m_rx = x;
        m_ry = y;
        m_rp = phi;
    }
    void add(double w, double x, double y, double phi) {
        // Scalars, the six distinct second moments: this runs per particle.
        const double dx = x - m_rx, dy = y - m_ry, dp = wrapOnce(phi - m_rp);
        const double wx = w * dx, wy = w * dy, wp = w * dp;
        m_w += w;
        m_x += wx;
        m_y += wy;
        m_p += wp;
        m_xx += wx * dx;
        m_yy += wy * dy;
        m_pp += wp * dp;
        m_xy += wx * dy;
        m_xp += wx * dp;
        m_yp += wy * dp;
    }
    /** The weighted mean and covariance (biased: normalised by the weights). */
    TPoseMoments moments() const;

  private:
    static double wrapOnce(double a) {
        return a > M_PI ? a - 2 * M_PI : (a < -M_PI ? a + 2 * M_PI : a);
    }
    double m_rx = 0, m_ry = 0, m_rp = 0;  //!< the reference pose
    double m_w = 0, m_x = 0, m_y = 0, m_p = 0;
    double m_xx = 0, m_yy = 0, m_pp = 0, m_xy = 0, m_xp = 0, m_yp = 0;
};

class CTagRobotCorrelation {
  public:
    /** Shift callback: (id, landmark, dx, dy). */
    using TShift = std::function<void(const std::string&, bool, double, double)>;

    /** minStd (m): a tag whose cross-covariance with the robot position has
     * shrunk below minStd^2 leaves the set: it no longer moves with it. */
    /** maxTags: at most this many tags follow the robot; a new one pushes
     * out the oldest (so a correction costs O(maxTags) whatever the map's
     * size; in the stock runs the set stayed under 150). */
    explicit CTagRobotCorrelation(double minStd = 0.002, size_t maxTags = 1000)
        : m_minVar(minStd * minStd), m_maxTags(maxTags) {}

    void clear() { m_active.clear(); }
    /** A tag (or landmark) just mapped at (tx, ty) from a robot with these
     * pose moments. */
    void add(const std::string& id, bool landmark, double tx, double ty,
             const TPoseMoments& robot);
    /** The weighing moved the robot's moments from `before` to `after`:
     * moves every correlated tag through `shift`, updates C. Returns the
     * number of tags moved. */
    size_t correct(const TPoseMoments& before, const TPoseMoments& after,
                   const TShift& shift);
    /** The tags that weighed the robot in this step: the weighing took them
     * as independent of it, so moving them with its correction would feed it
     * back (robot and tag chasing each other); they leave the set. */
    void drop(const std::vector<std::string>& ids);
    size_t size() const { return m_active.size(); }

  private:
    struct TEntry {
        std::string id;
        bool landmark = false;
        Eigen::Matrix<double, 2, 3> C;  //!< cross-covariance at the reference
        /** The tag's variance from the robot's error (J P J^T at the first
         * read, less what corrections took): C P^-1 C^T may not exceed it
         * (the joint covariance stays positive), which bounds a shift. */
        Eigen::Matrix2d T;
        double refX = 0, refY = 0;  //!< robot mean position C refers to
    };
    std::deque<TEntry> m_active;  //!< oldest first
    double m_minVar;
    size_t m_maxTags;
};

/** The map correction as the PF/PS engine runs it: a weighing's correction
 * waits while the kidnap detector's run of disagreeing steps is open (the
 * pose may be wrong), is applied once a step maps again, and is dropped with
 * a sensor resetting (the correlations then mean nothing). */
class CMapCorrection {
  public:
    explicit CMapCorrection(double minStd = 0.002, size_t maxTags = 1000)
        : m_corr(minStd, maxTags) {}
    void clear();
    /** A tag (or landmark) first mapped at (tx, ty) from these moments. */
    void mapped(const std::string& id, bool landmark, double tx, double ty,
                const TPoseMoments& robot) {
        m_corr.add(id, landmark, tx, ty, robot);
    }
    /** The reads of `ids` moved the robot's moments from `before` to `after`. */
    void weighed(const TPoseMoments& before, const TPoseMoments& after,
                 const std::vector<std::string>& ids);
    /** End of a step: a resetting drops what waits; a step that maps applies
     * it (the weighing tags leave the set first). Returns the tags moved. */
    size_t settle(bool reset, bool mapping, const CTagRobotCorrelation::TShift& shift);
    size_t size() const { return m_corr.size(); }

  private:
    CTagRobotCorrelation m_corr;
    std::vector<std::pair<TPoseMoments, TPoseMoments>> m_pending;
    std::vector<std::string> m_pendingIds;
};

}  // namespace rfir::slam
