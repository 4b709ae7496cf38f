#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/models/resampling.h>
#include <rfir/models/robot_resampling.h>
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/slam/CRobotPoseParticles.h>
#include <rfir/slam/slam_engine.h>
#include <rfir/slam/tagmap_engine.h>

#include "loop_closure.h"
#include "tagmap_settings.h"

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>
#include <rfir/models/random.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace rfir::slam {
using rfir::maps::CRFIDTagParticleMap;

namespace {
/** The map's entry for a detection's tag or landmark, if mapped. */
const CRFIDTagParticleMap::TTagEntry* mapEntry(const CRFIDTagParticleMap& map,
                                               const TDetection& d) {
    return d.kind == TDetection::Kind::RFID ? map.getTag(d.id) : map.getLandmark(d.id);
}

/** This step's detections of landmarks the map already has: where sensor
 * resetting may put the robot. */
std::vector<TAnchor> knownAnchors(const CRFIDTagParticleMap& map,
                                  const std::vector<TDetection>& dets) {
    std::vector<TAnchor> out;
    for (const auto& d : dets) {
        if (const auto* e = mapEntry(map, d))
            out.push_back({d, e->estimate.mean.x, e->estimate.mean.y});
    }
    return out;
}

class CTagMapEngine : public CSlamEngine, private CRobotPoseParticles::IStepModel {
  public:
    CTagMapEngine(const TSlamConfig& c, const rfir::obs::CObservationLogHeader& h)
        : cfg_(c), hdr_(h), kidnap_(c.kidnap) {
        filter_.m_options = rfir::models::withoutMrptResampling(c.slam.pfOptions());
        pf_.setStepModel(this);
    }
    CTagMapEngine(const CTagMapEngine&) = delete;
    CTagMapEngine& operator=(const CTagMapEngine&) = delete;
    void reset(const mrpt::poses::CPose2D& start) override {
        // The run's one generator (--seed): motion, resampling, kidnap
        // resetting; the map's per-step streams are seeded from it.
        rng_.randomize(cfg_.seed);
        map_.clear();
        map_.insertionOptions = cfg_.tagmap->insertion;
        // Dead reckoning maps from the odometry poses with no correction:
        // placing a contradicted tag again, or holding it against a read, is
        // a correction (with the first, after the kidnapping of the
        // experiments' `kidnap` row its tags moved 0.1 -> 2.2 m off).
        if (cfg_.method() == TMethod::Odometry) {
            map_.insertionOptions.reseatContradicted = false;
            map_.insertionOptions.holdOutvoted = false;
        }
        map_.likelihoodOptions = cfg_.tagmap->likelihood;
        map_.setRandomSeed(rng_.drawUniform64bit());
        map_.setLandmarkNames(hdr_.rbLandmarkNames);
        pf_.setHeadingDrift(cfg_.motion.headingDrift());
        pf_.reset(start, cfg_.slam.robot_particles, cfg_.slam.start_std_xy,
                  cfg_.slam.start_std_phi, rng_);
        kidnap_ = CKidnapMonitor(cfg_.kidnap);
        resetTimes_.clear();
        lastSeen_.clear();
        slip_.reset();
        corr_ = CMapCorrection(cfg_.slam.map_correction_min_std,
                               cfg_.slam.map_correction_max_tags);
        pose_ = start;
        odo_ = start;
        runAnchors_.clear();
        hist_.reset(start);
        closureTimes_.clear();
    }
    void step(const TSlamInput& in) override;
    mrpt::poses::CPose2D pose() const override { return pose_; }
    std::vector<TLandmarkOut> landmarks() const override;
    std::vector<mrpt::math::TPose2D> particlePoses() const override {
        std::vector<mrpt::math::TPose2D> out;
        for (const auto& p : pf_.m_particles) out.push_back(p.d.asTPose());
        return out;
    }
    const std::vector<double>& resetTimes() const override { return resetTimes_; }
    const std::vector<double>& loopClosureTimes() const override { return closureTimes_; }

