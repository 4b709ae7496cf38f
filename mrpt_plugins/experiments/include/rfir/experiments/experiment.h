/* rfir-experiments: the experiment rows (the tables and figures of the thesis
 * and the PS-SLAM paper, docs/bibliography.md [1] [3]) as data: which
 * simulated setup, which methods, which sweep points, and the numbers the
 * papers report for it. */
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace rfir::experiments {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/** One method of a row: a stock INI (config_ini/slam_<method>.ini) plus
 * "section.key=value" edits. */
struct TMethodSpec {
    std::string label;   //!< e.g. "PF-SLAM"
    std::string method;  //!< pf | ps | fastslam | odometry
    std::vector<std::string> edits;
};

/** A row of a table of the papers (mm, rad); NaN where they give no number. */
struct TPaperNumbers {
    std::string label;  //!< method as in our rows
    double x = kNaN, y = kNaN, theta = kNaN, dr = kNaN;
    double tx = kNaN, ty = kNaN, dt = kNaN;
    std::string note;  //!< e.g. "about", "> 300"
};

/** One simulated data set averaged into a point (e.g. one of the five
 * predefined trajectories): a sim INI and overrides. */
struct TSubRun {
    std::string label;
    std::string simIni;  //!< file name in the config folder
    std::vector<std::string> simOverrides;
};

/** A point of a row: a table row has one; a sweep one per x value. */
struct TPoint {
    std::string label;
    double x = 0;
    std::vector<std::string> simOverrides;  //!< applied after the sub-run's
    std::vector<std::string> slamEdits;     //!< applied to every method
    /** > 0: every [odometry] noise parameter of the sim INI times this. */
    double odometryScale = 0;
};

enum class TRowKind {
    Table,  //!< one point, errors table
    Sweep,  //!< several points, line plots
    Kidnap  //!< one point, error before / after the kidnapping
};

struct TRow {
    std::string id, title, source;
    TRowKind kind = TRowKind::Table;
    std::vector<TSubRun> runs;
    std::vector<TPoint> points;
    std::vector<TMethodSpec> methods;
    std::vector<TPaperNumbers> paperNumbers;
    std::string paperClaim;  //!< what the papers report, in words
    bool figure = false;     //!< path/map figure of the first seed
    std::string xLabel;
    bool logX = false;
    bool plotTime = false;  //!< sweep: also plot the time per update
    unsigned maxSeeds = 0;  //!< > 0: at most this many random seeds (long rows)
};

/** Every row; `quick` trims them (first sub-run, end points of sweeps). */
std::vector<TRow> allRows(bool quick);

}  // namespace rfir::experiments
