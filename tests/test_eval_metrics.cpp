// Evaluation metrics computed by hand on tiny synthetic paths and maps.
#include <rfir/eval/metrics.h>
#include <rfir/eval/report.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace rfir::eval;
using mrpt::poses::CPose2D;
using rfir::common::TMapEntry;
using rfir::common::TMapFile;
using rfir::common::TPath2D;

namespace {
TMapEntry tag(const std::string& id, double x, double y,
              TMapEntry::Kind k = TMapEntry::Kind::Tag) {
    TMapEntry e;
    e.kind = k;
    e.id = id;
    e.x = x;
    e.y = y;
    return e;
}
}  // namespace

TEST(EvalMetrics, WrapToPi) {
    EXPECT_NEAR(wrapToPi(3 * M_PI / 2), -M_PI / 2, 1e-12);
    EXPECT_NEAR(wrapToPi(-M_PI), M_PI, 1e-12);  // (-pi, pi]
    EXPECT_NEAR(wrapToPi(M_PI), M_PI, 1e-12);
    EXPECT_NEAR(wrapToPi(6.2), 6.2 - 2 * M_PI, 1e-12);
}

TEST(EvalMetrics, InterpolationLinearAndAcrossPi) {
    const TPath2D gt{{0, CPose2D(0, 0, 0)},
                     {1, CPose2D(1, 2, 1.0)},
                     {2, CPose2D(1, 2, 3.0)},
                     {3, CPose2D(1, 2, -3.0)}};
    auto p = interpolatePose(gt, 0.25);
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->x(), 0.25, 1e-12);
    EXPECT_NEAR(p->y(), 0.5, 1e-12);
    EXPECT_NEAR(p->phi(), 0.25, 1e-12);
    // Exact stamps give the stored pose.
    p = interpolatePose(gt, 2.0);
    EXPECT_NEAR(p->phi(), 3.0, 1e-12);
    // 3.0 -> -3.0 is a 0.283 rad turn through pi, not -6 rad through 0.
    p = interpolatePose(gt, 2.5);
    EXPECT_NEAR(std::abs(p->phi()), M_PI, 1e-9);
    p = interpolatePose(gt, 2.25);
    EXPECT_NEAR(p->phi(), 3.0 + 0.25 * (2 * M_PI - 6.0), 1e-9);
    EXPECT_FALSE(interpolatePose(gt, -0.1));
    EXPECT_FALSE(interpolatePose(gt, 3.1));
    EXPECT_TRUE(interpolatePose(gt, 3.0 + 1e-7));  // within the stamp tolerance
}

TEST(EvalMetrics, RobotErrorsByHand) {
    const TPath2D gt{{0, CPose2D(0, 0, 3.1)}, {2, CPose2D(2, 0, 3.1)}};
    // Errors: t=0 (0.03, -0.04), dtheta = -3.1 - 3.1 wrapped = 2 pi - 6.2 = 0.0832;
    // t=1 (gt 1,0): (-0.01, 0.0), dtheta -0.1; t=9: outside, skipped.
    const TPath2D est{{0, CPose2D(0.03, -0.04, -3.1)},
                      {1, CPose2D(0.99, 0, 3.0)},
                      {9, CPose2D(5, 5, 0)}};
    const auto r = computeRobotErrors(est, gt);
    ASSERT_EQ(r.perPose.size(), 2u);
    EXPECT_EQ(r.skipped, 1u);
    const double dth0 = 2 * M_PI - 6.2;
    EXPECT_NEAR(r.perPose[0].dtheta, dth0, 1e-12);
    EXPECT_NEAR(r.perPose[0].dist, 0.05, 1e-12);
    EXPECT_NEAR(r.perPose[1].dx, -0.01, 1e-12);
    EXPECT_NEAR(r.perPose[1].dtheta, -0.1, 1e-12);
    EXPECT_EQ(r.stats.count, 2u);
    EXPECT_NEAR(r.stats.mean_dx, 0.02, 1e-12);
    EXPECT_NEAR(r.stats.mean_dy, 0.02, 1e-12);
    EXPECT_NEAR(r.stats.mean_dtheta, 0.5 * (dth0 + 0.1), 1e-12);
    EXPECT_NEAR(r.stats.mean_dist, 0.03, 1e-12);
    EXPECT_NEAR(r.stats.max_dx, 0.03, 1e-12);
    EXPECT_NEAR(r.stats.max_dy, 0.04, 1e-12);
    EXPECT_NEAR(r.stats.max_dtheta, 0.1, 1e-12);
    EXPECT_NEAR(r.stats.max_dist, 0.05, 1e-12);
}

