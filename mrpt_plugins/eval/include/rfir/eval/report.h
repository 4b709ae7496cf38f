/* rfir: error tables in the papers' layout (mm and rad) and one-line JSON. */
#pragma once

#include <rfir/eval/metrics.h>

#include <optional>
#include <string>
#include <vector>

namespace rfir::eval {
/** The evaluation of one run (one method on one data set). */
struct TEvalResult {
    std::string label = "estimate";  //!< method name, first table column
    std::optional<TRobotErrors> robot;
    /** Dead reckoning on the same data (odometry aligned at the start pose). */
    std::optional<TRobotErrors> odometry;
    std::optional<TMapErrors> map;
    /** Time windows (rfir-eval --segments): n + 1 bounds [s], and the mean
     * and max per window of the robot's and of dead reckoning's errors
     * (segmentStats); empty when not asked for. */
    std::vector<double> segmentBounds;
    std::vector<TErrorStats> robotSegments, odometrySegments;
};

struct TTableOptions {
    bool showMax = true;  //!< add the "max" columns beside the "mean" ones
    /** Add the table of evo's figures (RMSE, aligned errors, RPE). */
    bool showEvo = true;
};

/** Plain-text tables, one row per result: robot x, y [mm], theta [rad], dr [mm]
 * (mean, then max), then map x, y, dt [mm] with mapped / passed-over / total
 * counts. A result's `odometry` adds a row "<label> odometry". Then (showEvo)
 * RMSE, SE(2)-aligned errors and RPE of the same rows. Time windows
 * add a table of the mean distance error per window after the robot's.
 * Sections with no data in any row are left out. */
std::string formatErrorTable(const std::vector<TEvalResult>& rows,
                             const TTableOptions& opts = {});

/** One JSON object on one line (no newline), SI units (m, rad). Keys:
 * "label"; "robot": {"poses","skipped","mean_dx","mean_dy","mean_dtheta",
 * "mean_dist","max_dx","max_dy","max_dtheta","max_dist","rmse_dist",
 * "rmse_dtheta", "aligned": {"theta","tx","ty" (the SE(2) alignment),
 * "mean_dist","rmse_dist","max_dist","mean_dtheta","rmse_dtheta",
 * "max_dtheta"}, "rpe_per_m" and "rpe_per_s": {"delta","pairs","mean_trans",
 * "rmse_trans","max_trans","mean_rot","rmse_rot","max_rot"}};
 * "dead_reckoning": same keys; for a map of kind K with plural P ("tags",
 * "landmarks", "emitters"): P: {"count","mean_dx","mean_dy","mean_dist",
 * "max_dx","max_dy","max_dist","rmse_dist"}, "P_mapped", "P_total", "P_unknown_ids",
 * "P_passed_over" and "P_mapped_of_passed_over" (null when unknown);
 * with time windows, "segments": {"t": bounds, "robot_mean_dist": [...],
 * "dead_reckoning_mean_dist": [...]} (null for a window with no pose).
 * Absent parts are omitted. */
std::string toJson(const TEvalResult& r);

}  // namespace rfir::eval
