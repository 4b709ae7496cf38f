#include <rfir/slamapp/slam_app.h>

#include <rfir/common/install_paths.h>
#include <rfir/slam/graph_smoother.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/ini_file.h>
#include <rfir/common/ini_key_docs.h>
#include <rfir/common/ini_override.h>
#include <rfir/common/json.h>
#include <rfir/common/map_io.h>
#include <rfir/common/output_set.h>
#include <rfir/common/progress.h>
#include <rfir/common/rawlog_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/eval/compare.h>
#include <rfir/eval/input_formats.h>
#include <rfir/eval/metrics.h>
#include <rfir/eval/plot.h>
#include <rfir/eval/report.h>
#include <rfir/eval/scene3d.h>
#include <rfir/slam/slam_engine.h>
#include <rfir/slam/slam_inputs.h>
#include <rfir/slam/slam_outputs.h>

#include <mrpt/random/RandomGenerators.h>
#include <mrpt/system/filesystem.h>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace rfir::slamapp {
using rfir::common::TMapEntry;
using rfir::common::TMapFile;
using rfir::common::TPath2D;

namespace {
/** stderr, or a sink under --quiet (warnings still go to stderr). */
std::ostream& logStream(const TAppArgs& a) {
    static thread_local std::ostream sink(nullptr);  // runs in threads (Python)
    return a.quiet ? sink : std::cerr;
}

/** The INI with the --set edits written over it (in memory); a bad edit is
 * a command-line error naming it (rfir::common::loadWithIniEdits). */
rfir::slam::TSlamConfig loadConfig(const std::string& ini, const TAppArgs& a) {
    rfir::slam::TSlamConfig cfg;
    rfir::common::loadWithIniEdits(a.sets, [&](const std::vector<std::string>& edits) {
        auto f = rfir::common::readIniFile(ini);
        rfir::common::applyIniOverrides(f, edits);
        cfg = rfir::slam::loadSlamConfig(f, a.method);
    });
    return cfg;
}

struct TLoaded {
    rfir::obs::CObservationLogHeader header;
    bool hasHeader = true;
    std::optional<mrpt::poses::CPose2D> firstOdometry;  //!< first absolute pose
    std::vector<rfir::slam::TSlamInput> inputs;
    rfir::eval::TRawlogInfo info;  //!< odometry and sensor geometry, for the scoring
};

/** Reads the rawlog once: the filters' inputs and what the scoring needs;
 * with [motion] interpolate_polls, every instant at the odometry interpolated
 * to its time (rfir::slam::interpolatedInputs). */
TLoaded readInputs(const std::string& path, const rfir::slam::TMotionOptions& motion) {
    if (!mrpt::system::fileExists(path))
        throw std::runtime_error("cannot read rawlog '" + path + "'");
    rfir::common::CRawlogReader rd(path);
    TLoaded l;
    l.header = rd.header();
    l.hasHeader = rd.hasHeader();
    rfir::eval::CRawlogInfoBuilder info(l.header);
    rfir::common::TRawlogStep st;
    std::vector<rfir::slam::TRawInstant> raw;
    std::optional<mrpt::poses::CPose2D> odo;  // the increments composed
    std::optional<double> lastOdoT;
    while (rd.next(st)) {
        info.add(st);
        if (!l.firstOdometry) l.firstOdometry = st.odometry;
        rfir::slam::TSlamInput in;
        in.t = st.t;
        in.odometryIncrement = st.odometryIncrement;
        if (st.odometryIncrement && lastOdoT) in.odometryDt = st.t - *lastOdoT;
        if (st.odometryIncrement || st.odometry) lastOdoT = st.t;
        in.rfid = st.rfid;
        in.rb = st.rb;
        if (motion.interpolate_polls) {
            // Absolute odometry from the increments the filters would use.
            const bool anchor = !odo && (st.odometry || st.odometryIncrement);
            if (anchor) odo = mrpt::poses::CPose2D();
            if (st.odometryIncrement) odo = *odo + *st.odometryIncrement;
            raw.push_back({st.t, anchor || st.odometryIncrement ? odo : std::nullopt,
                           st.rfid, st.rb});
        }
        l.inputs.push_back(std::move(in));
    }
    if (l.inputs.empty()) throw std::runtime_error(path + ": no sensing instant");
    if (motion.interpolate_polls)
        l.inputs = rfir::slam::interpolatedInputs(raw, motion.odometry_latency);
    l.info = info.finish();
    return l;
}

/** Where the filter starts: --start, else the rawlog header's start pose,
 * else (no header, e.g. a rawlog cut by rawlog-edit) the first odometry pose
 * (the simulator's odometry starts at the true pose), said on stderr. */
mrpt::poses::CPose2D startPose(const TAppArgs& a, const TLoaded& d) {
    if (a.start) return *a.start;
    if (d.header.startPose) return *d.header.startPose;
    const auto p = d.firstOdometry.value_or(mrpt::poses::CPose2D());
    std::ostringstream o;
    o << "rfir-slam: warning: " << a.rawlog
      << (d.hasHeader ? ": the rfir log header gives no start pose"
                      : ": no rfir log header (cut by rawlog-edit?)")
      << "; assumed: start pose " << p.x() << " " << p.y() << " " << p.phi()
      << (d.firstOdometry ? " (the first odometry pose)" : " (no odometry pose)")
      << " (set it with --start X Y PHI)";
    if (!d.hasHeader) {
        o << "; RFID readers from the observations:";
        for (const auto& r : d.info.readers)
            o << " " << r.id << " (" << r.x << ", " << r.y << ", " << 2 * r.halfX << " x "
              << 2 * r.halfY << " m)";
        if (d.info.readers.empty()) o << " none";
    }
    std::cerr << o.str() << "\n";
    return p;
}

/** The ground truth of a run, loaded once for every set of outputs. */
struct TTruth {
    std::optional<TPath2D> path;
    std::optional<TMapFile> map;
    std::optional<TPath2D> odometry;  //!< aligned at the start to `path`
    std::optional<rfir::eval::TRobotErrors> odometryErrors;
    std::vector<rfir::obs::TRFIDReader> readers;
    std::optional<rfir::obs::TRBSensor> rbSensor;
};

TTruth loadTruth(const TAppArgs& a, const rfir::eval::TRawlogInfo& info) {
    TTruth t;
    t.readers = info.readers;  // also drawn in the 3D scene, truth or not
    t.rbSensor = info.rbSensor;
    if (!a.gtPath) {
        if (a.gtMap)
            std::cerr
                << "rfir-slam: --gt-map without a ground-truth path: no error table\n";
        return t;
    }
    t.path = rfir::common::loadTUM(*a.gtPath);
    if (!info.odometry.empty()) {
        // From where the filter starts, as rfir-eval does.
        t.odometry = rfir::eval::deadReckoning(
            info.odometry, a.start ? a.start : info.startPose, *t.path);
        t.odometryErrors = rfir::eval::computeRobotErrors(*t.odometry, *t.path);
    }
    if (a.gtMap) t.map = rfir::common::loadMapFile(*a.gtMap);
    return t;
}

using rfir::common::printed;
using rfir::common::TJson;

std::string statsJson(const rfir::slam::TSlamConfig& cfg, const rfir::slam::TSlamRun& run,
                      uint64_t seed, const std::string& identity, const TJson& smoother) {
    size_t tags = 0, lms = 0;
    uint64_t reseats = 0;
    for (const auto& l : run.map) {
        (l.isTag ? tags : lms)++;
        reseats += l.reseats;
    }
    TJson j;
    j["method"] = rfir::slam::methodName(cfg.slam.method);
    j["seed"] = seed;
    j["steps"] = run.path.size();
    j["tags_mapped"] = tags;
    j["landmarks_mapped"] = lms;
    j["tags_reseated"] = reseats;
    j["robot_particles"] = cfg.slam.robot_particles;
    j["mean_update_time_s"] = printed(run.meanStepTime);
    j["max_update_time_s"] = printed(run.maxStepTime);
    j["total_time_s"] = printed(run.totalTime);
    j["kidnap_resets"] = run.resets;
    j["kidnap_reset_times_s"] = printed(run.resetTimes);
    if (!run.loopClosureTimes.empty())
        j["loop_closure_times_s"] = printed(run.loopClosureTimes);
    if (!smoother.is_null()) j["smoother"] = smoother;
    j["run"] = TJson::parse(identity);
    return rfir::common::dumpJson(j) + "\n";
}

const std::vector<std::string> kOutputPatterns = {
    "path*.tum",      "map*.txt",        "path_map*.png", "errors*.json",
    "scene*.3Dscene", "error_time*.png", "settings.ini",  "stats.json"};

/** settings.ini and stats.json, last: they name the run and every file it
 * wrote. Returns stats.json's text. */
std::string writeSettingsAndStats(rfir::common::COutputFolder& out,
                                  const rfir::slam::TSlamConfig& cfg,
                                  const rfir::slam::TSlamRun& run, uint64_t seed,
                                  const std::string& ini, const TJson& smoother) {
    const std::string settingsPath = out.file("settings.ini");
    const std::string statsPath = out.file("stats.json");
    const auto files = out.files();
    const std::string id = rfir::common::runIdentityJson(seed, ini, files);
    std::string list;
    for (const auto& f : files) list += " " + f;
    const std::string settings =
        "# rfir-slam " + rfir::common::rfirVersion() + ": " +
        rfir::common::processCommandLine() + "\n# seed " + std::to_string(seed) +
        ", INI " + ini + " (md5 " + rfir::common::fileMD5(ini) + ")\n# files:" + list +
        "\n" + rfir::common::annotateIni(rfir::slam::dumpSlamConfig(cfg), "rfir-slam");
    rfir::common::writeFileAtomically(settingsPath,
                                      [&](std::ostream& o) { o << settings; });
    const std::string stats = statsJson(cfg, run, seed, id, smoother);
    rfir::common::writeFileAtomically(statsPath, [&](std::ostream& o) { o << stats; });
    return stats;
}

/** Ground truth beside the rawlog unless given. */
void findGroundTruth(TAppArgs& a) {
    const std::string base = rfir::common::rawlogStem(a.rawlog);
    if (!a.gtPath && mrpt::system::fileExists(base + ".gt.tum"))
        a.gtPath = base + ".gt.tum";
    if (!a.gtMap && mrpt::system::fileExists(base + ".gt_map.txt"))
        a.gtMap = base + ".gt_map.txt";
}

/** Errors against the ground truth, if there is one (fig gets the truth). */
std::optional<rfir::eval::TEvalResult> evaluate(const TTruth& truth,
                                                const std::string& label,
                                                const TPath2D& est,
                                                const TMapFile& estMap,
                                                rfir::eval::TMapFigure& fig) {
    if (!truth.path) return std::nullopt;
    const TPath2D& gt = *truth.path;
    rfir::eval::TEvalResult r;
    r.label = label;
    fig.gtPath = gt;
    r.robot = rfir::eval::computeRobotErrors(est, gt);
    if (truth.odometry) fig.odomPath = *truth.odometry;
    r.odometry = truth.odometryErrors;
    if (truth.map) {
        const TMapFile& gtm = *truth.map;
        fig.gtMap = gtm;
        bool anyTag = false;
        for (const auto& e : estMap) anyTag |= e.kind == TMapEntry::Kind::Tag;
        const auto kind =
            anyTag || estMap.empty() ? TMapEntry::Kind::Tag : TMapEntry::Kind::Landmark;
        r.map = rfir::eval::computeMapErrors(estMap, gtm, kind);
        if (kind == TMapEntry::Kind::Tag && !truth.readers.empty())
            rfir::eval::setPassedOver(
                *r.map, rfir::eval::tagsPassedOver(gtm, gt, truth.readers), estMap);
        else if (kind == TMapEntry::Kind::Landmark && truth.rbSensor)
            rfir::eval::setPassedOver(
                *r.map, rfir::eval::landmarksInView(gtm, gt, *truth.rbSensor), estMap);
    }
    return r;
}

void writeErrors(const std::string& file, const rfir::eval::TEvalResult& r) {
    rfir::common::writeFileAtomically(
        file, [&](std::ostream& o) { o << rfir::eval::toJson(r) << "\n"; });
}

/** A run's path and map, and its errors against the ground truth if any. */
struct TScored {
    TPath2D path;
    TMapFile map;
    std::optional<rfir::eval::TEvalResult> errors;
};

/** path<sfx>.tum, map<sfx>.txt, path_map<sfx>.png and errors<sfx>.json of a
 * run, named `label` in the table, the figure and the map's header; only
 * scored, nothing written, without `out`. */
TScored writeAndScore(const TAppArgs& a, rfir::common::COutputFolder* out,
                      const TTruth& truth, const rfir::slam::TSlamRun& run,
                      const std::string& sfx, const std::string& label,
                      const std::string& legend) {
    TScored s{rfir::slam::stampedPath(run), rfir::slam::landmarkEntries(run.map), {}};
    rfir::eval::TMapFigure fig;
    fig.title = "rfir-slam " + label + ": " + mrpt::system::extractFileName(a.rawlog);
    fig.estPath = s.path;
    fig.estMap = s.map;
    s.errors = evaluate(truth, label, s.path, s.map, fig);
    if (!out) return s;
    rfir::common::saveTUM(out->file("path" + sfx + ".tum"), s.path);
    rfir::common::saveMapFile(out->file("map" + sfx + ".txt"), s.map,
                              "rfir-slam " + label + ": " + legend);
    rfir::eval::plotMapFigure(out->file("path_map" + sfx + ".png"), fig);
    rfir::eval::saveScene3D(out->file("scene" + sfx + ".3Dscene"), fig, truth.readers);
    if (s.errors) {
        writeErrors(out->file("errors" + sfx + ".json"), *s.errors);
        rfir::eval::plotErrorsOverTime(out->file("error_time" + sfx + ".png"), *s.errors,
                                       fig.title);
    }
    return s;
}

/** --smooth: the offline refinement of the filter's run and its outputs. */
TScored smoothAndWrite(const TAppArgs& a, rfir::common::COutputFolder* out,
                       const rfir::slam::TSlamConfig& cfg, const TLoaded& data,
                       const TTruth& truth, const mrpt::poses::CPose2D& start,
                       const rfir::slam::TSlamRun& run, TJson& stats) {
    const auto p = rfir::slam::smootherParams(cfg);
    logStream(a) << "rfir-slam: smoothing " << run.path.size() << " poses offline ("
                 << p.options.solver << ")\n";
    const auto res = rfir::slam::smoothRun(data.inputs, start, run, p);
    logStream(a) << "rfir-slam: smoothed in " << res.iterations << " iterations, "
                 << res.seconds << " s (" << res.reads << " reads, " << res.negatives
                 << " polls without the tag; cost " << res.initialCost << " -> "
                 << res.finalCost << ")\n";
    for (const double t : res.cutTimes)
        logStream(a) << "rfir-slam: smoother cut the odometry at t = " << std::fixed
                     << std::setprecision(2) << t << " s (kidnapping)\n"
                     << std::defaultfloat;
    if (res.biasHeld)
        logStream(a) << "rfir-slam: odometry systematic error not estimated: "
                     << res.closures << " tags read again after "
                     << p.options.closure_min_travel << " m of path (bias_min_closures "
                     << p.options.bias_min_closures << ")\n";
    else
        logStream(a) << std::setprecision(6)
                     << "rfir-slam: odometry systematic error: translation scale "
                     << res.odometryScale << ", heading drift "
                     << res.headingDriftPerMetre << " rad/m\n";
    stats = TJson();
    stats["solver"] = p.options.solver;
    stats["iterations"] = res.iterations;
    stats["time_s"] = printed(res.seconds);
    stats["reads"] = res.reads;
    stats["negative_reads"] = res.negatives;
    stats["odometry_scale"] = printed(res.odometryScale);
    stats["heading_drift_rad_per_m"] = printed(res.headingDriftPerMetre);
    stats["closures"] = res.closures;  // tags read again after closure_min_travel
    stats["bias_estimated"] = res.biasEstimated;
    stats["odometry_cut_times_s"] = printed(res.cutTimes, "%.6g");
    return writeAndScore(a, out, truth, res.run, "_smoothed",
                         rfir::slam::methodName(cfg.slam.method) + " smoothed",
                         "<tag> <id> <x> <y> <sx> <sy>");
}
/** The run's values in the result, and the error table of its rows. */
void fillResult(TSlamAppResult& res, TScored main, std::optional<TScored> smoothed) {
    std::vector<rfir::eval::TEvalResult> rows;
    if (main.errors) {
        res.errorsJson = rfir::eval::toJson(*main.errors);
        rows.push_back(std::move(*main.errors));
    }
    if (smoothed) {
        res.smoothedPath = std::move(smoothed->path);
        res.smoothedMap = std::move(smoothed->map);
        if (smoothed->errors) {
            res.smoothedErrorsJson = rfir::eval::toJson(*smoothed->errors);
            smoothed->errors->odometry.reset();  // the odometry row is printed once
            rows.push_back(std::move(*smoothed->errors));
        }
    }
    if (!rows.empty()) res.errorTable = rfir::eval::formatErrorTable(rows);
    res.path = std::move(main.path);
    res.map = std::move(main.map);
}

/** The run's INI: --config, else the method's stock one; a bad --method is
 * refused before anything is read. */
std::string iniOf(const TAppArgs& a) {
    if (a.method) rfir::slam::parseMethod(*a.method);
    return a.config ? *a.config : rfir::common::slamIniPath(a.method.value_or("pf"));
}
}  // namespace

