// evo-like figures (RMSE, SE(2)-aligned errors, relative pose error) checked
// against values worked out by hand, in the library and through rfir-eval.
#include <rfir/common/trajectory_io.h>
#include <rfir/eval/compare.h>
#include <rfir/eval/metrics.h>
#include <rfir/eval/report.h>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "test_tmpdir.h"

using namespace rfir::eval;
using mrpt::poses::CPose2D;
using rfir::common::TPath2D;

namespace {
/** A curved 40-pose path (not a line: the rotation is then observable). */
TPath2D curve() {
    TPath2D p;
    for (int k = 0; k < 40; k++) {
        const double t = 0.25 * k;
        p.push_back({t, CPose2D(2 * std::cos(0.3 * t), std::sin(0.5 * t), 0.2 * t - 1)});
    }
    return p;
}

/** The path moved rigidly: rotated by th about the origin, then shifted. */
TPath2D moved(const TPath2D& p, double th, double ox, double oy) {
    TPath2D o;
    const double c = std::cos(th), s = std::sin(th);
    for (const auto& q : p)
        o.push_back(
            {q.t, CPose2D(c * q.pose.x() - s * q.pose.y() + ox,
                          s * q.pose.x() + c * q.pose.y() + oy, q.pose.phi() + th)});
    return o;
}

/** The number after "key": in the object that follows `within` in j. */
double jsonValue(const std::string& j, const std::string& within,
                 const std::string& key) {
    const auto a = j.find(within);
    EXPECT_NE(a, std::string::npos) << within << " not in " << j;
    const auto b = j.find("\"" + key + "\":", a == std::string::npos ? 0 : a);
    EXPECT_NE(b, std::string::npos) << key << " not in " << j;
    return std::stod(j.substr(b + key.size() + 3));
}
}  // namespace

TEST(EvalTrajectory, RmseAndAlignmentOfARigidlyMovedPath) {
    const TPath2D gt = curve();
    const TPath2D est = moved(gt, 0.3, 0.5, -0.2);
    const auto r = computeRobotErrors(est, gt);
    // Unaligned RMSE, by hand: sqrt(mean |p_est - p_gt|^2); heading off by 0.3.
    double s2 = 0;
    for (size_t k = 0; k < gt.size(); k++)
        s2 += std::pow(est[k].pose.x() - gt[k].pose.x(), 2) +
              std::pow(est[k].pose.y() - gt[k].pose.y(), 2);
    EXPECT_NEAR(r.stats.rmse_dist, std::sqrt(s2 / gt.size()), 1e-12);
    EXPECT_GT(r.stats.rmse_dist, 0.3);  // a large error before alignment
    EXPECT_NEAR(r.stats.rmse_dtheta, 0.3, 1e-9);
    // The alignment undoes the motion exactly: rotation -0.3, and the offset
    // that brings R(-0.3) (0.5, -0.2) back.
    EXPECT_NEAR(r.alignment.theta, -0.3, 1e-9);
    const double c = std::cos(-0.3), s = std::sin(-0.3);
    EXPECT_NEAR(r.alignment.tx, -(c * 0.5 - s * -0.2), 1e-9);
    EXPECT_NEAR(r.alignment.ty, -(s * 0.5 + c * -0.2), 1e-9);
    EXPECT_NEAR(r.alignment.scale, 1, 1e-12);
    EXPECT_LT(r.aligned.max_dist, 1e-9);
    EXPECT_LT(r.aligned.max_dtheta, 1e-9);
    EXPECT_EQ(r.aligned.count, gt.size());
    // Relative motion is unchanged by a rigid motion.
    EXPECT_GT(r.rpePerMetre.pairs, 5u);
    EXPECT_GT(r.rpePerSecond.pairs, 30u);
    EXPECT_LT(r.rpePerMetre.max_trans, 1e-9);
    EXPECT_LT(r.rpePerSecond.max_rot, 1e-9);
}