TEST(EvalMetrics, RobotErrorsAtTruthTimes) {
    // Sparse truth (two marked spots) against a dense estimate.
    const TPath2D est{
        {0, CPose2D(0, 0, 0)}, {1, CPose2D(1, 0.1, 0.2)}, {2, CPose2D(2, 0, 0)}};
    const TPath2D spots{
        {0.5, CPose2D(0.5, 0, 0)}, {1.5, CPose2D(1.5, 0, -0.1)}, {7, CPose2D(0, 0, 0)}};
    const auto r = computeRobotErrors(est, spots, Association::AtTruthTimes);
    ASSERT_EQ(r.perPose.size(), 2u);
    EXPECT_EQ(r.skipped, 1u);  // t = 7 is after the estimate ends
    EXPECT_NEAR(r.perPose[0].t, 0.5, 1e-12);
    EXPECT_NEAR(r.perPose[0].dy, 0.05, 1e-12);     // estimate minus truth
    EXPECT_NEAR(r.perPose[1].dtheta, 0.2, 1e-12);  // est 0.1 vs truth -0.1
    EXPECT_NEAR(r.stats.mean_dist, 0.05, 1e-12);
    // The default pairs every estimated pose with the (interpolated) spots.
    EXPECT_EQ(computeRobotErrors(est, spots).perPose.size(), 2u);
    const TPath2D unsorted{{1, CPose2D()}, {0, CPose2D()}};
    EXPECT_THROW(computeRobotErrors(unsorted, spots, Association::AtTruthTimes),
                 std::runtime_error);
}

TEST(EvalMetrics, RobotErrorsRejectBadPaths) {
    const TPath2D gt{{0, CPose2D(0, 0, 0)}, {1, CPose2D(1, 0, 0)}};
    EXPECT_THROW(computeRobotErrors({}, gt), std::runtime_error);
    EXPECT_THROW(computeRobotErrors({{5, CPose2D()}}, gt), std::runtime_error);
    const TPath2D unsorted{{1, CPose2D()}, {0.5, CPose2D()}};
    try {
        computeRobotErrors({{0.7, CPose2D()}}, unsorted);
        FAIL() << "unsorted ground truth accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("non-decreasing time (pose 2"),
                  std::string::npos)
            << e.what();
    }
}

TEST(EvalMetrics, MapErrorsByHand) {
    const TMapFile gt{tag("a", 0, 0), tag("b", 1, 1), tag("c", 2, 2),
                      tag("E", 5, 5, TMapEntry::Kind::Emitter)};
    const TMapFile est{tag("a", 0.03, 0.04), tag("b", 0.9, 1.0), tag("zz", 7, 7)};
    const auto m = computeMapErrors(est, gt);
    EXPECT_EQ(m.kind, TMapEntry::Kind::Tag);
    EXPECT_EQ(m.mapped, 2u);
    EXPECT_EQ(m.total, 3u);  // emitters are not tags
    ASSERT_EQ(m.unknownIds.size(), 1u);
    EXPECT_EQ(m.unknownIds[0], "zz");
    EXPECT_NEAR(m.stats.mean_dx, 0.065, 1e-12);
    EXPECT_NEAR(m.stats.mean_dy, 0.02, 1e-12);
    EXPECT_NEAR(m.stats.mean_dist, 0.075, 1e-12);
    EXPECT_NEAR(m.stats.max_dx, 0.1, 1e-12);
    EXPECT_NEAR(m.stats.max_dist, 0.1, 1e-12);
    EXPECT_FALSE(m.passedOver);
}