  private:
    /** @name The stages executeOn runs between the motion and the weighing.
     * @{ */
    void afterMotion() override;
    bool weighs() const override { return !obs_.empty(); }
    double logLikelihood(size_t i, const CParticlePose2D& p) const override {
        return weigh(i, p);
    }
    /** @} */
    void resolveReads();
    /** After the weighing: the kidnap monitor's step, sensor resetting. */
    void checkKidnap();
    /** [kidnap] loop_closure_smoothing at a trigger: true if the smoothed run
     * explained it (tags and robot moved there), false to reset. */
    bool closeLoop();
    TStepEvidence stepEvidence() const;
    /** A base term of `r`'s reads in the kidnap check's units, those of the
     * RFID step model: range-and-bearing terms rescaled ([kidnap]
     * rb_loglik_scale), the one place both the step's sum and each read's
     * term go through. */
    double kidnapUnits(const CRFIDTagParticleMap::TRobotReads& r, double base) const {
        return r.rangeBearing ? cfg_.kidnap.rb_loglik_scale * base : base;
    }
    /** Particle i's log-likelihood: the sum computeObservationLikelihood
     * gives over obs_ (same terms, same order), from reads resolved once. */
    double weigh(size_t i, const CParticlePose2D& p) const {
        // CPose3D(p) has x, y, yaw == p.x(), p.y(), p.phi() exactly.
        const mrpt::math::TPose2D pose(p.x(), p.y(), p.phi());
        double ll = 0, base = 0;
        const double c = p.phi_cos(), s = p.phi_sin();  // cached in the pose
        for (const auto& r : reads_) {
            double b = 0;
            ll += map_.robotReadsLogLikelihood(r, pose, c, s, &b);
            base += kidnapUnits(r, b);
        }
        if (i < baseLogLik_.size()) baseLogLik_[i] = base;
        return ll;
    }
    void insert(const mrpt::poses::CPose2D& at) {
        insert(at, [&] {
            for (const auto& o : obs_)
                map_.insertObservation(*o, mrpt::poses::CPose3D(at));
        });
    }
    /** Runs `insertInto` (the map insertion of this step's observations, or
     * a part of them), with the robot samples and the map correction's
     * bookkeeping around it. */
    template <class F>
    void insert(const mrpt::poses::CPose2D& at, F&& insertInto) {
        if (map_.usesRobotSamples()) drawRobotSamples();
        std::vector<const TDetection*> fresh;  // first reads: join the correction
        if (cfg_.slam.map_correction)
            for (const auto& d : dets_)
                if (!mapEntry(map_, d)) fresh.push_back(&d);
        insertInto();
        if (fresh.empty()) return;
        // The robot's moments after this step's weighing, or now if it did not weigh.
        const auto post = pf_.posteriorMoments();
        const auto m = post ? *post : pf_.poseMoments();
        for (const auto* d : fresh)
            if (const auto* e = mapEntry(map_, *d))
                corr_.mapped(d->id, d->kind != TDetection::Kind::RFID, e->estimate.mean.x,
                             e->estimate.mean.y, m);
    }
    /** While the kidnap check's run is open ([kidnap] map_new_tags_in_run):
     * only the RFID tags never mapped. */
    void insertNewOnly(const mrpt::poses::CPose2D& at) {
        if (obs_.empty()) return;
        auto* rf = dynamic_cast<const rfir::obs::CObservationRFIDReaders*>(obs_[0].get());
        if (!rf || !map_.readsNewTags(*rf)) return;
        insert(at, [&] { map_.insertNewTags(*rf, at); });
    }
    /** End of a weighing step with map_correction: the tags still correlated
     * with the robot follow its correction (tag_correlation.h). */
    void correctMap(bool reset) {
        // The moments exist only for a step that known tags weighed
        // (afterMotion turns their tracking on).
        const auto before = pf_.priorMoments(), after = pf_.posteriorMoments();
        if (before && after) {
            std::vector<std::string> ids;
            for (const auto& r : reads_)
                for (const auto& rd : r.reads)
                    if (rd.id) ids.push_back(*rd.id);
            corr_.weighed(*before, *after, ids);
        }
        corr_.settle(reset, mapThisStep_,
                     [&](const std::string& id, bool lm, double dx, double dy) {
                         map_.translateEntry(id, lm, dx, dy);
                     });
    }
    /** tag_robot_pose = samples*: the map places readers by robot poses drawn
     * from the current (weighted) robot set; O(M) per step, not per tag. */
    void drawRobotSamples() {
        const auto& ps = pf_.m_particles;
        std::vector<double> lw(ps.size());
        for (size_t i = 0; i < ps.size(); i++) lw[i] = ps[i].log_w;
        const auto idx = rfir::models::resampleIndices(
            lw, ps.size(), rfir::models::ResamplingScheme::Systematic, rng_);
        std::vector<mrpt::math::TPose2D> v(idx.size());
        for (size_t k = 0; k < idx.size(); k++) v[k] = ps[idx[k]].d.asTPose();
        map_.setRobotSamples(std::move(v));
    }

