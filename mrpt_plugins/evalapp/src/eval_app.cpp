/* rfir-eval: errors of an estimated path and map against the ground truth, in
 * the papers' table layout (mm, rad) and as one JSON line; optional PNG figure. */
#include <rfir/evalapp/eval_app.h>

#include <rfir/common/atomic_file.h>
#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/common/usage_error.h>
#include <rfir/eval/metrics.h>
#include <rfir/eval/plot.h>
#include <rfir/eval/report.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace rfir::evalapp {
using namespace rfir::eval;
using rfir::common::TMapEntry;

namespace {
/** MRPT's outputs need the log's start pose (rbpf-slam's start at the origin)
 * or its instants' times (pf-localization's particle files). */
void validateMrptInputs(const TEvalArgs& a) {
    using rfir::common::CUsageError;
    const bool mrptPath =
        (!a.path.empty() && a.pathFormat == InputFormat::Mrpt) ||
        std::any_of(a.runs.begin(), a.runs.end(), [&](const TRunSpec& r) {
            return r.format.value_or(a.pathFormat) == InputFormat::Mrpt;
        });
    const bool mrptMap =
        (!a.map.empty() && a.mapFormat == InputFormat::Mrpt) ||
        std::any_of(a.runs.begin(), a.runs.end(), [&](const TRunSpec& r) {
            return !r.map.empty() && r.format.value_or(a.mapFormat) == InputFormat::Mrpt;
        });
    if ((mrptPath || mrptMap) && a.rawlog.empty() && !a.start)
        throw CUsageError(std::string(mrptPath ? "--path-format" : "--map-format") +
                          " mrpt: MRPT's rbpf-slam starts at the origin: give --rawlog "
                          "FILE (its header's start pose) or --start X Y PHI");
    std::vector<std::string> paths;
    if (a.pathFormat == InputFormat::Mrpt && !a.path.empty()) paths.push_back(a.path);
    for (const auto& r : a.runs)
        if (r.format.value_or(a.pathFormat) == InputFormat::Mrpt) paths.push_back(r.path);
    for (const auto& p : paths)
        if (std::filesystem::is_directory(p) && a.rawlog.empty())
            throw CUsageError("--path-format mrpt: " + p +
                              " is pf-localization's output folder: its particle files "
                              "carry no time, give --rawlog FILE");
}
}  // namespace

void validateEvalArgs(const TEvalArgs& a) {
    validateMrptInputs(a);
    if (!a.runs.empty() && (!a.path.empty() || !a.map.empty() || a.segments > 0))
        throw rfir::common::CUsageError(
            "--run compares whole runs: give each path and map in its --run, "
            "without --path, --map or --segments");
    if (!a.runs.empty() && a.gtPath.empty())
        throw rfir::common::CUsageError("--run needs --gt-path (the ground-truth path)");
    for (const auto& r : a.runs)
        if (!r.map.empty() && a.gtMap.empty())
            throw rfir::common::CUsageError("--run " + r.label +
                                            ": a map needs --gt-map");
    if (!a.runs.empty()) return;
    if (!a.path.empty() && a.gtPath.empty())
        throw rfir::common::CUsageError("--path needs --gt-path (the ground-truth path)");
    if (!a.errorPlot.empty() && a.path.empty())
        throw rfir::common::CUsageError("--error-plot needs --path and --gt-path");
    if (a.segments < 0)
        throw rfir::common::CUsageError(
            "--segments must be a positive number of windows, not " +
            std::to_string(a.segments));
    if (a.segments > 0 && a.path.empty())
        throw rfir::common::CUsageError("--segments needs --path and --gt-path");
    if (!a.map.empty() && a.gtMap.empty())
        throw rfir::common::CUsageError("--map needs --gt-map (the ground-truth map)");
    if (a.path.empty() && a.map.empty())
        throw rfir::common::CUsageError(
            "nothing to evaluate: give --path/--gt-path and/or "
            "--map/--gt-map (see --help)");
    if (!a.kind.empty() && a.kind != "tag" && a.kind != "landmark")
        throw rfir::common::CUsageError("--kind must be 'tag' or 'landmark', not '" +
                                        a.kind + "'");
}