TEST(EvalMetrics, MapKindInference) {
    const TMapFile gt{tag("a", 0, 0), tag("a", 1, 0, TMapEntry::Kind::Landmark)};
    const TMapFile lm{tag("a", 1.5, 0, TMapEntry::Kind::Landmark)};
    const auto m = computeMapErrors(lm, gt);
    EXPECT_EQ(m.kind, TMapEntry::Kind::Landmark);
    EXPECT_NEAR(m.stats.mean_dist, 0.5, 1e-12);
    const TMapFile mixed{tag("a", 0, 0), tag("a", 1, 0, TMapEntry::Kind::Landmark)};
    EXPECT_THROW(computeMapErrors(mixed, gt), std::runtime_error);
    EXPECT_EQ(computeMapErrors(mixed, gt, TMapEntry::Kind::Tag).mapped, 1u);
}

TEST(EvalMetrics, TagsPassedOverStraightLine) {
    // One 60 mm reader at the robot centre; only the two end poses are given.
    const std::vector<rfir::obs::TRFIDReader> readers{{"R", 0, 0, 0.03, 0.03}};
    const TPath2D path{{0, CPose2D(0, 0, 0)}, {1, CPose2D(0.4, 0, 0)}};
    const TMapFile gt{tag("in", 0.2, 0.02),   tag("in2", 0.1, -0.029),
                      tag("off", 0.2, 0.04),  tag("end", 0.42, 0),
                      tag("beyond", 0.44, 0), tag("behind", -0.04, 0)};
    const auto s = tagsPassedOver(gt, path, readers);
    EXPECT_EQ(s, (std::set<std::string>{"in", "in2", "end"}));
}

TEST(EvalMetrics, TagsPassedOverTurnInPlaceAndJump) {
    // A reader 0.1 m ahead sweeps a quarter circle while the robot turns.
    const std::vector<rfir::obs::TRFIDReader> readers{{"R", 0.1, 0, 0.03, 0.03}};
    const TPath2D turn{{0, CPose2D(0, 0, 0)}, {1, CPose2D(0, 0, M_PI / 2)}};
    const double c = 0.1 * std::cos(M_PI / 4);
    const TMapFile gt{tag("mid", c, c), tag("out", 0.14, 0.14)};
    EXPECT_EQ(tagsPassedOver(gt, turn, readers), (std::set<std::string>{"mid"}));
    // A 2 m jump in one step (kidnapping) is not interpolated.
    const TPath2D jump{{0, CPose2D(0, 0, 0)}, {1, CPose2D(2, 0, 0)}};
    const TMapFile line{tag("start", 0.1, 0), tag("mid", 1.1, 0), tag("end", 2.1, 0)};
    EXPECT_EQ(tagsPassedOver(line, jump, readers),
              (std::set<std::string>{"start", "end"}));
    EXPECT_THROW(tagsPassedOver(line, jump, {}), std::runtime_error);
}

