#include <rfir/maps/CRFIDTagParticleMap.h>
#include <rfir/models/ini_reader.h>
#include <rfir/models/resampling.h>
#include <rfir/slam/CRobotPoseParticles.h>
#include <rfir/slam/robot_resampling.h>
#include <rfir/slam/slam_engine.h>
#include <rfir/slam/tagmap_engine.h>

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>
#include <rfir/models/random.h>

#include <cmath>
#include <optional>
#include <sstream>

namespace rfir::slam {
using rfir::maps::CRFIDTagParticleMap;

struct TTagMapSettings {
    CRFIDTagParticleMap::TInsertionOptions insertion;
    CRFIDTagParticleMap::TLikelihoodOptions likelihood;
};

namespace {
/** Kidnap check: the best particle's mean log-likelihood per detection of a
 * landmark the map already has, and those detections as anchors. */
struct TConsistency {
    std::optional<double> bestMeanLogLik;
    std::vector<TAnchor> anchors;
};

/** Range-bearing: Gaussian log-likelihood of the landmark point the reading
 * implies, against the landmark estimate, with the sensor noise and the
 * landmark's own uncertainty (a collapse test must not fire on a landmark
 * that is merely poorly known). */
double rbConsistencyLogLik(const mrpt::poses::CPose2D& sensor,
                           const CRFIDTagParticleMap::TTagEntry& lm, const TDetection& d,
                           const rfir::models::RangeBearingParams& rb) {
    const auto q = rfir::models::rangeBearingToPoint(
        {sensor.x(), sensor.y(), sensor.phi()}, d.a, d.b);
    const double px = q.x, py = q.y;
    const double var = rb.sigmaRange * rb.sigmaRange +
                       (d.a * rb.sigmaBearing) * (d.a * rb.sigmaBearing) +
                       0.5 * (lm.estimate.cov(0, 0) + lm.estimate.cov(1, 1));
    const double e2 = (px - lm.estimate.mean.x) * (px - lm.estimate.mean.x) +
                      (py - lm.estimate.mean.y) * (py - lm.estimate.mean.y);
    return -0.5 * e2 / var;
}

/** Also leaves in `terms` (M rows of one column per known detection) each
 * RFID detection's term, which the weighing reuses when nothing changed. */
TConsistency checkConsistency(const CRFIDTagParticleMap& map,
                              const CRobotPoseParticles& pf,
                              const std::vector<TDetection>& dets,
                              std::vector<double>& terms) {
    TConsistency c;
    std::vector<const CRFIDTagParticleMap::TTagEntry*> known;
    for (const auto& d : dets) {
        const auto* e =
            d.kind == TDetection::Kind::RFID ? map.getTag(d.id) : map.getLandmark(d.id);
        if (!e) continue;
        known.push_back(e);
        c.anchors.push_back({d, e->estimate.mean.x, e->estimate.mean.y});
    }
    terms.clear();
    if (known.empty()) return c;
    const auto& rb = map.likelihoodOptions.rangeBearing;
    const rfir::models::DetectionLikelihood det(map.likelihoodOptions.detection);
    const size_t K = known.size();
    terms.resize(pf.m_particles.size() * K);
    double best = -1e300;
    for (size_t i = 0; i < pf.m_particles.size(); i++) {
        const auto& p = pf.m_particles[i];
        const mrpt::math::TPose2D pose = p.d.asTPose();
        const double cphi = p.d.phi_cos(), sphi = p.d.phi_sin();  // cached
        double ll = 0;
        for (size_t k = 0; k < K; k++) {
            const TDetection& d = c.anchors[k].det;
            // = map.detectionLogLikelihood(*known[k], pose, area)
            const double t =
                d.kind == TDetection::Kind::RFID
                    ? det.logLikelihood(pose, cphi, sphi, {d.a, d.b, d.halfX, d.halfY},
                                        known[k]->estimate.mean)
                    : rbConsistencyLogLik(p.d + d.sensor, *known[k], d, rb);
            terms[i * K + k] = t;
            ll += t;
        }
        best = std::max(best, ll);
    }
    c.bestMeanLogLik = best / double(K);
    return c;
}

class CTagMapEngine : public CSlamEngine, private CRobotPoseParticles::IStepModel {
  public:
    CTagMapEngine(const TSlamConfig& c, const rfir::obs::CObservationLogHeader& h)
        : cfg_(c), hdr_(h), kidnap_(c.kidnap) {
        filter_.m_options = withoutMrptResampling(c.slam.pfOptions());
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
        map_.likelihoodOptions = cfg_.tagmap->likelihood;
        map_.setRandomSeed(rng_.drawUniform64bit());
        map_.setLandmarkNames(hdr_.rbLandmarkNames);
        pf_.reset(start, cfg_.slam.robot_particles, cfg_.slam.start_std_xy,
                  cfg_.slam.start_std_phi, rng_);
        kidnap_ = CKidnapMonitor(cfg_.kidnap);
        pose_ = start;
    }
    void step(const TSlamInput& in) override;
    mrpt::poses::CPose2D pose() const override { return pose_; }
    std::vector<TLandmarkOut> landmarks() const override;
    size_t resets() const override { return kidnap_.resets(); }

