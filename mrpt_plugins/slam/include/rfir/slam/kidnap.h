/* rfir: kidnapping detection and recovery (thesis 3.4.3) by sensor
 * resetting. The evidence is the robot filter's own weighing of each step
 * (the same per-particle log-likelihoods that weigh the particles, from the
 * reads the map's robot-update policy picks): a step disagrees when even the
 * best particle explains its reads badly (mean log-likelihood per read below
 * `collapse_loglik`, and not one of them within it). One such step is normal (a drifted
 * filter meeting a revisited tag is corrected by that very weighing); a kidnapping is a
 * run of disagreeing steps, with no agreeing step between them, over several distinct
 * known landmarks, while the short-term average of the step evidence (the weighted mean
 * likelihood per read) has fallen below its long-term average (augmented MCL, as in nav2
 * / Beluga). Then a fraction of the particles is redrawn where a re-detected known
 * landmark lies in the detecting reader's area (or at the measured range and bearing),
 * and the map is not updated while the reads disagree. */
#pragma once

#include <rfir/slam/detections.h>

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose2D.h>
#include <rfir/models/random.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rfir::slam {
/** INI section [kidnap]. */
struct TKidnapOptions : public mrpt::config::CLoadableOptions {
    bool enabled = true;
    /** A read disagrees when the best particle's log-likelihood for it is
     * below this (-4: a tag about three half-sides outside the reader). */
    double collapse_loglik = -4.0;
    unsigned collapse_steps = 3;  //!< disagreeing steps in a run...
    unsigned min_tags = 3;        //!< ...over this many distinct known landmarks
    /** s: a run ends when no step disagrees for this long. */
    double max_gap = 5.0;
    /** Per read, log units: the fast average of the step evidence must be
     * this far below the slow one (100: the reads about 14 half-sides of
     * their readers away from every particle; a drifted filter meeting a
     * revisited tag measured at most 41 on the stock INIs, a kidnapping
     * 200 at 300 mm and 4000 at 60 mm). */
    double evidence_drop = 100.0;
    /** Or, without the drop: this many distinct known landmarks contradicted
     * in one run with no agreeing read (0: off, stock). A robot put down a
     * metre away among 300 mm readers drops its evidence by only 15-20 per
     * read and is caught by this (12: 17-29 s after the put-down); but so are drifted
     * runs of 60 mm readers on a noisy odometry (docs/slam.md, "Kidnapping"). */
    unsigned persist_tags = 0;
    double fast_rate = 0.5;        //!< per weighing step (0, 1]
    double slow_rate = 0.02;       //!< per weighing step (0, 1]
    double inject_fraction = 1.0;  //!< of the robot particles, per resetting
    /** Share of injected particles that keep the current heading estimate
     * (with heading_std noise), for a filter that drifted rather than was
     * carried; the rest as pair_heading_share says. */
    double keep_heading_share = 0.2;
    double heading_std = 0.1;  //!< rad
    /** Share of the others whose heading comes from two landmarks of the
     * disagreeing run (the map's vector between them against the vector the
     * odometry and the reads give); the rest get a uniform heading. A
     * uniform heading leaves a few particles within 0.1 rad of the truth,
     * and the resetting kept whichever of them the next reads favoured. */
    double pair_heading_share = 0.8;
    /** m: two landmarks give a heading only this far apart in the map. */
    double pair_min_distance = 0.5;
    /** Range-and-bearing reads enter the detector's evidence times this.
     * Their Gaussian (1 cm range noise) makes a landmark 15 cm off cost
     * about 110, as much as an RFID tag 14 reader half-sides away. Measured
     * (sim_rb_*, seeds 1-3): normal runs drop at most 1416 per read (a
     * drifted map met again), kidnappings 2700-10000; times 0.05 the
     * thresholds above mean a landmark about 0.13 m (collapse) and 0.63 m
     * (drop) off. */
    double rb_loglik_scale = 0.05;
    /** While a run of disagreeing steps is open the known tags are not
     * updated (they would be from a wrong pose); RFID tags never mapped
     * still are (else a drifting filter leaves every tag it meets then out
     * of the map). */
    bool map_new_tags_in_run = true;
    /** At a trigger, first smooth the run so far offline (graph_smoother.h,
     * no cut there, the odometry's drift estimated); if the smoothed path
     * explains the last seconds' reads it was a loop closure after drift,
     * not a kidnapping: the tags move to their smoothed places and the
     * robot particles are drawn about the smoothed pose, with no sensor
     * resetting (docs/slam.md, "Loop closure by smoothing"). RFID only. */
    bool loop_closure_smoothing = true;

    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                            const std::string& s) override;
    void saveToConfigFile(mrpt::config::CConfigFileBase& c,
                          const std::string& s) const override;
};

