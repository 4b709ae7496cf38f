/* rfir: Monte Carlo localization on the IR emitter map (thesis Algorithm 3)
 * on MRPT's particle filter: mrpt::bayes::CParticleFilter driving a
 * CIRParticles (a mrpt::slam::CMonteCarloLocalization2D) whose map is a
 * CIREmitterMap; one generator, the localizer's, for every draw.
 * Unknown start (particles over the map's area); the estimate (eq. 5.4) is
 * reported from the first unique-ID reading on. Sensor resetting draws some
 * particles from a unique-ID reading when too few particles agree with it. */
#pragma once

#include <rfir/ir/ir_particles.h>
#include <rfir/ir/track_monitor.h>
#include <rfir/maps/CIREmitterMap.h>

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>
#include <rfir/models/random.h>

#include <deque>
#include <memory>
#include <optional>

namespace rfir::ir {
/** Odometry motion noise (seed eq. 3.6: a Gaussian step in the robot frame),
 * per step with increment (dx, dy, dphi), d = |(dx, dy)|:
 *   var_xy  = k_xy^2 d + (scale_sigma d)^2 + min_std_xy^2
 *   var_phi = k_phi_rot^2 |dphi| + k_phi_xy^2 d + (rot_scale_sigma dphi)^2
 *             + (heading_drift d)^2 + min_std_phi^2 */
struct TMotionNoise {
    double kXY = 0.02, kPhiRot = 0.04, kPhiXY = 0.01;
    double scaleSigma = 0.02, rotScaleSigma = 0.02, headingDrift = 0.01;
    double minStdXY = 0.0005, minStdPhi = 0.001;
    /** Covariance of the increment, robot frame (x, y, phi). */
    mrpt::math::CMatrixDouble33 covariance(const mrpt::poses::CPose2D& incr) const;
};

struct TLocalizerParams : public mrpt::config::CLoadableOptions {
    // [localization]
    /** num_particles (M), the thesis' 1000: in docs/results_ir.md every start
     * succeeds from 500; with the first unique ID late (at a corner) the
     * worst settled error is 63 mm at 500, 66 mm at 1000, 425 mm at 200. */
    size_t numParticles = 1000;
    /** init_area "x0 y0 x1 y1": initial particle area; empty: the emitters'
     * bounding box grown by init_margin. */
    double initX0 = 0, initY0 = 0, initX1 = 0, initY1 = 0;
    bool initAreaSet = false;
    double initMargin = 0.3;  //!< init_margin (m)
    /** start_from_reading: at the first unique ID, draw every particle from
     * the reading (false: weigh the uniform prior with it, as the thesis). */
    bool startFromReading = true;
    /** start_history (m): with start_from_reading, the particles drawn at the
     * first unique ID are weighed by the repeated-ID readings of the last
     * start_history metres of odometry before it, each particle walked back
     * along the odometry with the motion noise drawn per interval (one unique
     * emitter leaves a ring of poses; the path's earlier readings pick the
     * headings on it). 0: off (the thesis). */
    double startHistory = 2.0;
    /** start_pose: `unknown` (global localization, the thesis) or `log`: the
     * robot starts where the log's header says (`start`), e.g. at its dock;
     * the particles are drawn about it with start_std_xy (m) and
     * start_std_phi (rad) and the estimate is reported from the first instant
     * (startAt). */
    bool startFromLog = false;
    double startStdXY = 0.05, startStdPhi = 0.05;
    bool sensorResetting = true;       //!< sensor_resetting
    double resetMinFraction = 0.001;   //!< reset_min_fraction: weight in view below it
    double resetRatio = 0.5;           //!< reset_ratio: share of particles redrawn
    double resetDistanceSigma = 0.02;  //!< reset_distance_sigma (m)
    /** reset_view_margin (m): "in view" for resetting means within the visible
     * radius plus this, so a good track at the edge of view is not reset. */
    double resetViewMargin = 0.1;
    /** repeated_before_unique: use repeated-ID readings before the first
     * unique one (association = particle only; the thesis waits). */
    bool repeatedBeforeUnique = false;
    /** association_max_std (m): association = estimate attributes repeated
     * IDs against the estimate only while the particles' position spread
     * (largest standard deviation) is below this; a spread-out (e.g. ring
     * shaped, after a single unique emitter) posterior has a meaningless mean.
     * 0 disables the gate (the thesis). */
    double associationMaxStd = 0;
    double essThreshold = 0.5;  //!< ess_threshold: resample when ESS/M below it
    mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm resampling =
        mrpt::bayes::CParticleFilter::prSystematic;  //!< resampling
    bool decodeRaw = true;  //!< decode_raw: FFT-decode raw windows without codes
    /** Gate, emitter health, lost-track detection ([localization] keys). */
    TRobustParams robust;
    // [motion]
    TMotionNoise motion;

