#include <rfir/eval/compare.h>

#include "report_json.h"

#include <rfir/common/usage_error.h>

#include <stdexcept>

namespace rfir::eval {
using rfir::common::TMapEntry;

TRunSpec parseRunSpec(const std::string& s) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
        throw rfir::common::CUsageError(
            "--run '" + s + "': expected LABEL=PATH[,MAP] or LABEL=mrpt:PATH[,MAP]");
    TRunSpec r;
    r.label = s.substr(0, eq);
    std::string rest = s.substr(eq + 1);
    if (rest.rfind("mrpt:", 0) == 0) {  // an MRPT app's path and map
        r.format = InputFormat::Mrpt;
        rest = rest.substr(5);
    }
    const auto comma = rest.find(',');
    r.path = rest.substr(0, comma);
    if (comma != std::string::npos) r.map = rest.substr(comma + 1);
    if (r.path.empty() || (comma != std::string::npos && r.map.empty()))
        throw rfir::common::CUsageError("--run '" + s + "': empty path or map file name");
    return r;
}

bool addPassedOver(TMapErrors& m, const rfir::common::TMapFile& est,
                   const rfir::common::TMapFile& gt, const rfir::common::TPath2D& gtPath,
                   const TRawlogInfo& info) {
    if (m.kind == TMapEntry::Kind::Tag && !info.readers.empty())
        setPassedOver(m, tagsPassedOver(gt, gtPath, info.readers), est);
    else if (m.kind == TMapEntry::Kind::Landmark && info.rbSensor)
        setPassedOver(m, landmarksInView(gt, gtPath, *info.rbSensor), est);
    else
        return false;
    return true;
}

namespace {
mrpt::img::TColor runColor(size_t i) {
    // Not the truth's blue, the tags' green and purple, or the odometry's grey.
    static const mrpt::img::TColor c[] = {
        {214, 39, 40}, {255, 127, 14}, {23, 190, 207}, {140, 86, 75}, {227, 119, 194}};
    return c[i % (sizeof(c) / sizeof(c[0]))];
}
}  // namespace

namespace {
TEvalResult scoreRun(const TRunSpec& s, const TCompareInput& in,
                     rfir::common::TPath2D& path, rfir::common::TMapFile& map) {
    TEvalResult r;
    r.label = s.label;
    path = loadPath(s.path, s.format.value_or(in.pathFormat), in.frame);
    if (path.empty()) throw std::runtime_error(s.path + ": the path has no pose");
    if (in.assoc == Association::AtTruthTimes) checkPath(path, s.path);
    try {
        r.robot = computeRobotErrors(path, in.gt, in.assoc);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(s.path + ": " + e.what());
    }
    if (!s.map.empty()) {
        if (!in.gtMap)
            throw std::runtime_error("--run " + s.label + ": a map needs --gt-map");
        map = loadMap(s.map, s.format.value_or(in.mapFormat), in.frame);
        r.map = computeMapErrors(map, *in.gtMap);
        if (in.rawlog) addPassedOver(*r.map, map, *in.gtMap, in.gt, *in.rawlog);
    }
    return r;
}
}  // namespace

std::vector<TEvalResult> compareRuns(const std::vector<TRunSpec>& runs,
                                     const TCompareInput& in, TMapFigure& fig) {
    std::vector<TEvalResult> rows;
    fig.gtPath = in.gt;
    if (in.gtMap) fig.gtMap = *in.gtMap;
    if (in.rawlog && in.deadReckoningRow && !in.rawlog->odometry.empty()) {
        TEvalResult r;
        r.label = "odometry";
        const auto dr = deadReckoning(in.rawlog->odometry, in.rawlog->startPose, in.gt);
        r.robot = computeRobotErrors(dr, in.gt, in.assoc);
        fig.odomPath = dr;
        rows.push_back(r);
    }
    for (size_t i = 0; i < runs.size(); i++) {
        TPlotPath p;
        rfir::common::TMapFile map;
        rows.push_back(scoreRun(runs[i], in, p.path, map));
        p.label = runs[i].label;
        p.color = runColor(i);
        fig.extraPaths.push_back(p);
        if (!map.empty()) {
            fig.estMap = map;
            fig.estMapLabel = runs[i].label;
        }
    }
    return rows;
}

namespace {
void plotErrorsOf(const std::string& png, const std::vector<const TEvalResult*>& rows,
                  const std::string& title) {
    const mrpt::img::TColor grey(130, 130, 130);
    TLinePlot p;
    p.title = title + ": robot position error";
    p.xLabel = "time [s]";
    p.yLabel = "dr [mm]";
    size_t k = 0;
    for (const TEvalResult* row : rows) {
        const TEvalResult& r = *row;
        if (r.robot) {
            p.series.push_back(errorVsTime(r.label, r.robot->perPose));
            p.series.back().color = r.label == "odometry" ? grey : runColor(k++);
        }
        if (r.odometry) {
            p.series.push_back(errorVsTime(r.label + " odometry", r.odometry->perPose));
            p.series.back().color = grey;
        }
    }
    if (p.series.empty()) throw std::invalid_argument("error plot: no robot path scored");
    plotLines(png, p);
}
}  // namespace

void plotErrorsOverTime(const std::string& png, const std::vector<TEvalResult>& rows,
                        const std::string& title) {
    std::vector<const TEvalResult*> ptrs;
    for (const auto& r : rows) ptrs.push_back(&r);
    plotErrorsOf(png, ptrs, title);
}

void plotErrorsOverTime(const std::string& png, const TEvalResult& row,
                        const std::string& title) {
    plotErrorsOf(png, {&row}, title);
}

std::string toJsonRuns(const std::vector<TEvalResult>& rows) {
    rfir::common::TJson runs = rfir::common::TJson::array();
    for (const auto& r : rows) runs.push_back(toJsonValue(r));
    rfir::common::TJson j;
    j["runs"] = runs;
    return rfir::common::dumpJson(j);
}

}  // namespace rfir::eval