TEST(EvalMetrics, LandmarksInView) {
    rfir::obs::TRBSensor s;  // at the robot centre, 0.5 m, 120 deg
    const TPath2D path{{0, CPose2D(0, 0, 0)}};
    const TMapFile gt{tag("a", 0.4, 0.1, TMapEntry::Kind::Landmark),
                      tag("far", 0.4, 0.4, TMapEntry::Kind::Landmark),
                      tag("b", 0.2, 0.3, TMapEntry::Kind::Landmark),
                      tag("wide", 0.1, 0.3, TMapEntry::Kind::Landmark),
                      tag("behind", -0.2, 0, TMapEntry::Kind::Landmark),
                      tag("t", 0.2, 0)};
    EXPECT_EQ(landmarksInView(gt, path, s), (std::set<std::string>{"a", "b"}));
    TMapErrors m;
    m.kind = TMapEntry::Kind::Landmark;
    setPassedOver(m, {"a", "b"}, {tag("a", 0, 0, TMapEntry::Kind::Landmark)});
    EXPECT_EQ(*m.passedOver, 2u);
    EXPECT_EQ(*m.mappedOfPassedOver, 1u);
}

TEST(EvalMetrics, DeadReckoningAlignedAtStart) {
    // Odometry frame rotated: starts at (5, 5, pi/2) and drives 1 m forward.
    const TPath2D odo{{0, CPose2D(5, 5, M_PI / 2)}, {1, CPose2D(5, 6, M_PI / 2)}};
    const TPath2D gt{{0, CPose2D(1, 2, 0)}, {1, CPose2D(2, 2, 0)}};
    const auto dr = alignOdometryAtStart(odo, gt);
    ASSERT_EQ(dr.size(), 2u);
    EXPECT_NEAR(dr[0].pose.x(), 1, 1e-12);
    EXPECT_NEAR(dr[1].pose.x(), 2, 1e-12);
    EXPECT_NEAR(dr[1].pose.y(), 2, 1e-12);
    EXPECT_NEAR(dr[1].pose.phi(), 0, 1e-12);
    EXPECT_THROW(alignOdometryAtStart({{7, CPose2D()}}, gt), std::runtime_error);
    // From a known start pose instead: same path.
    const auto dr2 = alignOdometryAt(odo, CPose2D(1, 2, 0));
    ASSERT_EQ(dr2.size(), 2u);
    EXPECT_NEAR(dr2[1].pose.x(), 2, 1e-12);
    EXPECT_NEAR(dr2[1].pose.y(), 2, 1e-12);
    // deadReckoning: from the start when known (even where the truth differs),
    // else from the truth.
    EXPECT_NEAR(deadReckoning(odo, CPose2D(0, 0, 0), gt)[1].pose.x(), 1, 1e-12);
    EXPECT_NEAR(deadReckoning(odo, std::nullopt, gt)[1].pose.x(), 2, 1e-12);
}

TEST(EvalReport, JsonKeysAndTable) {
    TEvalResult r;
    r.label = "PF \"x\"";
    const TPath2D gt{{0, CPose2D(0, 0, 0)}, {1, CPose2D(1, 0, 0)}};
    r.robot = computeRobotErrors({{0, CPose2D(0.02, 0, 0)}}, gt);
    r.odometry = r.robot;
    r.map = computeMapErrors({tag("a", 0.01, 0)}, {tag("a", 0, 0), tag("b", 1, 1)});
    std::string j = toJson(r);
    EXPECT_EQ(j.find('\n'), std::string::npos);
    for (const char* k :
         {"\"label\":\"PF \\\"x\\\"\"",
          "\"robot\":{\"poses\":1,\"skipped\":0,\"mean_dx\":0.02", "\"mean_dy\":0",
          "\"mean_dtheta\":0", "\"mean_dist\":0.02", "\"max_dx\":0.02",
          "\"max_dy\":", "\"max_dtheta\":", "\"max_dist\":", "\"dead_reckoning\":{",
          "\"tags\":{\"count\":1,\"mean_dx\":0.01", "\"tags_mapped\":1",
          "\"tags_total\":2", "\"tags_unknown_ids\":0", "\"tags_passed_over\":null",
          "\"tags_mapped_of_passed_over\":null"})
        EXPECT_NE(j.find(k), std::string::npos) << k << " not in " << j;
    r.map->passedOver = 2;
    r.map->mappedOfPassedOver = 1;
    j = toJson(r);
    EXPECT_NE(j.find("\"tags_passed_over\":2"), std::string::npos) << j;
    const std::string t = formatErrorTable({r});
    EXPECT_NE(t.find("dr [mm]"), std::string::npos) << t;
    EXPECT_NE(t.find("20.0"), std::string::npos) << t;  // 0.02 m in mm
    EXPECT_NE(t.find("odometry"), std::string::npos) << t;
    EXPECT_NE(t.find("passed over"), std::string::npos) << t;
    r.map->kind = TMapEntry::Kind::Landmark;
    EXPECT_NE(toJson(r).find("\"landmarks_mapped\":1"), std::string::npos);
}

