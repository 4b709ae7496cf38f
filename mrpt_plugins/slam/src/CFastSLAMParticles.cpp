#include <rfir/slam/CFastSLAMParticles.h>
#include <rfir/slam/motion_model.h>
#include <rfir/slam/slam_options.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CActionCollection.h>

#include <rfir/models/ini_reader.h>

namespace rfir::slam {
void TFastSLAMOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                          const std::string& s) {
    using R = rfir::ini::TRange;
    const rfir::ini::CIniSection sec(
        c, s, {"rfid_std_factor", "rb_std_range", "rb_std_bearing"});
    meas.rfidStdFactor =
        sec.getDouble("rfid_std_factor", meas.rfidStdFactor, R::aboveZero(100));
    meas.rbStdRange = sec.getDouble("rb_std_range", meas.rbStdRange, R::aboveZero(100));
    meas.rbStdBearing =
        sec.getDouble("rb_std_bearing", meas.rbStdBearing, R::aboveZero(M_PI));
}

void TFastSLAMOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                        const std::string& s) const {
    c.write(s, "rfid_std_factor", meas.rfidStdFactor, -1, -1,
            "RFID: tag std about the reader centre / half side");
    c.write(s, "rb_std_range", meas.rbStdRange, -1, -1,
            "range std [m] when the observation gives none");
    c.write(s, "rb_std_bearing", meas.rbStdBearing, -1, -1,
            "bearing std [rad] when the observation gives none");
}

void CFastSLAMParticles::reset(const mrpt::poses::CPose2D& start, size_t M, double stdXY,
                               double stdPhi, rfir::models::TRandom& rng) {
    rng_ = &rng;
    moves_ = 0;
    m_particles.assign(M, {});
    for (auto& p : m_particles) {
        p.log_w = 0;
        p.d.pose = start + mrpt::poses::CPose2D(0, 0, 0);
        if (stdXY > 0 || stdPhi > 0)
            p.d.pose = mrpt::poses::CPose2D(start.x() + rng.drawGaussian1D(0, stdXY),
                                            start.y() + rng.drawGaussian1D(0, stdXY),
                                            start.phi() + rng.drawGaussian1D(0, stdPhi));
    }
    if (drift_.std > 0)
        drawDriftPrior(
            m_particles, [](auto& p, size_t) -> double& { return p.d.drift; }, drift_.std,
            rng);
    index_.clear();
    names_.clear();
    isTag_.clear();
}

size_t CFastSLAMParticles::indexOf(const TDetection& d) {
    // Tags and range-bearing landmarks are separate name spaces.
    const std::string key = (d.kind == TDetection::Kind::RFID ? "t:" : "l:") + d.id;
    auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    index_[key] = names_.size();
    names_.push_back(d.id);
    isTag_.push_back(d.kind == TDetection::Kind::RFID);
    return names_.size() - 1;
}

double CFastSLAMParticles::updateParticle(TFastSLAMParticle& p,
                                          const std::vector<size_t>& idx) {
    double logLik = 0;
    for (size_t k = 0; k < idx.size(); k++) {
        const TDetection& d = (*detections_)[k];
        const TLandmarkEKF* old = p.landmarks.get(idx[k]);
        if (!old) {
            // A new landmark: every particle sees it now, so its importance
            // factor is a common constant and is left out.
            p.landmarks.set(idx[k], std::make_shared<const TLandmarkEKF>(
                                        model_.initialize(d, p.pose)));
            continue;
        }
        auto lm = std::make_shared<TLandmarkEKF>(*old);  // the one copy of an update
        logLik += ekfUpdate(*lm, model_.linearize(d, p.pose, lm->mean));
        p.landmarks.set(idx[k], std::move(lm));
    }
    return logLik;
}

void CFastSLAMParticles::prediction_and_update_pfStandardProposal(
    const mrpt::obs::CActionCollection* action, const mrpt::obs::CSensoryFrame*,
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions&) {
    const auto poseOf = [](auto& p) -> CParticlePose2D& { return p.d.pose; };
    if (const auto g = motionOf(action)) {
        if (drift_.on())
            drawMotion(
                *g, m_particles, poseOf,
                [](auto& p, size_t) -> double& { return p.d.drift; }, drift_.walk, *rng_,
                moves_);
        else
            drawMotion(*g, m_particles, poseOf, *rng_, moves_);
    }
    if (!detections_ || detections_->empty()) return;
    std::vector<size_t> idx;
    for (const auto& d : *detections_) idx.push_back(indexOf(d));
    for (auto& p : m_particles) p.log_w += updateParticle(p.d, idx);
}

mrpt::poses::CPose2D CFastSLAMParticles::meanPose() const {
    std::vector<double> lw(m_particles.size());
    for (size_t i = 0; i < lw.size(); i++) lw[i] = m_particles[i].log_w;
    return weightedMeanPose(
        m_particles.size(), lw,
        [&](size_t i) -> const CParticlePose2D& { return m_particles[i].d.pose; });
}

std::vector<CFastSLAMParticles::TLandmarkEstimate> CFastSLAMParticles::landmarks() const {
    std::vector<double> w(m_particles.size());
    double mx = -1e300, sw = 0;
    for (const auto& p : m_particles) mx = std::max(mx, p.log_w);
    for (size_t i = 0; i < w.size(); i++)
        sw += (w[i] = std::exp(m_particles[i].log_w - mx));
    std::vector<TLandmarkEstimate> out;
    for (size_t j = 0; j < names_.size(); j++) {
        TLandmarkEstimate e{names_[j], isTag_[j], Eigen::Vector2d::Zero(),
                            Eigen::Matrix2d::Zero()};
        for (size_t i = 0; i < w.size(); i++)
            if (auto* lm = m_particles[i].d.landmarks.get(j))
                e.mean += w[i] / sw * lm->mean;
        for (size_t i = 0; i < w.size(); i++)
            if (auto* lm = m_particles[i].d.landmarks.get(j)) {
                const Eigen::Vector2d dm = lm->mean - e.mean;
                e.cov += w[i] / sw * (lm->cov + dm * dm.transpose());
            }
        out.push_back(e);
    }
    return out;
}

}  // namespace rfir::slam