TEST(EvalTrajectory, AlignmentWithScale) {
    const TPath2D gt = curve();
    std::vector<TPosePair> pairs;
    for (const auto& g : gt)
        pairs.push_back(
            {g.t, CPose2D(2 * g.pose.x() + 1, 2 * g.pose.y(), g.pose.phi()), g.pose});
    const auto a = alignPositions(pairs, true);
    EXPECT_NEAR(a.scale, 0.5, 1e-9);
    EXPECT_NEAR(a.theta, 0, 1e-9);
    for (const auto& p : pairs) EXPECT_NEAR(a.apply(p.est).distanceTo(p.gt), 0, 1e-9);
    // Without scale the best rigid fit leaves an error.
    const auto b = alignPositions(pairs, false);
    EXPECT_NEAR(b.scale, 1, 1e-12);
    EXPECT_GT(b.apply(pairs.front().est).distanceTo(pairs.front().gt), 0.1);
}

TEST(EvalTrajectory, RelativePoseErrorByHand) {
    // Truth: along x, 0.5 m and 1 s apart. Estimate: x2 = 1.1, heading 0.1
    // at pose 3, y4 = 0.05.
    std::vector<TPosePair> p;
    const double ex[] = {0, 0.5, 1.1, 1.5, 2}, ey[] = {0, 0, 0, 0, 0.05},
                 eph[] = {0, 0, 0, 0.1, 0};
    for (int k = 0; k < 5; k++)
        p.push_back({double(k), CPose2D(ex[k], ey[k], eph[k]), CPose2D(0.5 * k, 0, 0)});
    // Per metre: pairs (0,2), (1,3), (2,4); (3, .) has 0.5 m left.
    //  (0,2): est step (1.1, 0, 0) against (1, 0, 0): 0.1 m, 0 rad
    //  (1,3): (1.0, 0, 0.1): 0 m, 0.1 rad
    //  (2,4): (0.9, 0.05, 0): (-0.1, 0.05): sqrt(0.0125) m, 0 rad
    const auto m = relativePoseError(p, 1.0, RpeUnit::Metres);
    ASSERT_EQ(m.pairs, 3u);
    const double t3 = std::sqrt(0.0125);
    EXPECT_NEAR(m.mean_trans, (0.1 + 0 + t3) / 3, 1e-12);
    EXPECT_NEAR(m.rmse_trans, std::sqrt((0.01 + 0.0125) / 3), 1e-12);
    EXPECT_NEAR(m.max_trans, t3, 1e-12);
    EXPECT_NEAR(m.mean_rot, 0.1 / 3, 1e-12);
    EXPECT_NEAR(m.rmse_rot, std::sqrt(0.01 / 3), 1e-12);
    EXPECT_NEAR(m.max_rot, 0.1, 1e-12);
    // Per second: pairs (0,1) .. (3,4); true step (0.5, 0, 0) each.
    //  (0,1): 0; (1,2): (0.1, 0), 0; (2,3): step (0.4, 0, 0.1): (-0.1, 0), 0.1;
    //  (3,4): step = R(-0.1) (0.5, 0.05), heading -0.1, minus (0.5, 0).
    const double c = std::cos(0.1), s = std::sin(0.1);
    const double t4 = std::hypot(c * 0.5 + s * 0.05 - 0.5, -s * 0.5 + c * 0.05);
    const auto sec = relativePoseError(p, 1.0, RpeUnit::Seconds);
    ASSERT_EQ(sec.pairs, 4u);
    EXPECT_NEAR(sec.mean_trans, (0 + 0.1 + 0.1 + t4) / 4, 1e-12);
    EXPECT_NEAR(sec.rmse_trans, std::sqrt((0.01 + 0.01 + t4 * t4) / 4), 1e-12);
    EXPECT_NEAR(sec.mean_rot, (0.1 + 0.1) / 4, 1e-12);
    EXPECT_NEAR(sec.max_rot, 0.1, 1e-12);
    // Too long a step: no pair, not a crash.
    EXPECT_EQ(relativePoseError(p, 10.0, RpeUnit::Metres).pairs, 0u);
}