TEST(EvalMetrics, SegmentStatsByHand) {
    // Errors 10, 20, 30, 40, 50 mm at t = 0, 1, 2, 3, 4; three windows over
    // [0, 4.5): [0, 1.5) holds t = 0, 1; [1.5, 3) holds t = 2; [3, 4.5] the rest.
    std::vector<TPoseError> e;
    for (int k = 0; k < 5; k++)
        e.push_back({double(k), 0, 0.01 * (k + 1), 0, 0.01 * (k + 1)});
    auto s = segmentStats(e, 0, 4.5, 3);
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].count, 2u);
    EXPECT_NEAR(s[0].mean_dist, 0.015, 1e-12);
    EXPECT_NEAR(s[0].max_dy, 0.02, 1e-12);
    EXPECT_EQ(s[1].count, 1u);
    EXPECT_NEAR(s[1].mean_dist, 0.03, 1e-12);
    EXPECT_EQ(s[2].count, 2u);
    EXPECT_NEAR(s[2].mean_dist, 0.045, 1e-12);
    // The end time belongs to the last window; times outside are clamped.
    s = segmentStats(e, 1, 4, 3);
    EXPECT_EQ(s[0].count, 2u);  // t = 0 (clamped) and t = 1
    EXPECT_EQ(s[2].count, 2u);  // t = 3 and t = 4 (the closed end)
    // A window with no pose has count 0.
    s = segmentStats({e[0]}, 0, 4, 2);
    EXPECT_EQ(s[1].count, 0u);
    EXPECT_THROW(segmentStats(e, 0, 4, 0), std::invalid_argument);
    EXPECT_THROW(segmentStats(e, 4, 4, 2), std::invalid_argument);
}

TEST(EvalReport, SegmentsInTableAndJson) {
    TEvalResult r;
    r.label = "PF";
    const TPath2D gt{{0, CPose2D(0, 0, 0)}, {2, CPose2D(2, 0, 0)}};
    r.robot =
        computeRobotErrors({{0, CPose2D(0, 0.01, 0)}, {2, CPose2D(2, 0.03, 0)}}, gt);
    r.odometry = r.robot;
    r.segmentBounds = {0, 1, 2};
    r.robotSegments = segmentStats(r.robot->perPose, 0, 2, 2);
    r.odometrySegments = {r.robotSegments[0], TErrorStats{}};
    const std::string j = toJson(r);
    EXPECT_NE(j.find("\"segments\":{\"t\":[0,1,2],\"robot_mean_dist\":[0.01,0.03],"
                     "\"dead_reckoning_mean_dist\":[0.01,null]}"),
              std::string::npos)
        << j;
    const std::string t = formatErrorTable({r});
    EXPECT_NE(t.find("0-1 s  1-2 s"), std::string::npos) << t;
    EXPECT_NE(t.find("PF            10.0   30.0"), std::string::npos) << t;
    EXPECT_NE(t.find("PF odometry   10.0      -"), std::string::npos) << t;
    // Without windows: no table, no key.
    r.segmentBounds.clear();
    EXPECT_EQ(toJson(r).find("segments"), std::string::npos);
    EXPECT_EQ(formatErrorTable({r}).find("time window"), std::string::npos);
}