    /** Reads sections `<prefix>localization` and `<prefix>motion`, rejecting
     * unknown keys. */
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                            const std::string& prefix) override;
    void dumpToTextStream(std::ostream& out) const override;
};

/** What one step did. */
struct TLocalizerStep {
    bool started = false;       //!< estimation running (a unique ID was seen)
    bool justStarted = false;   //!< this step saw the first unique ID
    bool uniqueRead = false;    //!< this step used a unique-ID reading
    size_t readings = 0;        //!< readings with a code
    size_t used = 0;            //!< readings that weighed the particles
    size_t unknownIds = 0;      //!< codes forming an ID absent from the map
    size_t decoded = 0;         //!< raw windows decoded here
    size_t resetParticles = 0;  //!< particles redrawn by sensor resetting
    /** At the first unique ID: the earlier readings that weighed the drawn
     * particles (start_history). */
    size_t historyReadings = 0;
    size_t gated = 0;    //!< readings inconsistent with the motion prior
    bool lost = false;   //!< the track was declared lost (and redrawn)
    std::string lostId;  //!< the unique ID it was redrawn from
    /** The particles became confident again (spread under gate_max_std)
     * after a lost-track reset. */
    bool settled = false;
};

class CIRLocalizer {
  public:
    /** `map` is shared: the association reference is set on it each step. */
    CIRLocalizer(std::shared_ptr<rfir::maps::CIREmitterMap> map,
                 const TLocalizerParams& p, uint64_t seed);

    /** One instant: the odometry increment since the previous one (nullopt:
     * not moved) and the IR observation (may be null). `t` (s, optional): the
     * instant's time; with it, an IR instant without an observation (no
     * receiver saw anything: a text log cannot say so otherwise) counts as
     * silence of the emitters the estimate puts a receiver under. */
    TLocalizerStep step(const std::optional<mrpt::poses::CPose2D>& odometryIncrement,
                        const rfir::obs::CObservationIRSignals* ir,
                        std::optional<double> t = std::nullopt);

    /** A known start: every particle drawn about `p` (start_std_xy,
     * start_std_phi), the estimation running from now on. Before the first
     * step. */
    void startAt(const mrpt::math::TPose2D& p);

    /** Weighted mean of the particles (eq. 5.4). */
    mrpt::poses::CPose2D estimate() const;
    /** The particles now (for a live view). */
    std::vector<mrpt::math::TPose2D> particlePoses() const {
        std::vector<mrpt::math::TPose2D> out;
        for (const auto& p : m_pdf.m_particles) out.push_back(p.d);
        return out;
    }
    /** Per emitter (index as the map's emitters()): readings, gated, checks. */
    const std::vector<TEmitterHealth>& emitterHealth() const {
        return m_monitor.health();
    }