/** One weighing step, as the robot filter weighed it. */
struct TStepEvidence {
    double t = 0;                //!< s
    size_t reads = 0;            //!< reads that weighed the robot (> 0)
    double bestMeanLogLik = 0;   //!< best particle, per read
    double meanLogEvidence = 0;  //!< log of the weighted mean likelihood, per read
    std::vector<std::string> disagreeing;  //!< landmarks the best particle contradicts
    /** Reads the best particle explains (base term >= collapse_loglik): one
     * such read ends a run, so that a ghost read next to good ones is not
     * taken for a kidnapping (a kidnapped robot's reads all disagree). */
    size_t agreeing = 0;
};

class CKidnapMonitor {
  public:
    explicit CKidnapMonitor(const TKidnapOptions& o = {}) : o_(o) {}
    /** One weighing step. Returns true when sensor resetting should happen
     * now. */
    bool update(const TStepEvidence& e);
    /** A run of disagreeing steps is open: do not map from this pose. */
    bool suspicious() const { return bad_ > 0; }
    unsigned runSteps() const { return bad_; }  //!< disagreeing steps in the open run
    size_t resets() const { return resets_; }

  private:
    void endRun() {
        bad_ = 0;
        ids_.clear();
    }
    TKidnapOptions o_;
    unsigned bad_ = 0;                   //!< disagreeing steps in the open run
    double lastBad_ = 0;                 //!< s, the run's last disagreeing step
    std::set<std::string> ids_;          //!< distinct landmarks contradicted in it
    std::optional<double> fast_, slow_;  //!< averages of meanLogEvidence
    double slowAtRunStart_ = 0;          //!< slow_ before the open run
    size_t resets_ = 0;
};

/** A detection of a landmark whose position the map already knows. */
struct TAnchor {
    TDetection det;
    double x = 0, y = 0;  //!< landmark estimate, world frame
};

/** An anchor of an earlier step of the disagreeing run, with the odometry
 * pose of its step (any frame: only differences are used). */
struct TRunAnchor {
    TAnchor a;
    mrpt::poses::CPose2D odo;
};

/** The anchors of the open run of disagreeing steps (bounded: the run lasts
 * seconds, and the oldest anchors go first). */
class CRunAnchors {
  public:
    void add(const std::vector<TAnchor>& anchors, const mrpt::poses::CPose2D& odo);
    void clear() { v_.clear(); }
    const std::vector<TRunAnchor>& all() const { return v_; }

  private:
    std::vector<TRunAnchor> v_;
};

/** A robot pose drawn so that anchor `a` is consistent with its detection,
 * with heading `phi`. */
mrpt::poses::CPose2D poseFromAnchor(const TAnchor& a, double phi,
                                    rfir::models::TRandom& rng);

/** n poses for sensor resetting from the anchors of this step (`now`, at
 * odometry pose `odo`), with headings from pairs of them and the run's
 * earlier anchors (`run`) where `pair_heading_share` says. */
std::vector<mrpt::poses::CPose2D> resettingPoses(const std::vector<TAnchor>& now,
                                                 const mrpt::poses::CPose2D& odo,
                                                 const std::vector<TRunAnchor>& run,
                                                 size_t n, double currentPhi,
                                                 const TKidnapOptions& o,
                                                 rfir::models::TRandom& rng);

}  // namespace rfir::slam
