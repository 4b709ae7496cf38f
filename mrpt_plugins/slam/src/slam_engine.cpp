#include <rfir/models/robot_resampling.h>
#include <rfir/slam/CFastSLAMParticles.h>
#include <rfir/slam/slam_engine.h>
#include <rfir/slam/tagmap_engine.h>

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CActionCollection.h>

#include <chrono>
#include <cmath>

namespace rfir::slam {
namespace {
/** The action collection the filters draw motion from: the odometry
 * increment with the INI's noise model (not the rawlog writer's). */
mrpt::obs::CActionCollection motionAction(const TSlamInput& in, const TMotionOptions& m,
                                          CSlipAwareMotion& slip) {
    mrpt::obs::CActionCollection acts;
    if (in.odometryIncrement)
        acts.insert(
            slip.movement(*in.odometryIncrement, in.odometryDt, in.odometryParts, m));
    return acts;
}

class CFastSLAMEngine : public CSlamEngine {
  public:
    CFastSLAMEngine(const TSlamConfig& c, const rfir::obs::CObservationLogHeader& h)
        : cfg_(c), hdr_(h), pf_(c.fastslam) {
        filter_.m_options = rfir::models::withoutMrptResampling(c.slam.pfOptions());
    }
    void reset(const mrpt::poses::CPose2D& start) override {
        rng_.randomize(cfg_.seed);  // the run's one generator (--seed)
        slip_.reset();
        pf_.setHeadingDrift(cfg_.motion.headingDrift());
        pf_.reset(start, cfg_.slam.robot_particles, cfg_.slam.start_std_xy,
                  cfg_.slam.start_std_phi, rng_);
    }
    void step(const TSlamInput& in) override {
        std::vector<TDetection> dets;
        if (in.rfid) appendDetections(*in.rfid, dets);
        if (in.rb) appendDetections(*in.rb, hdr_, dets);
        pf_.setDetections(&dets);
        const auto acts = motionAction(in, cfg_.motion, slip_);
        filter_.executeOn(pf_, &acts, nullptr);  // motion, weighing, normalising
        rfir::models::resampleIfNeeded(pf_, cfg_.slam.pfOptions(), rng_);
        pf_.setDetections(nullptr);
        pose_ = pf_.meanPose();
    }
    mrpt::poses::CPose2D pose() const override { return pose_; }
    std::vector<mrpt::math::TPose2D> particlePoses() const override {
        std::vector<mrpt::math::TPose2D> out;
        for (const auto& p : pf_.m_particles) out.push_back(p.d.pose.asTPose());
        return out;
    }
    std::vector<TLandmarkOut> landmarks() const override {
        std::vector<TLandmarkOut> out;
        for (const auto& e : pf_.landmarks())
            out.push_back({e.isTag, e.id, e.mean.x(), e.mean.y(), std::sqrt(e.cov(0, 0)),
                           std::sqrt(e.cov(1, 1))});
        return out;
    }

  private:
    TSlamConfig cfg_;
    rfir::obs::CObservationLogHeader hdr_;
    CFastSLAMParticles pf_;
    mrpt::bayes::CParticleFilter filter_;
    rfir::models::TRandom rng_;
    CSlipAwareMotion slip_;
    mrpt::poses::CPose2D pose_;
};

}  // namespace

std::unique_ptr<CSlamEngine> makeEngine(const TSlamConfig& cfg,
                                        const rfir::obs::CObservationLogHeader& hdr) {
    switch (cfg.method()) {
        case TMethod::FastSLAM:
            return std::make_unique<CFastSLAMEngine>(cfg, hdr);
        default:
            return makeTagMapEngine(cfg, hdr);
    }
}

TSlamRun runEngine(CSlamEngine& engine, const mrpt::poses::CPose2D& start,
                   const std::vector<TSlamInput>& inputs,
                   const std::function<void(size_t)>& progress) {
    using clock = std::chrono::steady_clock;
    TSlamRun run;
    engine.reset(start);
    for (size_t i = 0; i < inputs.size(); i++) {
        const auto t0 = clock::now();
        engine.step(inputs[i]);
        const double dt = std::chrono::duration<double>(clock::now() - t0).count();
        run.totalTime += dt;
        run.maxStepTime = std::max(run.maxStepTime, dt);
        run.path.emplace_back(inputs[i].t, engine.pose());
        if (progress) progress(i);
    }
    run.meanStepTime = inputs.empty() ? 0 : run.totalTime / double(inputs.size());
    run.map = engine.landmarks();
    run.resetTimes = engine.resetTimes();
    run.resets = run.resetTimes.size();
    run.loopClosureTimes = engine.loopClosureTimes();
    return run;
}

}  // namespace rfir::slam