namespace {
/** Passed-over / in-view landmarks, when the sensor geometry is known. */
void addPassedOverOrWarn(TMapErrors& m, const rfir::common::TMapFile& est,
                         const rfir::common::TMapFile& gt,
                         const rfir::common::TPath2D& gtPath, const TRawlogInfo& info) {
    if (!addPassedOver(m, est, gt, gtPath, info))
        std::cerr << "warning: the rawlog declares no "
                  << (m.kind == TMapEntry::Kind::Tag ? "RFID reader"
                                                     : "range-bearing sensor")
                  << ": no passed-over count\n";
}

/** --segments: windows over the ground truth's time span. */
void addSegments(TEvalResult& r, const rfir::common::TPath2D& gt, size_t n) {
    const double t0 = gt.front().t, t1 = gt.back().t;
    if (!(t1 > t0))
        throw std::runtime_error("--segments: the ground-truth path spans no time");
    for (size_t k = 0; k <= n; k++) r.segmentBounds.push_back(t0 + (t1 - t0) * k / n);
    r.robotSegments = segmentStats(r.robot->perPose, t0, t1, n);
    if (r.odometry) r.odometrySegments = segmentStats(r.odometry->perPose, t0, t1, n);
}

/** The rawlog's information, its start pose replaced by --start. */
std::optional<TRawlogInfo> rawlogInfo(const TEvalArgs& a) {
    if (a.rawlog.empty()) return std::nullopt;
    TRawlogInfo info = readRawlogInfo(a.rawlog);
    if (a.start) info.startPose = a.start;
    return info;
}

/** What puts MRPT's outputs in the world frame: the start pose (--start, else
 * the rawlog header's) and the rawlog's instants. */
TMrptFrame mrptFrame(const TEvalArgs& a, const std::optional<TRawlogInfo>& info) {
    TMrptFrame f;
    f.start = a.start;
    if (info) {
        if (!f.start) f.start = info->startPose;
        f.instantTimes = info->instantTimes;
        f.firstInstantStep = info->hasHeader ? 1 : 0;
    }
    return f;
}

/** Several runs: one table, one JSON line, one figure. */
int runCompare(const TEvalArgs& a, TMapFigure& fig) {
    TCompareInput in;
    in.gt = loadTumChecked(a.gtPath);
    checkPath(in.gt, a.gtPath);
    if (!a.gtMap.empty()) in.gtMap = rfir::common::loadMapFile(a.gtMap);
    in.rawlog = rawlogInfo(a);
    in.frame = mrptFrame(a, in.rawlog);
    in.pathFormat = a.pathFormat;
    in.mapFormat = a.mapFormat;
    in.deadReckoningRow = !a.noOdometry;
    in.assoc = a.atGtTimes ? Association::AtTruthTimes : Association::AtEstimateTimes;
    const auto rows = compareRuns(a.runs, in, fig);
    const std::string json = toJsonRuns(rows);
    if (!a.plot.empty()) plotMapFigure(a.plot, fig);
    if (!a.errorPlot.empty()) plotErrorsOverTime(a.errorPlot, rows, fig.title);
    if (!a.jsonFile.empty())
        rfir::common::writeFileAtomically(a.jsonFile,
                                          [&](std::ostream& o) { o << json << "\n"; });
    if (a.quiet) return 0;
    if (!a.jsonOnly) std::cout << formatErrorTable(rows) << "\n";
    std::cout << json << std::endl;
    return 0;
}

}  // namespace

int runEvalApp(const TEvalArgs& a) {
    TEvalResult r;
    r.label = a.label;
    TMapFigure fig;
    fig.title = a.title.empty() ? a.label : a.title;
    fig.showIds = a.ids;
    if (!a.runs.empty()) {
        if (a.title.empty()) fig.title = "runs compared";
        return runCompare(a, fig);
    }
    rfir::common::TPath2D gt;
    const auto assoc =
        a.atGtTimes ? Association::AtTruthTimes : Association::AtEstimateTimes;
    if (!a.gtPath.empty()) {
        gt = loadTumChecked(a.gtPath);
        checkPath(gt, a.gtPath);
        fig.gtPath = gt;
    }
    const std::optional<TRawlogInfo> info = rawlogInfo(a);
    const TMrptFrame frame = mrptFrame(a, info);
    if (!a.path.empty()) {
        const auto est = loadPath(a.path, a.pathFormat, frame);
        if (est.empty()) throw std::runtime_error(a.path + ": the path has no pose");
        if (a.atGtTimes) checkPath(est, a.path);  // interpolated: must be sorted
        r.robot = computeRobotErrors(est, gt, assoc);
        fig.estPath = est;
        fig.estPathLabel = a.label;
    }
    if (info && !gt.empty() && !a.noOdometry && !info->odometry.empty()) {
        // Dead reckoning from the known start pose (as the filters start), or
        // from the ground truth at the first odometry time.
        const auto dr = deadReckoning(info->odometry, info->startPose, gt);
        r.odometry = computeRobotErrors(dr, gt, assoc);
        fig.odomPath = dr;
    }
    if (a.segments > 0) addSegments(r, gt, size_t(a.segments));
    if (!a.gtMap.empty()) fig.gtMap = rfir::common::loadMapFile(a.gtMap);
    if (!a.map.empty()) {
        fig.estMap = loadMap(a.map, a.mapFormat, frame);
        std::optional<TMapEntry::Kind> k;
        if (!a.kind.empty())
            k = a.kind == "tag" ? TMapEntry::Kind::Tag : TMapEntry::Kind::Landmark;
        r.map = computeMapErrors(fig.estMap, fig.gtMap, k);
        if (info && !gt.empty())
            addPassedOverOrWarn(*r.map, fig.estMap, fig.gtMap, gt, *info);
    }
    // Files first: a failure (e.g. a missing folder) then prints no results.
    const std::string json = toJson(r);
    if (!a.plot.empty()) plotMapFigure(a.plot, fig);
    if (!a.errorPlot.empty()) plotErrorsOverTime(a.errorPlot, r, fig.title);
    if (!a.jsonFile.empty())
        rfir::common::writeFileAtomically(a.jsonFile,
                                          [&](std::ostream& o) { o << json << "\n"; });
    if (a.quiet) return 0;
    if (!a.jsonOnly) std::cout << formatErrorTable({r}) << "\n";
    std::cout << json << std::endl;
    return 0;
}
}  // namespace rfir::evalapp