  private:
    /** The estimate used for the Estimate association, nullopt while the
     * particles are too spread out (association_max_std). */
    std::optional<mrpt::math::TPose2D> associationReference() const;
    /** Weighted share of particles that place the reading's receiver within
     * the emitter's visible radius. */
    double fractionInView(const rfir::obs::CObservationIRSignals::TReading& r,
                          const rfir::ir::TEmitter& e) const;
    /** Largest standard deviation of the particles' position (m). */
    double positionStd() const;
    /** Receiver and emitter ID (empty: nothing) of every decoded reading. */
    using TSeen = std::vector<std::pair<rfir::obs::TIRReceiver, std::string>>;
    /** The observation to weigh with; `early` gets the repeated-ID readings
     * set aside before the first unique ID. */
    rfir::obs::CObservationIRSignals::Ptr prepare(
        const rfir::obs::CObservationIRSignals& in, TLocalizerStep& info, TSeen& seen,
        rfir::obs::CObservationIRSignals& early) const;
    /** Drops the readings inconsistent with the predicted particles (while
     * they are confident), feeds the emitter health; returns the index of a
     * reading that declares the track lost, if any. The terms it evaluates
     * for the kept readings go to m_step, for the weighing. */
    std::optional<size_t> gate(rfir::obs::CObservationIRSignals& obs,
                               TLocalizerStep& info);
    /** Expected answers: emitters the estimate puts a receiver under. */
    void checkEmitters(const TSeen& seen);
    void predict(const mrpt::poses::CPose2D& incr);
    /** Redraws particles from the first unique reading of `obs`: all of them
     * (`all`), or reset_ratio of those out of view when fewer than
     * reset_min_fraction see it. Returns how many were redrawn. */
    size_t sensorReset(const rfir::obs::CObservationIRSignals& obs, bool all);
    double drawDistance(const rfir::obs::CObservationIRSignals::TReading& r,
                        const rfir::ir::TEmitter& e);
    /** A pose consistent with the readings of one emitter (one or two receivers). */
    void drawFromReadings(
        const std::vector<const rfir::obs::CObservationIRSignals::TReading*>& rs,
        const rfir::ir::TEmitter& e, mrpt::math::TPose2D& out);

    std::shared_ptr<rfir::maps::CIREmitterMap> m_map;
    TLocalizerParams m_params;
    /** The run's generator, seeded by the constructor's seed (before m_pdf,
     * which draws from it). */
    rfir::models::TRandom m_rng;
    /** The step's likelihood, refilled every step (before m_pdf: it weighs). */
    TIRStepLikelihood m_step;
    CIRParticles m_pdf;
    mrpt::bayes::CParticleFilter m_pf;  //!< runs with its resampling off
    /** The options as configured: the resampling stage after executeOn. */
    mrpt::bayes::CParticleFilter::TParticleFilterOptions m_pfOptions;
    CTrackMonitor m_monitor;
    bool m_started = false;
    bool m_recovering = false;  //!< after a lost-track reset, until settled
    /** The receivers (from the fullest observation) and the IR cadence, for
     * the instants without an IR observation. */
    std::vector<rfir::obs::TIRReceiver> m_receivers;
    /** Before the first unique ID: the repeated-ID readings not used, with
     * the odometry pose and path length at their instant (start_history). */
    struct THistoryEntry {
        mrpt::poses::CPose2D odometry;
        double path = 0;
        rfir::obs::CObservationIRSignals::Ptr obs;
    };
    std::deque<THistoryEntry> m_history;
    mrpt::poses::CPose2D m_odometry;  //!< the increments composed
    double m_path = 0;                //!< their translations summed (m)
    /** Keeps the readings prepare() set aside (before the first unique ID). */
    void remember(rfir::obs::CObservationIRSignals::Ptr early);
    /** Adds to each particle's log-weight the history's log-likelihood at its
     * pose walked back along the odometry; then forgets the history. Returns
     * how many readings weighed. */
    size_t weighByHistory();
    std::optional<double> m_lastIrT, m_lastCheckT;
    double m_irPeriod = 0;
    void noteSilence(const rfir::obs::CObservationIRSignals* ir, std::optional<double> t,
                     TSeen& seen);
};

}  // namespace rfir::ir