TEST(EvalTrajectory, TableAndJsonCarryTheFigures) {
    TEvalResult r;
    r.robot = computeRobotErrors(moved(curve(), 0.3, 0.5, -0.2), curve());
    const std::string j = toJson(r);
    for (const char* k : {"\"rmse_dist\":", "\"rmse_dtheta\":", "\"aligned\":{\"theta\":",
                          "\"rpe_per_m\":{\"delta\":1,", "\"rpe_per_s\":{\"delta\":1,"})
        EXPECT_NE(j.find(k), std::string::npos) << k << " not in " << j;
    EXPECT_NEAR(jsonValue(j, "\"robot\":", "rmse_dist"), r.robot->stats.rmse_dist, 1e-8);
    EXPECT_NEAR(jsonValue(j, "\"aligned\":", "theta"), -0.3, 1e-8);
    const std::string t = formatErrorTable({r});
    EXPECT_NE(t.find("al. rmse dr"), std::string::npos) << t;
    EXPECT_NE(t.find("RPE/m t"), std::string::npos) << t;
    TTableOptions o;
    o.showEvo = false;
    EXPECT_EQ(formatErrorTable({r}, o).find("RPE/m"), std::string::npos);
}

namespace {
int runEval(const std::string& args, const rfir_test::TmpDir& d, std::string& out) {
    const std::string cmd = std::string(RFIR_BINARY_DIR) + "/bin/rfir-eval " + args +
                            " > " + (d / "out") + " 2> " + (d / "err");
    const int st = std::system(cmd.c_str());
    std::ifstream f(d / "out");
    std::stringstream ss;
    ss << f.rdbuf();
    out = ss.str();
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}
}  // namespace

TEST(EvalTrajectory, RfirEvalMatchesTheHandComputation) {
    rfir_test::TmpDir d;
    const TPath2D gt = curve(), est = moved(gt, 0.3, 0.5, -0.2);
    rfir::common::saveTUM(d / "gt.tum", gt);
    rfir::common::saveTUM(d / "est.tum", est);
    std::string out;
    ASSERT_EQ(
        runEval("--gt-path " + d / "gt.tum" + " --path " + d / "est.tum" + " --json-only",
                d, out),
        0);
    double s2 = 0;
    for (size_t k = 0; k < gt.size(); k++)
        s2 += std::pow(est[k].pose.distanceTo(gt[k].pose), 2);
    // TUM files keep 6 decimals (and a quaternion): 1e-5 m.
    EXPECT_NEAR(jsonValue(out, "\"robot\":", "rmse_dist"), std::sqrt(s2 / gt.size()),
                1e-5);
    EXPECT_NEAR(jsonValue(out, "\"aligned\":", "rmse_dist"), 0, 1e-5);
    EXPECT_NEAR(jsonValue(out, "\"aligned\":", "theta"), -0.3, 1e-5);
    EXPECT_NEAR(jsonValue(out, "\"rpe_per_m\":", "rmse_trans"), 0, 1e-5);

    // Several runs side by side: one JSON line with a row per run.
    ASSERT_EQ(runEval("--gt-path " + d / "gt.tum" + " --run A=" + d / "est.tum" +
                          " --run B=" + d / "gt.tum" + " --plot " + d / "all.png" +
                          " --error-plot " + d / "err.png",
                      d, out),
              0);
    EXPECT_NE(out.find("{\"runs\":[{\"label\":\"A\""), std::string::npos) << out;
    EXPECT_NE(out.find("{\"label\":\"B\""), std::string::npos) << out;
    EXPECT_NEAR(jsonValue(out, "{\"label\":\"B\"", "rmse_dist"), 0, 1e-5);
    EXPECT_TRUE(std::ifstream(d / "all.png").good());
    EXPECT_TRUE(std::ifstream(d / "err.png").good());
    // A malformed --run is refused before any output.
    EXPECT_NE(
        runEval("--gt-path " + d / "gt.tum" + " --run A --plot " + d / "x.png", d, out),
        0);
    EXPECT_FALSE(std::ifstream(d / "x.png").good());
    EXPECT_NE(runEval("--gt-path " + d / "gt.tum" + " --run A=" + d / "est.tum" +
                          " --path " + d / "est.tum",
                      d, out),
              0);
}
