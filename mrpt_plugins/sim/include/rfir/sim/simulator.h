/* rfir: the simulator of the papers' setups (docs/simulator.md): an
 * omnidirectional robot with 8 HF RFID readers over a tag carpet, two IR
 * receivers under a ceiling emitter lattice, a range-and-bearing sensor.
 *
 * In-process use (tests, benchmarks), no files involved:
 *
 *   rfir::sim::TSimConfig cfg;               // defaults: 60 mm, 16 tags/m^2,
 *                                            // rectangular loop x3, RFID only
 *   cfg.trajectory.laps = 1;                 // shorten the run
 *   cfg.maxDuration = 30;                    // or cut it (seconds)
 *   auto out = rfir::sim::simulate(cfg, 42); // same seed -> same output
 *   for (const auto& s : out.steps) { s.t; s.odometry; s.obs; s.truePose; }
 *   out.groundTruth;  out.gtMap;  out.header;
 *
 * Step k is at t = cfg.startTime + k cfg.dt (startTime = 1 s: MRPT takes a zero
 * timestamp as invalid) unless cfg.asyncTiming() (an odometry rate or latency,
 * round-robin polls: steps at every event); out.groundTruth[k] is the true pose
 * of out.steps[k]. Faults (off by default): out.faults, docs/simulator.md.
 *
 * or from a stock INI:
 *   auto cfg = rfir::sim::loadSimConfig(RFIR_SOURCE_DIR
 *                                       "/config_ini/sim_rfid_300mm_4tags_random.ini");
 *   rfir::sim::writeOutputs(rfir::sim::simulate(cfg, 1), "/tmp/out", "run");
 *
 * The models (noise, detection, voltage) are described in docs/simulator.md. */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/obs/CObservationLogHeader.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace rfir::sim {
/** Trajectory of the robot ([trajectory] section). */
struct TTrajectoryConfig {
    enum class Kind {
        Loop,        //!< rectangle inset by `margin` in the area, `laps` times
        Predefined,  //!< one of five closed shapes (`predefined` = 1..5), `laps` times
        Random,      //!< `waypoints` uniform random waypoints inside the inset area
        /** Coverage: stripes along x, `stripe_spacing` apart across y, driven
         * back and forth (boustrophedon), `laps` times. */
        Lawnmower
    };
    enum class Rotation {
        None,    //!< heading constant: the omnidirectional robot only translates
        Follow,  //!< turns in place at each corner to face the next segment
        Spin     //!< rotates at `spinRate` while translating
    };
    Kind kind = Kind::Loop;
    Rotation rotation = Rotation::None;
    int laps = 3;
    int predefined = 1;
    int waypoints = 20;
    double stripeSpacing = 0.5;  //!< m, between lawnmower stripes
    double margin = 0.5;         //!< distance kept from the area border (m)
    double speed = 0.2;          //!< m/s
    double turnRate = 0.5;       //!< rad/s, in-place turns (Follow)
    double spinRate = 0.2;       //!< rad/s (Spin)
    double startPhi = 0;         //!< initial heading (rad)
    int spots = 0;               //!< stops spread evenly along the path (IR: 70)
    double spotPause = 1.0;      //!< seconds standing at each spot
};

/** Kidnapping ([kidnap] section): at `time` the robot is lifted and carried for
 * `carryTime` seconds to the pose it had at `toTime` (then it replays its path
 * from there), or, when `toTime` < 0, to (toX, toY, toPhi) (then the rest of its
 * path is moved rigidly with it). The wheels do not turn while carried: odometry
 * records go on unchanged (Frozen) or stop until it is put down (Stop). The
 * lifted robot's floor readers read nothing. */
struct TKidnapConfig {
    enum class Odometry { Frozen, Stop };
    bool enabled = false;
    double time = 60;
    double carryTime = 2.0;
    double toTime = 10;
    double toX = 0, toY = 0, toPhi = 0;
    Odometry odometry = Odometry::Frozen;
};

/** Odometry noise ([odometry] section), per step on the true increment
 * (dx, dy, dphi) in the robot frame, d = |(dx, dy)|:
 *   dx' = (1 + s) dx + N(0, kXY^2 d),  dy' = (1 + s) dy + N(0, kXY^2 d)
 *   dphi' = (1 + r) dphi + h d + N(0, kPhiRot^2 |dphi| + kPhiXY^2 d)
 * with per-run biases s ~ N(0, scaleSigma), r ~ N(0, rotScaleSigma),
 * h ~ N(0, headingDriftSigma) [rad/m]. Variances grow with the distance
 * (not the step count), so the drift does not depend on dt. */
struct TOdometryNoise {
    double kXY = 0.01;                 //!< m / sqrt(m)
    double kPhiRot = 0.02;             //!< rad / sqrt(rad)
    double kPhiXY = 0.005;             //!< rad / sqrt(m)
    double scaleSigma = 0.01;          //!< translation scale bias (fraction)
    double rotScaleSigma = 0.01;       //!< rotation scale bias (fraction)
    double headingDriftSigma = 0.005;  //!< rad per metre travelled
    /** Fixed systematic errors, added to the drawn biases s, r, h (faults;
     * 0 by default): a known miscalibration rather than a random one. */
    double scaleError = 0, rotScaleError = 0, headingDriftError = 0;

    // Timing (faults; off by default). With rate > 0 or latency > 0 the run
    // is event-driven (docs/simulator.md, "Faults").
    double rate = 0;     //!< odometry records per second (0: one per dt step)
    double latency = 0;  //!< a record at t reports the wheels' pose at t - latency
    /** Wheel slips: at each time (s from the start) the odometry interval
     * containing it gains an extra translation of slipSize along the motion
     * (robot frame) and slipHeading rad; slipCount more at random times. */
    std::vector<double> slipTimes;
    int slipCount = 0;
    double slipSize = 0.05, slipHeading = 0;

    /** Every noise parameter times k (the odometry sweeps). */
    void scale(double k) {
        for (double* v :
             {&kXY, &kPhiRot, &kPhiXY, &scaleSigma, &rotScaleSigma, &headingDriftSigma})
            *v *= k;
    }
};

/** Tag carpet ([rfid] section): a square grid of `density` tags/m^2 over the
 * area, each tag displaced by N(0, placementSigma) per axis. */
struct TRFIDConfig {
    bool enabled = true;
    double density = 16;
    double placementSigma = 0.005;
    double missProbability = 0;          //!< a tag inside a square is missed with it
    std::string uidPrefix = "E0040150";  //!< + 8 random hex digits per tag

    // Faults, off by default (docs/simulator.md, "Faults").
    /** Per reader poll: the probability that the reader also reports one real
     * tag whose centre lies ghostMinDistance..ghostMaxDistance from its centre. */
    double ghostRate = 0;
    double ghostMinDistance = 0.2, ghostMaxDistance = 0.6;
    struct TDeadInterval {
        size_t reader = 0;        //!< index into TSimConfig::readers
        double from = 0, to = 0;  //!< s from the start; reads nothing in [from, to)
    };
    std::vector<TDeadInterval> deadReaders;
    bool writeEmptyPolls = true;  //!< false: a reader that read nothing is not written
    enum class Polling {
        Together,   //!< every reader at every dt step
        RoundRobin  //!< one reader per poll, each pollRate times a second
    };
    Polling polling = Polling::Together;
    double pollRate = 5;    //!< Hz per reader (round robin)
    double pollJitter = 0;  //!< uniform +- jitter on each poll time (s)
};

/** Ceiling emitters and receivers ([ir] section); thesis chapter 5. */
struct TIRConfig {
    enum class Output { Decoded, Raw };
    bool enabled = false;
    double pitch = 0.8;            //!< same-type emitter spacing (m)
    double ceilingHeight = 1.5;    //!< emitter height above the floor (m)
    double heightSpread = 0;       //!< per-emitter uniform +- variation (m)
    double referenceHeight = 1.2;  //!< vertical distance eq. 5.3 was fitted at
    std::vector<uint8_t> repeatedCodes{1, 2, 3, 4};
    int uniqueCodesPerId = 2;
    bool withRepeated = true, withUnique = true;
    bool allUnique = false;       //!< unique IDs at every position (thesis 5.4.1)
    double visibleRadius = 0.28;  //!< horizontal radius an emitter is seen in
    double voltSigma = 0.03;      //!< V noise on the decoded voltage
    Output output = Output::Decoded;
    double rateHz = 8000;
    int samples = 800;
    double rawNoiseSigma = 0.05;  //!< V noise per raw sample
    double rawOffset = 0.4;       //!< ambient offset (V)
    double period = 0.1;          //!< seconds between IR readings
    /** Failed emitters: an ID (all emitters with it) or "x y" (the emitter
     * there), one per entry. */
    std::vector<std::string> failed;

    // Faults, off by default (docs/simulator.md, "Faults").
    /** Moved emitters: the emitter at (x, y) is written at (x + dx, y + dy)
     * in NAME.map.txt, the map given to the localizer; the truth keeps it. */
    struct TMovedEmitter {
        double x = 0, y = 0, dx = 0, dy = 0;
    };
    std::vector<TMovedEmitter> moved;
    double wrongCodeRate = 0;  //!< per reading in view: the codes are wrong
    double wrongCodeOtherId =
        0.5;  //!< of those, the fraction spelling another emitter's ID
    double voltOutlierRate =
        0;  //!< per reading in view: V uniform in [0, voltOutlierMax]
    double voltOutlierMax = 4;
};

/** Range-and-bearing sensor and landmarks ([range_bearing] section; the
 * PS-SLAM paper's section 4.2). */
struct TRBConfig {
    bool enabled = false;
    double density = 4;         //!< landmarks per m^2, uniform over the area
    double sigmaRange = 0.010;  //!< m
    double sigmaBearing = 0.05235987755982989;  //!< rad (3 deg)
};

/** Every parameter of a run; the defaults are the papers' 60 mm / 16 tags/m^2
 * rectangular loop (x3). Sections (the INI of a run): [simulation], [robot],
 * [trajectory], [kidnap], [odometry], [rfid], [ir], [range_bearing]. */
struct TSimConfig : public mrpt::config::CLoadableOptions {
    TSimConfig();

    // [simulation]
    double dt = 0.1;  //!< sensing period (s)
    /** Clock reading at the first step (s, > 0: MRPT takes a zero timestamp as
     * invalid). Step k is at startTime + k dt; kidnap times, spot pauses and
     * maxDuration count from the start. */
    double startTime = 1.0;
    double maxDuration = 0;  //!< > 0: cut the run there (s)
    double areaMinX = 0, areaMinY = 0, areaMaxX = 4, areaMaxY = 4;  //!< m

    // [robot]
    std::vector<rfir::obs::TRFIDReader> readers;    //!< default: ring of 8
    std::vector<rfir::obs::TIRReceiver> receivers;  //!< default: 2, top sides
    rfir::obs::TRBSensor rbSensor;

    TTrajectoryConfig trajectory;
    TKidnapConfig kidnap;
    /** The clock (s, as the steps' timestamps) at which the robot is lifted
     * and put down: kidnap.time counts from the start, the clock from
     * startTime. */
    double kidnapLiftClock() const { return startTime + kidnap.time; }
    double kidnapDownClock() const { return kidnapLiftClock() + kidnap.carryTime; }
    TOdometryNoise odometry;
    TRFIDConfig rfid;
    TIRConfig ir;
    TRBConfig rb;

    /** Reads the sections "<prefix>simulation", "<prefix>robot", ... (prefix
     * usually empty). A missing key keeps its current value; an unknown key in
     * one of these sections or a bad value throws std::runtime_error naming
     * the section and key. */
    void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                            const std::string& prefix) override;
    void dumpToTextStream(std::ostream& out) const override;
    /** Throws std::invalid_argument naming the parameter if inconsistent. */
    void validate() const;
    /** Is any fault of docs/simulator.md's "Faults" on? */
    bool hasFaults() const;
    /** Event-driven timing (odometry rate or latency, round-robin polls)? */
    bool asyncTiming() const;
};