TSlamAppResult runSlam(const TAppArgs& args) {
    TAppArgs a = args;
    const std::string ini = iniOf(a);
    rfir::slam::TSlamConfig cfg = loadConfig(ini, a);
    cfg.seed = a.seed;
    findGroundTruth(a);
    // The truth's files are refused (bad line, not TUM) before the run.
    if (a.gtPath) rfir::eval::loadTumChecked(*a.gtPath);
    if (a.gtMap) rfir::common::loadMapFile(*a.gtMap);

    logStream(a) << "rfir-slam: " << rfir::slam::methodName(cfg.slam.method) << " on "
                 << a.rawlog << " (config " << ini << ", seed " << a.seed << ")\n";
    // The folder is checked (and refused if it holds foreign files) before the run.
    std::unique_ptr<rfir::common::COutputFolder> out;
    if (!a.outDir.empty())
        out = std::make_unique<rfir::common::COutputFolder>(a.outDir, kOutputPatterns,
                                                            "rfir-slam");
    TLoaded data = readInputs(a.rawlog, cfg.motion);
    // Refused before the filter runs and anything is written.
    if (a.smooth)
        for (const auto& in : data.inputs)
            if (in.rb)
                throw std::runtime_error(
                    "--smooth: " + a.rawlog +
                    " has range-bearing observations; the smoother uses RFID reads only");
    const mrpt::poses::CPose2D start = startPose(a, data);
    data.info.startPose = start;  // the dead-reckoning row starts there too
    auto engine = rfir::slam::makeEngine(cfg, data.header);
    const size_t n = data.inputs.size();
    rfir::common::CProgress progress("rfir-slam", n, a.quiet ? nullptr : &std::cerr);
    // Each sensor resetting and loop closure gets a line when it happens
    // (not only a count).
    size_t resets = 0, closures = 0;
    std::vector<std::string> events;  // this step's, for the view
    const auto report = [&](const std::vector<double>& times, size_t& done,
                            const char* what) {
        for (; done < times.size(); done++) {
            logStream(a) << "rfir-slam: " << what << " at t = " << std::fixed
                         << std::setprecision(2) << times[done] << " s\n"
                         << std::defaultfloat;
            std::ostringstream line;  // the same line for the view
            line << what << " at t = " << std::fixed << std::setprecision(2)
                 << times[done] << " s";
            events.push_back(line.str());
        }
    };
    // The view's truth is read here only for it (loadTruth comes after the run).
    std::optional<TPath2D> viewTruth;
    if (a.onStep && a.gtPath) viewTruth = rfir::common::loadTUM(*a.gtPath);
    const auto run = rfir::slam::runEngine(*engine, start, data.inputs, [&](size_t i) {
        progress.update(i);
        events.clear();
        report(engine->resetTimes(), resets, "kidnap detected, sensor resetting");
        report(engine->loopClosureTimes(), closures, "loop closure by smoothing");
        if (a.onStep)
            a.onStep({i, n, data.inputs[i], *engine, viewTruth ? &*viewTruth : nullptr,
                      events, rfir::slam::methodName(cfg.slam.method)});
    });
    progress.finish();

    const TTruth truth = loadTruth(a, data.info);
    const bool counts = cfg.method() != rfir::slam::TMethod::FastSLAM;
    TScored main = writeAndScore(
        a, out.get(), truth, run, "", rfir::slam::methodName(cfg.slam.method),
        counts ? "<tag or landmark> <id> <x> <y> <sx> <sy> <reads> <contradicted>"
               : "<tag or landmark> <id> <x> <y> <sx> <sy>");
    TSlamAppResult res;
    std::optional<TScored> smoothed;
    TJson smootherStats;  // null unless smoothed
    if (a.smooth)
        smoothed =
            smoothAndWrite(a, out.get(), cfg, data, truth, start, run, smootherStats);
    if (out) {
        res.statsJson = writeSettingsAndStats(*out, cfg, run, a.seed, ini, smootherStats);
        out->commit();
    } else {
        res.statsJson =
            statsJson(cfg, run, a.seed, rfir::common::runIdentityJson(a.seed, ini, {}),
                      smootherStats);
    }
    fillResult(res, std::move(main), std::move(smoothed));
    logStream(a) << "rfir-slam: " << run.path.size() << " steps, " << run.map.size()
                 << " landmarks, " << std::fixed << std::setprecision(2)
                 << run.meanStepTime * 1e3 << " ms/update"
                 << (a.outDir.empty() ? "" : "; outputs in " + a.outDir) << "\n"
                 << std::defaultfloat;
    return res;
}

int runSlamApp(const TAppArgs& a) {
    if (a.helpKeys) {
        const std::string ini = iniOf(a);
        std::cout << rfir::common::describeKeys(
            "rfir-slam", [&] { return rfir::slam::dumpSlamConfig(loadConfig(ini, a)); });
        return 0;
    }
    const TSlamAppResult res = runSlam(a);
    if (!a.quiet) std::cout << res.errorTable;
    return 0;
}

}  // namespace rfir::slamapp
