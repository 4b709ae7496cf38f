/* rfir: several runs on one data set scored side by side (rfir-eval --run):
 * one table, one JSON line, one figure with every path and the truth. */
#pragma once

#include <rfir/eval/input_formats.h>
#include <rfir/eval/metrics.h>
#include <rfir/eval/plot.h>
#include <rfir/eval/report.h>

#include <optional>
#include <string>
#include <vector>

namespace rfir::eval {
/** One run to compare: `LABEL=[mrpt:]PATH[,MAP]`. */
struct TRunSpec {
    std::string label, path, map;
    /** "mrpt:": the path and map are an MRPT app's; none: rfir-eval's
     * --path-format and --map-format. */
    std::optional<InputFormat> format;
};

/** Parses `LABEL=[mrpt:]PATH[,MAP]`; throws rfir::common::CUsageError naming
 * the text. */
TRunSpec parseRunSpec(const std::string& s);

/** Fills m.passedOver from the rawlog's sensor geometry; false when the rawlog
 * declares no sensor for m's kind (no count). */
bool addPassedOver(TMapErrors& m, const rfir::common::TMapFile& est,
                   const rfir::common::TMapFile& gt, const rfir::common::TPath2D& gtPath,
                   const TRawlogInfo& info);

struct TCompareInput {
    rfir::common::TPath2D gt;
    std::optional<rfir::common::TMapFile> gtMap;
    std::optional<TRawlogInfo> rawlog;  //!< dead-reckoning row, passed-over counts
    bool deadReckoningRow = true;
    Association assoc = Association::AtEstimateTimes;
    /** The runs' formats unless a run gives its own, and what puts MRPT's
     * outputs in the world frame. */
    InputFormat pathFormat = InputFormat::Rfir, mapFormat = InputFormat::Rfir;
    TMrptFrame frame;
};

/** Scores every run (files read here; errors name the file) and, first, the
 * dead reckoning as a row "odometry" when the rawlog has odometry. Adds the
 * truth, the odometry and every run's path to `fig` (a colour per run), and
 * the map of the last run that has one. */
std::vector<TEvalResult> compareRuns(const std::vector<TRunSpec>& runs,
                                     const TCompareInput& in, TMapFigure& fig);

/** The robot's position error over time of every row (and of each row's
 * `odometry`, grey), as a PNG: rfir-eval --error-plot, rfir-slam's
 * error_time.png. Rows named "odometry" are grey too; the others take
 * the colours compareRuns gives their paths, in order. */
void plotErrorsOverTime(const std::string& png, const std::vector<TEvalResult>& rows,
                        const std::string& title);
/** The same for one row, without copying it (its per-pose errors). */
void plotErrorsOverTime(const std::string& png, const TEvalResult& row,
                        const std::string& title);

/** {"runs":[toJson(row), ...]} on one line. */
std::string toJsonRuns(const std::vector<TEvalResult>& rows);

}  // namespace rfir::eval