/** Loads an INI (every section of the file must be one of ours), then applies
 * `overrides` ("section.key=value", as rfir-sim --set). Throws
 * std::runtime_error("FILE: [section] key: what is wrong"). */
TSimConfig loadSimConfig(const std::string& iniPath,
                         const std::vector<std::string>& overrides = {});

/** The sections loadSimConfig knows (for routing a program's --set edits). */
const std::vector<std::string>& simConfigSections();

/** The default reader layout: 8 readers on a ring of radius `ringRadius`
 * at 22.5 + k * 45 deg, squares of half side `halfSize`. */
std::vector<rfir::obs::TRFIDReader> ringReaderLayout(double ringRadius, double halfSize);

/** One sensing instant. */
struct TSimStep {
    double t = 0;
    std::optional<mrpt::poses::CPose2D> odometry;  //!< absolute odometry pose
    /** Labels RFID, IR, RB; IR and RB only when something is in view, in the
     * form a text log's import gives (docs/simulator.md, "Rawlogs and the
     * text format"). */
    std::vector<mrpt::obs::CObservation::Ptr> obs;
    mrpt::poses::CPose2D truePose;
};

struct TSimOutput {
    rfir::obs::CObservationLogHeader header;
    std::vector<TSimStep> steps;
    rfir::common::TPath2D groundTruth;  //!< true pose at every step
    rfir::common::TMapFile gtMap;       //!< tags, emitters, landmarks
    rfir::common::TPath2D spots;        //!< true pose at each stop (IR spots)
    /** Emitters installed but not emitting, "ID x y" (they are in gtMap). */
    std::vector<std::string> failedEmitters;
    /** Per-run odometry biases drawn from the noise model (s, r, h). */
    double scaleBias = 0, rotScaleBias = 0, headingDrift = 0;
    /** The faults injected, one record per line of NAME.gt_faults.txt
     * (docs/simulator.md): "ghost t reader tag distance", "slip t dx dy dphi",
     * "dead_reader reader from to", "wrong_code t receiver true written",
     * "volt_outlier t receiver true written", "moved_emitter id x y map_x map_y",
     * "failed_emitter id x y", "odometry_bias s r h". Empty without faults. */
    std::vector<std::string> faults;
    bool hasFaults = false;
    /** With moved emitters: the map the localizer is given (NAME.map.txt). */
    rfir::common::TMapFile localizerMap;
};

/** Runs the simulation; deterministic in (cfg, seed). */
TSimOutput simulate(const TSimConfig& cfg, uint64_t seed);

/** Writes DIR/NAME.rawlog, NAME.gt.tum, NAME.gt_map.txt and, when there are
 * spots, NAME.spots.tum, with faults NAME.gt_faults.txt, with moved emitters
 * NAME.map.txt (each file whole or not at all); progress lines go to
 * `progress` if given. */
void writeOutputs(const TSimOutput& out, const std::string& outDir,
                  const std::string& name, std::ostream* progress = nullptr);

}  // namespace rfir::sim
