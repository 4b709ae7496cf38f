/* The map correction's linear-Gaussian algebra (tag_correlation.h) against
 * the exact Kalman update of a joint robot-tag Gaussian. */
#include <rfir/slam/tag_correlation.h>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <map>
#include <string>

using rfir::slam::CMapCorrection;
using rfir::slam::CTagRobotCorrelation;
using rfir::slam::TPoseMoments;

namespace {
TPoseMoments moments(double x, double y, double phi, const Eigen::Matrix3d& cov) {
    TPoseMoments m;
    m.x = x;
    m.y = y;
    m.phi = phi;
    m.cov = cov;
    return m;
}

Eigen::Matrix3d robotCov() {
    Eigen::Matrix3d P;
    P << 0.04, 0.01, 0.002, 0.01, 0.09, -0.003, 0.002, -0.003, 0.01;
    return P;
}

/** Shifts collected by id. */
struct TShifts {
    std::map<std::string, Eigen::Vector2d> by;
    CTagRobotCorrelation::TShift fn() {
        return [this](const std::string& id, bool, double dx, double dy) {
            by.try_emplace(id, Eigen::Vector2d::Zero()).first->second +=
                Eigen::Vector2d(dx, dy);
        };
    }
};
}  // namespace

// A tag mapped at robot xy + l, where l is known: a correction d of the robot
// at the same place moves the tag by C P^-1 d = J d, the linearised rigid
// motion (d_xy plus the heading correction turning l).
TEST(MapCorrection, ShiftIsTheKalmanUpdateAtTheMappingPose) {
    const Eigen::Matrix3d P = robotCov();
    const auto before = moments(1.0, 2.0, 0.3, P);
    const auto after = moments(1.05, 1.97, 0.31, 0.25 * P);
    CTagRobotCorrelation c(0.001);
    c.add("a", false, 1.5, 2.2, before);  // l = (0.5, 0.2)
    TShifts s;
    EXPECT_EQ(c.correct(before, after, s.fn()), 1u);
    const Eigen::Vector2d expect(0.05 - 0.2 * 0.01, -0.03 + 0.5 * 0.01);
    EXPECT_NEAR(s.by["a"].x(), expect.x(), 1e-12);
    EXPECT_NEAR(s.by["a"].y(), expect.y(), 1e-12);
}

// After a noiseless drive by (dx, dy) the robot's covariance is F P F^T and
// the tag's cross-covariance with it C F^T: the correction moves the tag by
// J F^-1 d, the correction carried back to the mapping pose.
TEST(MapCorrection, MotionSinceTheMappingIsCarriedByItsJacobian) {
    const Eigen::Matrix3d P = robotCov();
    const auto atMap = moments(0.0, 0.0, 0.0, P);
    CTagRobotCorrelation c(0.001);
    c.add("a", false, 0.3, -0.1, atMap);
    const double dx = 2.0, dy = 1.0;
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 2) = -dy;
    F(1, 2) = dx;
    const Eigen::Matrix3d Pn = F * P * F.transpose();
    const auto before = moments(dx, dy, 0.0, Pn);
    const auto after = moments(dx + 0.02, dy - 0.04, 0.015, 0.5 * Pn);
    TShifts s;
    c.correct(before, after, s.fn());
    Eigen::Matrix<double, 2, 3> J;
    J << 1, 0, 0.1, 0, 1, 0.3;
    const Eigen::Vector3d d(0.02, -0.04, 0.015);
    const Eigen::Vector2d expect = J * F.inverse() * d;
    EXPECT_NEAR(s.by["a"].x(), expect.x(), 1e-9);
    EXPECT_NEAR(s.by["a"].y(), expect.y(), 1e-9);
}

