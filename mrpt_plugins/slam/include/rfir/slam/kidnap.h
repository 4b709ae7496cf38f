/* rfir: kidnapping recovery (thesis 3.4.3) by sensor resetting. The robot
 * filter is taken as lost when, for `collapse_steps` steps in a row, even its
 * best particle explains the detections of known landmarks badly (mean
 * log-likelihood per known detection below `collapse_loglik`). Then a
 * fraction of the particles is redrawn where a re-detected known landmark
 * lies in the detecting reader's area (or at the measured range and bearing),
 * and the map is not updated while the filter is lost. */
#pragma once

#include <rfir/slam/detections.h>

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <rfir/models/random.h>

#include <optional>
#include <vector>

namespace rfir::slam {
/** INI section [kidnap]. */
struct TKidnapOptions : public mrpt::config::CLoadableOptions {
    bool enabled = true;
    double collapse_loglik = -4.0;  //!< per known detection, best particle
    unsigned collapse_steps = 3;
    double inject_fraction = 0.5;  //!< of the robot particles, per resetting
    /** Share of injected particles that keep the current heading estimate
     * (with heading_std noise); the rest get a uniform heading. */
    double keep_heading_share = 0.5;
    double heading_std = 0.1;  //!< rad

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                            const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c,
                          const std::string& s) const override;
};

/** A detection of a landmark whose position the map already knows. */
struct TAnchor {
    TDetection det;
    double x = 0, y = 0;  //!< landmark estimate, world frame
};

class CKidnapMonitor {
  public:
    explicit CKidnapMonitor(const TKidnapOptions& o = {}) : o_(o) {}
    /** One step: the best particle's mean log-likelihood per known
     * detection (nullopt: no known landmark detected, nothing learnt).
     * Returns true when sensor resetting should happen now. */
    bool update(std::optional<double> bestMeanLogLik);
    /** Inconsistent detections seen in this run of steps: do not map them. */
    bool suspicious() const { return bad_ > 0; }
    size_t resets() const { return resets_; }
    const TKidnapOptions& options() const { return o_; }

  private:
    TKidnapOptions o_;
    unsigned bad_ = 0;
    size_t resets_ = 0;
};

/** A robot pose drawn so that anchor `a` is consistent with its detection,
 * with heading `phi`. */
mrpt::poses::CPose2D poseFromAnchor(const TAnchor& a, double phi,
                                    rfir::models::TRandom& rng);

/** n poses for sensor resetting from the anchors of this step. */
std::vector<mrpt::poses::CPose2D> resettingPoses(const std::vector<TAnchor>& anchors,
                                                 size_t n, double currentPhi,
                                                 const TKidnapOptions& o,
                                                 rfir::models::TRandom& rng);

}  // namespace rfir::slam