  private:
    /** @name The stages executeOn runs between the motion and the weighing.
     * @{ */
    void afterMotion() override { beforeWeighing(dets_, literal_); }
    bool weighs() const override { return !obs_.empty(); }
    double logLikelihood(size_t i, const mrpt::poses::CPose2D& p) const override {
        return weigh(i, p);
    }
    /** @} */
    void beforeWeighing(const std::vector<TDetection>& dets, bool literal);
    void resolveReads(bool reuseTerms);
    /** Particle i's log-likelihood: the sum computeObservationLikelihood
     * gives over obs_ (same terms, same order), from reads resolved once. */
    double weigh(size_t i, const mrpt::poses::CPose2D& p) const {
        // CPose3D(p) has x, y, yaw == p.x(), p.y(), p.phi() exactly.
        const mrpt::math::TPose2D pose(p.x(), p.y(), p.phi());
        const double* t = termsWidth_ ? &terms_[i * termsWidth_] : nullptr;
        double ll = 0;
        const double c = p.phi_cos(), s = p.phi_sin();  // cached in the pose
        for (const auto& r : reads_) ll += map_.robotReadsLogLikelihood(r, pose, c, s, t);
        return ll;
    }
    /** The step's action: one collection kept for the run, its movement
     * recomputed in place (a new collection per step cloned the movement
     * and its PDF). */
    const mrpt::obs::CActionCollection* movement(
        const std::optional<mrpt::poses::CPose2D>& increment) {
        if (!increment) return &noMove_;
        if (move_.size() == 0) move_.insert(mrpt::obs::CActionRobotMovement2D());
        move_.getActionByClass<mrpt::obs::CActionRobotMovement2D>()->computeFromOdometry(
            *increment, motionModel_);
        return &move_;
    }
    void insert(const mrpt::poses::CPose2D& at) {
        if (map_.usesRobotSamples()) drawRobotSamples();
        for (const auto& o : obs_) map_.insertObservation(*o, mrpt::poses::CPose3D(at));
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
    rfir::models::TRandom rng_;
    const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel_ =
        cfg_.motion.toMRPT();
    mrpt::obs::CActionCollection move_, noMove_;
    std::vector<mrpt::obs::CObservation::Ptr> obs_;
    std::vector<TDetection> dets_;  //!< this step's detections
    bool literal_ = false;          //!< tags updated before the weighing
    bool mapThisStep_ = true;
    std::vector<CRFIDTagParticleMap::TRobotReads> reads_;
    std::vector<double> terms_;  //!< kidnap check's per-particle terms
    size_t termsWidth_ = 0;      //!< their columns; 0: not reusable
    std::optional<mrpt::poses::CPose2D> predictedForInsert_;
    mrpt::poses::CPose2D pose_;
};

void CTagMapEngine::beforeWeighing(const std::vector<TDetection>& dets, bool literal) {
    // With recovery off the per-particle consistency pass decides nothing
    // (the monitor ignores it): skip it, it costs a likelihood per particle.
    const TConsistency c = cfg_.kidnap.enabled ? checkConsistency(map_, pf_, dets, terms_)
                                               : (terms_.clear(), TConsistency{});
    const bool reset = kidnap_.update(c.bestMeanLogLik);
    // While the detections contradict every particle, the map is not updated
    // (it would be updated from a wrong pose).
    mapThisStep_ = !reset && !kidnap_.suspicious();
    // The mean after motion, computed only if used and before any particle
    // or weight changes.
    std::optional<mrpt::poses::CPose2D> predicted;
    const auto predictedMean = [&]() {
        if (!predicted) predicted = pf_.meanPose();
        return *predicted;
    };
    if (reset) {
        const size_t M = pf_.m_particles.size();
        const size_t n = std::max<size_t>(1, size_t(cfg_.kidnap.inject_fraction * M));
        const auto poses =
            resettingPoses(c.anchors, n, predictedMean().phi(), cfg_.kidnap, rng_);
        for (size_t k = 0; k < poses.size(); k++)
            pf_.replacePose(rng_.drawUniform32bit() % M, poses[k]);
    }
    const bool insertNow = literal && mapThisStep_;
    if (insertNow) insert(predictedMean());
    predictedForInsert_.reset();
    if (!literal && mapThisStep_ && cfg_.slam.tag_update_pose == "predicted")
        predictedForInsert_ = predictedMean();
    // The kidnap terms are the weighing's own when neither the particles nor
    // the map changed since.
    resolveReads(!reset && !insertNow);
}

void CTagMapEngine::resolveReads(bool reuseTerms) {
    reads_.assign(obs_.size(), {});
    for (size_t j = 0; j < obs_.size(); j++)
        if (map_.genericMapParams.enableObservationLikelihood)
            map_.resolveRobotReads(*obs_[j], reads_[j]);
    const size_t M = pf_.m_particles.size();
    termsWidth_ = reuseTerms && M > 0 && !terms_.empty() ? terms_.size() / M : 0;
}

void CTagMapEngine::step(const TSlamInput& in) {
    // The step, in order (issue 11's pipeline; 003 Algorithm 1, 004 Alg. 1):
    // 1. this step's observations and detections;
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
    if (cfg_.method() == TMethod::Odometry) {
        // Dead reckoning: map the tags from the odometry poses, no correction.
        if (in.odometryIncrement) pose_ = pose_ + *in.odometryIncrement;
        insert(pose_);
        return;
    }
    literal_ = map_.updateTagsBeforeWeighing();
    // 2-4. MRPT's CParticleFilter::executeOn: propagate every particle by a
    // draw of the odometry Gaussian (engine's generator), then afterMotion()
    // (kidnap check, reads resolved once; literal policy: tag update), then
    // weigh with logLikelihood(), then normalise;
    filter_.executeOn(pf_, movement(in.odometryIncrement), nullptr);
    // 5. resample when the ESS is low (MRPT's scheme, engine's generator);
    resampleIfNeeded(pf_, cfg_.slam.pfOptions(), rng_);
    reads_.clear();
    // 6. the estimate, and the tag update of the revisit policies.
    pose_ = pf_.meanPose();
    if (!literal_ && mapThisStep_)
        insert(predictedForInsert_ ? *predictedForInsert_ : pose_);
}

std::vector<TLandmarkOut> CTagMapEngine::landmarks() const {
    std::vector<TLandmarkOut> out;
    auto add = [&](const CRFIDTagParticleMap::TTagEntry* e, bool isTag) {
        const auto& est = e->estimate;
        out.push_back({isTag, e->id, est.mean.x, est.mean.y,
                       std::sqrt(std::max(0.0, est.cov(0, 0))),
                       std::sqrt(std::max(0.0, est.cov(1, 1)))});
    };
    for (const auto* e : map_.tags()) add(e, true);
    for (const auto* e : map_.landmarks()) add(e, false);
    return out;
}
}  // namespace

std::set<std::string> tagMapSections() {
    return {"tagmap", "tagmap_likelihood"};
}

std::string joinSections(const std::set<std::string>& s) {
    std::string r;
    for (const auto& x : s) r += (r.empty() ? "" : ", ") + x;
    return r;
}

std::shared_ptr<TTagMapSettings> loadTagMapOptions(
    const mrpt::config::CConfigFileBase& ini, TMethod method) {
    auto s = std::make_shared<TTagMapSettings>();
    // The estimator follows the method (per-tag filters for pf, smoothers for
    // ps) and the map's draws the run's --seed: keys saying otherwise are
    // refused rather than silently overridden.
    const std::string kind = method == TMethod::PS ? rfir::models::kFixedLagSmootherName
                                                   : rfir::models::kParticleFilterName;
    if (ini.sectionExists("tagmap") && ini.keyExists("tagmap", "seed"))
        rfir::ini::fail(ini, "tagmap", "seed",
                        "the run's --seed seeds the tag map; remove this key");
    s->insertion.estimator = kind;
    s->insertion.loadFromConfigFile(ini, "tagmap");
    if (s->insertion.estimator != kind)
        rfir::ini::fail(ini, "tagmap", "estimator",
                        "contradicts the method '" + methodName(method) +
                            "', which sets it (pf, fastslam, odometry: "
                            "particle_filter; ps: fixed_lag_smoother); remove the key "
                            "or make it agree");
    s->likelihood.loadFromConfigFile(ini, "tagmap_likelihood");
    return s;
}

std::string dumpTagMapOptions(const std::shared_ptr<TTagMapSettings>& s, uint64_t seed) {
    if (!s) return {};
    auto ins = s->insertion;
    ins.seed = seed;  // the map's draws follow the run's --seed
    std::ostringstream ins_o;
    ins.dumpToTextStream(ins_o);
    // The seed is --seed's (a seed key in [tagmap] is refused): a comment, so
    // that the dump stays a valid --config.
    std::istringstream lines(ins_o.str());
    std::ostringstream o;
    o << "[tagmap]\n";
    for (std::string l; std::getline(lines, l);)
        o << (l.rfind("seed ", 0) == 0 ? "# " + l + " (--seed)" : l) << "\n";
    o << "\n[tagmap_likelihood]\n";
    s->likelihood.dumpToTextStream(o);
    return o.str();
}

std::unique_ptr<CSlamEngine> makeTagMapEngine(
    const TSlamConfig& cfg, const rfir::obs::CObservationLogHeader& hdr) {
    return std::make_unique<CTagMapEngine>(cfg, hdr);
}

}  // namespace rfir::slam