// Two corrections of one tag: C becomes C P^-1 P+ after the first; motion
// noise between them (the robot's covariance doubled) halves the share of the
// robot's error the tag still carries, so the second moves it by half the
// robot's correction.
TEST(MapCorrection, CorrelationFollowsTheKalmanUpdateAndTheMotionNoise) {
    const Eigen::Matrix3d P = robotCov();
    const auto b1 = moments(0, 0, 0, P);
    const auto a1 = moments(0.1, 0, 0, 0.1 * P);
    CTagRobotCorrelation c(0.0001);
    c.add("a", false, 0, 0, b1);
    TShifts s1, s2;
    c.correct(b1, a1, s1.fn());
    EXPECT_NEAR(s1.by["a"].x(), 0.1, 1e-12);
    EXPECT_NEAR(s1.by["a"].y(), 0.0, 1e-12);
    const auto b2 = moments(0.1, 0, 0, 0.2 * P);
    const auto a2 = moments(0.2, 0, 0, 0.05 * P);
    c.correct(b2, a2, s2.fn());
    EXPECT_NEAR(s2.by["a"].x(), 0.05, 1e-9);
    EXPECT_NEAR(s2.by["a"].y(), 0.0, 1e-9);
}

// A weighing that does not narrow the cloud is no Gaussian update: nothing
// moves. A tag that weighed the robot leaves the set.
TEST(MapCorrection, NoNarrowingMovesNothingAndDroppedTagsStay) {
    const Eigen::Matrix3d P = robotCov();
    const auto before = moments(0, 0, 0, P);
    CTagRobotCorrelation c(0.001);
    c.add("a", false, 0.1, 0, before);
    c.add("b", false, 0.2, 0, before);
    TShifts s;
    EXPECT_EQ(c.correct(before, moments(0.3, 0, 0, P), s.fn()), 0u);
    EXPECT_TRUE(s.by.empty());
    c.drop({"a"});
    EXPECT_EQ(c.size(), 1u);
    EXPECT_EQ(c.correct(before, moments(0.3, 0, 0, 0.5 * P), s.fn()), 1u);
    EXPECT_EQ(s.by.count("a"), 0u);
    EXPECT_EQ(s.by.count("b"), 1u);
}

// A tag mapped from a robot whose position is already known to within the
// minimum std does not join.
TEST(MapCorrection, CertainRobotAddsNothing) {
    CTagRobotCorrelation c(0.002);
    c.add("a", false, 0.1, 0, moments(0, 0, 0, 1e-8 * Eigen::Matrix3d::Identity()));
    EXPECT_EQ(c.size(), 0u);
}

// The engine's order: corrections wait while the map is not updated, are
// applied together when it is, and a resetting drops them.
TEST(MapCorrection, PendingCorrectionsWaitForAMappingStepOrDropWithAReset) {
    const Eigen::Matrix3d P = robotCov();
    const auto b = moments(0, 0, 0, P);
    const auto a = moments(0.1, 0, 0, 0.5 * P);
    CMapCorrection m(0.001);
    m.mapped("t", false, 0, 0, b);
    m.mapped("u", false, 0, 0, b);
    m.weighed(b, a, {"u"});
    TShifts s;
    EXPECT_EQ(m.settle(false, false, s.fn()), 0u);  // suspicious: waits
    EXPECT_TRUE(s.by.empty());
    EXPECT_EQ(m.settle(false, true, s.fn()), 1u);  // applied; u weighed
    EXPECT_NEAR(s.by["t"].x(), 0.1, 1e-12);
    EXPECT_EQ(s.by.count("u"), 0u);

    CMapCorrection r(0.001);
    r.mapped("t", false, 0, 0, b);
    r.weighed(b, a, {});
    TShifts s2;
    EXPECT_EQ(r.settle(true, true, s2.fn()), 0u);
    EXPECT_EQ(r.size(), 0u);
    EXPECT_TRUE(s2.by.empty());
}

// At most maxTags tags follow the robot: a new one pushes out the oldest, so
// a correction's cost does not grow with the map.
TEST(MapCorrection, TheOldestTagLeavesBeyondTheCap) {
    const Eigen::Matrix3d P = robotCov();
    const auto b = moments(0, 0, 0, P);
    CTagRobotCorrelation c(0.001, 2);
    for (const char* id : {"a", "b", "c"}) c.add(id, false, 0.1, 0, b);
    EXPECT_EQ(c.size(), 2u);
    TShifts s;
    EXPECT_EQ(c.correct(b, moments(0.1, 0, 0, 0.5 * P), s.fn()), 2u);
    EXPECT_EQ(s.by.count("a"), 0u);
    EXPECT_EQ(s.by.count("b"), 1u);
    EXPECT_EQ(s.by.count("c"), 1u);
}