    TSlamConfig cfg_;
    rfir::obs::CObservationLogHeader hdr_;
    CRFIDTagParticleMap map_;
    CRobotPoseParticles pf_;
    mrpt::bayes::CParticleFilter filter_;
    CKidnapMonitor kidnap_;
    CSlipAwareMotion slip_;  //!< the motion model's slip memory
    CMapCorrection corr_;
    rfir::models::TRandom rng_;
    std::vector<mrpt::obs::CObservation::Ptr> obs_;
    std::vector<TDetection> dets_;  //!< this step's detections
    /** read_confirm_window: each tag's last read time (s). */
    std::unordered_map<std::string, double> lastSeen_;
    void confirmReads(double window);
    bool literal_ = false;  //!< tags updated before the weighing
    bool mapThisStep_ = true;
    std::vector<CRFIDTagParticleMap::TRobotReads> reads_;
    /** This step's weighing terms without the outlier mixture, per particle
     * (what the kidnap check reads). */
    mutable std::vector<double> baseLogLik_;
    std::optional<mrpt::poses::CPose2D> predictedForInsert_;
    mrpt::poses::CPose2D pose_;
    /** The odometry's own pose: dead reckoning's estimate, and the run
     * anchors' frame. */
    mrpt::poses::CPose2D odo_;
    CRunAnchors runAnchors_;
    double t_ = 0;                    //!< this step's time
    std::vector<double> resetTimes_;  //!< when sensor resetting fired
    /** loop_closure_smoothing: the run so far, and when a trigger was a
     * loop closure. */
    CRunHistory hist_;
    std::vector<double> closureTimes_;
    bool relocatedNow_ = false;  //!< this step reset or closed a loop
};

void CTagMapEngine::afterMotion() {
    // While a run of reads contradicts every particle the map is not updated
    // (it would be updated from a wrong pose).
    mapThisStep_ = !kidnap_.suspicious();
    predictedForInsert_.reset();
    if (literal_ && mapThisStep_)
        insert(pf_.meanPose());
    else if (literal_ && cfg_.kidnap.map_new_tags_in_run)
        insertNewOnly(pf_.meanPose());
    else if (!literal_ &&
             cfg_.slam.tag_update_pose == TSlamOptions::TTagUpdatePose::Predicted)
        predictedForInsert_ = pf_.meanPose();
    resolveReads();
    baseLogLik_.assign(pf_.m_particles.size(), 0.0);
    // The map correction needs the weighing's moments only when known tags
    // weigh the robot (the particle loops then accumulate them).
    bool weighing = false;
    for (const auto& r : reads_) weighing = weighing || !r.reads.empty();
    pf_.trackMoments(cfg_.slam.map_correction && weighing);
}

void CTagMapEngine::resolveReads() {
    reads_.assign(obs_.size(), {});
    for (size_t j = 0; j < obs_.size(); j++)
        if (map_.genericMapParams.enableObservationLikelihood)
            map_.resolveRobotReads(*obs_[j], reads_[j]);
    // A visit's first read is by definition unconfirmed: under the policy
    // that weighs only that read the confirmation would leave it nothing.
    if (cfg_.slam.read_confirm_window > 0 && !map_.weighsOnlyFirstReads())
        confirmReads(cfg_.slam.read_confirm_window);
}

void CTagMapEngine::confirmReads(double window) {
    // A ghost read is one event; a real tag stays in its reader over a few
    // polls. Unconfirmed reads leave the weighing (and the kidnap check,
    // which reads the same reads_); every read of this step confirms the next.
    const auto unconfirmed = [&](const CRFIDTagParticleMap::TRobotReads::TRead& rd) {
        if (!rd.id) return false;
        const auto it = lastSeen_.find(*rd.id);
        return it == lastSeen_.end() || !(t_ - it->second <= window);
    };
    for (auto& r : reads_) {
        if (r.rangeBearing) continue;
        r.reads.erase(std::remove_if(r.reads.begin(), r.reads.end(), unconfirmed),
                      r.reads.end());
    }
    for (const auto& d : dets_)
        if (d.kind == TDetection::Kind::RFID) lastSeen_[d.id] = t_;
}

TStepEvidence CTagMapEngine::stepEvidence() const {
    // Everything from the weighing's own terms: per-particle sums, and, for
    // the best particle, the same callable on each read alone.
    TStepEvidence e;
    e.t = t_;
    for (const auto& r : reads_) e.reads += r.reads.size();
    // The base model's terms (the mixture off): the mixture caps a read's
    // cost at log(eps) + floor, below any drop the detector could see.
    const auto& ll = baseLogLik_;
    if (e.reads == 0 || pf_.stepLogLik().empty() || ll.size() != pf_.m_particles.size())
        return e;
    const size_t best = size_t(std::max_element(ll.begin(), ll.end()) - ll.begin());
    const double K = double(e.reads);
    e.bestMeanLogLik = ll[best] / K;
    e.meanLogEvidence = pf_.stepLogEvidence(ll) / K;
    const auto& p = pf_.m_particles[best].d;
    const mrpt::math::TPose2D pose(p.x(), p.y(), p.phi());
    for (const auto& r : reads_) {
        CRFIDTagParticleMap::TRobotReads one = r;
        for (const auto& rd : r.reads) {
            one.reads.assign(1, rd);
            double b = 0;
            map_.robotReadsLogLikelihood(one, pose, p.phi_cos(), p.phi_sin(), &b);
            b = kidnapUnits(r, b);
            if (b >= cfg_.kidnap.collapse_loglik)
                e.agreeing++;
            else if (rd.id)
                e.disagreeing.push_back(*rd.id);
        }
    }
    return e;
}

void CTagMapEngine::checkKidnap() {
    if (!cfg_.kidnap.enabled || pf_.stepLogLik().empty()) return;
    const TStepEvidence e = stepEvidence();
    if (e.reads == 0) return;
    const bool reset = kidnap_.update(e);
    if (kidnap_.suspicious() || reset) mapThisStep_ = false;
    if (!reset) {
        // The open run's anchors give the resetting its headings (looked up
        // only while a run is open: most steps have none).
        if (kidnap_.runSteps() <= 1) runAnchors_.clear();  // none, or a new run
        if (kidnap_.suspicious()) runAnchors_.add(knownAnchors(map_, dets_), odo_);
        return;
    }
    relocatedNow_ = true;
    if (cfg_.kidnap.loop_closure_smoothing && !hist_.rangeBearing() && closeLoop())
        return;
    resetTimes_.push_back(t_);
    const size_t M = pf_.m_particles.size();
    const size_t n = std::max<size_t>(1, size_t(cfg_.kidnap.inject_fraction * M));
    const auto poses = resettingPoses(knownAnchors(map_, dets_), odo_, runAnchors_.all(),
                                      n, pf_.meanPose().phi(), cfg_.kidnap, rng_);
    runAnchors_.clear();
    // Mixture MCL (Thrun et al. 2001): each drawn pose is weighed by this
    // step's reads with the weighing's own callable, on the best prior
    // weight, so that resampling keeps the poses that explain every read,
    // not only the one they were drawn from.
    const double prior = pf_.bestPriorLogW();
    for (const auto& p : poses) {
        const double ll = weigh(SIZE_MAX, CParticlePose2D(p));
        pf_.replacePose(rng_.drawUniform32bit() % M, p, prior + ll, ll);
    }
}

bool CTagMapEngine::closeLoop() {
    // This step's pose before any reset joins the smoothed run.
    const auto run = hist_.closeLoop(t_, pf_.meanPose(), landmarks(), resetTimes_, cfg_);
    if (!run) return false;
    for (const auto& l : run->map)
        if (const auto* e = map_.getTag(l.id))
            map_.translateEntry(l.id, false, l.x - e->estimate.mean.x,
                                l.y - e->estimate.mean.y);
    pf_.reset(run->path.back().second, cfg_.slam.robot_particles, cfg_.slam.start_std_xy,
              cfg_.slam.start_std_phi, rng_);
    closureTimes_.push_back(t_);
    runAnchors_.clear();
    return true;
}

void CTagMapEngine::step(const TSlamInput& in) {
    // The step, in order (issue 11's pipeline; 003 Algorithm 1, 004 Alg. 1):
    // 1. this step's observations and detections;
    t_ = in.t;
    obs_.clear();
    dets_.clear();
    if (in.rfid) {
        obs_.push_back(in.rfid);
        appendDetections(*in.rfid, dets_);
    }
    if (in.rb) {
        obs_.push_back(in.rb);
        appendDetections(*in.rb, hdr_, dets_);
    }
    if (in.odometryIncrement) odo_ = odo_ + *in.odometryIncrement;
    if (cfg_.method() == TMethod::Odometry) {
        // Dead reckoning: map the tags from the odometry poses, no correction.
        pose_ = odo_;
        insert(pose_);
        return;
    }
    relocatedNow_ = false;
    if (cfg_.kidnap.loop_closure_smoothing) hist_.addInput(in);
    literal_ = map_.updateTagsBeforeWeighing();
    // 2-4. MRPT's CParticleFilter::executeOn: propagate every particle by a
    // draw of the odometry Gaussian (engine's generator), then afterMotion()
    // (reads resolved once; literal policy: tag update), then
    // weigh with logLikelihood(), then normalise;
    mrpt::obs::CActionCollection acts;
    if (in.odometryIncrement)
        acts.insert(slip_.movement(*in.odometryIncrement, in.odometryDt, in.odometryParts,
                                   cfg_.motion));
    filter_.executeOn(pf_, &acts, nullptr);
    // 5. the kidnap check on this weighing (sensor resetting if lost);
    checkKidnap();
    // 6. resample when the ESS is low (MRPT's scheme, engine's generator);
    rfir::models::resampleIfNeeded(pf_, cfg_.slam.pfOptions(), rng_);
    // 7. PF/PS with map_correction: the tags mapped from an uncertain robot
    // follow the weighing's correction of it;
    if (cfg_.slam.map_correction) correctMap(relocatedNow_);
    reads_.clear();
    // 8. the estimate, and the tag update of the revisit policies.
    pose_ = pf_.meanPose();
    if (!literal_ && mapThisStep_)
        insert(predictedForInsert_ ? *predictedForInsert_ : pose_);
    else if (!literal_ && cfg_.kidnap.map_new_tags_in_run)
        insertNewOnly(predictedForInsert_ ? *predictedForInsert_ : pose_);
    if (cfg_.kidnap.loop_closure_smoothing) hist_.addPose(t_, pose_);
}

std::vector<TLandmarkOut> CTagMapEngine::landmarks() const {
    std::vector<TLandmarkOut> out;
    auto add = [&](const CRFIDTagParticleMap::TTagEntry* e, bool isTag) {
        const auto& est = e->estimate;
        TLandmarkOut l{isTag,
                       e->id,
                       est.mean.x,
                       est.mean.y,
                       std::sqrt(std::max(0.0, est.cov(0, 0))),
                       std::sqrt(std::max(0.0, est.cov(1, 1)))};
        l.reads = e->detections;
        l.contradicted = e->contradicted;
        l.reseats = e->reseats;
        out.push_back(l);
    };
    for (const auto* e : map_.tags()) add(e, true);
    for (const auto* e : map_.landmarks()) add(e, false);
    return out;
}
}  // namespace

std::unique_ptr<CSlamEngine> makeTagMapEngine(
    const TSlamConfig& cfg, const rfir::obs::CObservationLogHeader& hdr) {
    return std::make_unique<CTagMapEngine>(cfg, hdr);
}

}  // namespace rfir::slam
