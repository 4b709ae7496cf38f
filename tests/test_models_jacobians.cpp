// The measurement models written once (read_model.h, read_noise.h,
// range_bearing.h): analytic Jacobians and gradients against central
// differences, inverse models against the forward ones, the outlier mixture.
#include <rfir/models/detection_likelihood.h>
#include <rfir/models/random.h>
#include <rfir/models/range_bearing.h>
#include <rfir/models/read_model.h>
#include <rfir/models/read_noise.h>

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <array>
#include <cmath>
#include <functional>

using namespace rfir::models;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace {
constexpr double kStep = 1e-6, kTol = 1e-6;

/** Central difference of a 2-vector function of n variables, column j. */
std::array<double, 2> numericColumn(
    const std::function<std::array<double, 2>(const std::array<double, 3>&)>& f,
    std::array<double, 3> x, int j) {
    auto lo = x, hi = x;
    lo[j] -= kStep, hi[j] += kStep;
    const auto a = f(lo), b = f(hi);
    return {(b[0] - a[0]) / (2 * kStep), (b[1] - a[1]) / (2 * kStep)};
}

struct TCase {
    TPose2D robot;
    TPoint2D tag;
    double offX, offY;
};

std::vector<TCase> randomCases(size_t n) {
    TRandom rng(17);
    std::vector<TCase> out;
    for (size_t i = 0; i < n; i++)
        out.push_back({{rng.drawUniform(-5, 5), rng.drawUniform(-5, 5),
                        rng.drawUniform(-M_PI, M_PI)},
                       {rng.drawUniform(-5, 5), rng.drawUniform(-5, 5)},
                       rng.drawUniform(-0.3, 0.3),
                       rng.drawUniform(-0.3, 0.3)});
    return out;
}
}  // namespace

TEST(ReadModel, JacobiansMatchNumericDifferentiation) {
    for (const auto& k : randomCases(50)) {
        TReadJacobians J;
        readModel(k.robot, k.offX, k.offY, k.tag, &J);
        const auto byPose = [&](const std::array<double, 3>& x) {
            const auto e = readModel({x[0], x[1], x[2]}, k.offX, k.offY, k.tag);
            return std::array<double, 2>{e.x, e.y};
        };
        const auto byTag = [&](const std::array<double, 3>& x) {
            const auto e = readModel(k.robot, k.offX, k.offY, {x[0], x[1]});
            return std::array<double, 2>{e.x, e.y};
        };
        for (int j = 0; j < 3; j++) {
            const auto n = numericColumn(byPose, {k.robot.x, k.robot.y, k.robot.phi}, j);
            EXPECT_NEAR(J.pose[0][j], n[0], kTol) << j;
            EXPECT_NEAR(J.pose[1][j], n[1], kTol) << j;
        }
        for (int j = 0; j < 2; j++) {
            const auto n = numericColumn(byTag, {k.tag.x, k.tag.y, 0}, j);
            EXPECT_NEAR(J.tag[0][j], n[0], kTol) << j;
            EXPECT_NEAR(J.tag[1][j], n[1], kTol) << j;
        }
    }
}

TEST(ReadModel, InversesAndTheLikelihoodUseIt) {
    const DetectionLikelihood det;
    for (const auto& k : randomCases(50)) {
        const double c = std::cos(k.robot.phi), s = std::sin(k.robot.phi);
        // A tag at the reader centre gives e = 0.
        const auto centre = readerCentreInWorld(k.robot, {k.offX, k.offY, 0.03, 0.03});
        const auto e0 = readModel(k.robot, k.offX, k.offY, centre);
        EXPECT_NEAR(e0.x, 0, 1e-12);
        EXPECT_NEAR(e0.y, 0, 1e-12);
        // The tag from e, and the robot position from the tag seen at offset + e.
        const auto e = readModel(k.robot, k.offX, k.offY, k.tag);
        const auto t = robotFrameToWorld(k.robot, c, s, k.offX + e.x, k.offY + e.y);
        EXPECT_NEAR(t.x, k.tag.x, 1e-12);
        EXPECT_NEAR(t.y, k.tag.y, 1e-12);
        const auto p = robotPositionFromRead(k.tag, c, s, k.offX + e.x, k.offY + e.y);
        EXPECT_NEAR(p.x, k.robot.x, 1e-12);
        EXPECT_NEAR(p.y, k.robot.y, 1e-12);
        // DetectionLikelihood is the step noise of this e (bit for bit).
        const ReaderArea r{k.offX, k.offY, 0.5, 0.2};
        EXPECT_EQ(det.logLikelihood(k.robot, r, k.tag),
                  CStepReadNoise(1.618).logLik(e.x, e.y, 0.5, 0.2));
    }
}

TEST(ReadNoise, GradientsMatchNumericDifferentiation) {
    const CStepReadNoise step(1.618);
    const CGaussianReadNoise gauss(1.5);
    const double hx = 0.15, hy = 0.05;
    TRandom rng(3);
    for (int i = 0; i < 200; i++) {
        const double ex = rng.drawUniform(-0.6, 0.6), ey = rng.drawUniform(-0.3, 0.3);
        const auto check = [&](const auto& model, const char* name) {
            double g[2];
            model.logLik(ex, ey, hx, hy, g);
            const double nx = (model.logLik(ex + kStep, ey, hx, hy) -
                               model.logLik(ex - kStep, ey, hx, hy)) /
                              (2 * kStep);
            const double ny = (model.logLik(ex, ey + kStep, hx, hy) -
                               model.logLik(ex, ey - kStep, hx, hy)) /
                              (2 * kStep);
            // The step is discontinuous at the rectangle's edge: skip those.
            if (std::abs(std::abs(ex) - hx) < 2 * kStep ||
                std::abs(std::abs(ey) - hy) < 2 * kStep)
                return;
            EXPECT_NEAR(g[0], nx, 1e-5) << name << " " << ex << " " << ey;
            EXPECT_NEAR(g[1], ny, 1e-5) << name << " " << ex << " " << ey;
        };
        check(step, "step");
        check(gauss, "gaussian");
    }
}

TEST(ReadNoise, OutlierMixtureBoundsTheCostOfAFarRead) {
    const CStepReadNoise step(1.618);
    const double eps = 0.01, floor = -8.0;
    const COutlierMixture mixture(eps, floor);
    const auto mix = [&](double ex, double ey) {
        return mixture.mix(step.logLik(ex, ey, 0.03, 0.03));
    };
    // Inside: log(1 - eps + eps e^floor), just below 0.
    EXPECT_NEAR(mix(0, 0), std::log(1 - eps + eps * std::exp(floor)), 1e-12);
    // Far away the base model is ~ -inf; the mixture stays at log(eps) + floor.
    EXPECT_LT(step.logLik(3, 0, 0.03, 0.03), -1000);
    EXPECT_NEAR(mix(3, 0), std::log(eps) + floor, 1e-9);
    // In between, the exact log((1 - eps) L + eps floor).
    const double ll = step.logLik(0.05, 0.01, 0.03, 0.03);
    EXPECT_NEAR(mix(0.05, 0.01),
                std::log((1 - eps) * std::exp(ll) + eps * std::exp(floor)), 1e-12);
    // Through DetectionLikelihood: off by default (the papers' model), on with eps.
    DetectionModelParams p;
    EXPECT_EQ(DetectionLikelihood(p).logLikelihoodOffset(3, 0, 0.03, 0.03),
              step.logLik(3, 0, 0.03, 0.03));
    p.outlierWeight = eps;
    p.outlierLogFloor = floor;
    EXPECT_NEAR(DetectionLikelihood(p).logLikelihoodOffset(3, 0, 0.03, 0.03),
                std::log(eps) + floor, 1e-9);
}

TEST(RangeBearingModel, JacobiansMatchNumericDifferentiation) {
    TRandom rng(5);
    for (int i = 0; i < 50; i++) {
        const TPose2D robot(rng.drawUniform(-3, 3), rng.drawUniform(-3, 3),
                            rng.drawUniform(-M_PI, M_PI));
        const TPose2D mount(rng.drawUniform(-0.2, 0.2), rng.drawUniform(-0.2, 0.2),
                            rng.drawUniform(-1, 1));
        const TPoint2D lm(rng.drawUniform(-3, 3), rng.drawUniform(-3, 3));
        const auto rb = [](const TRangeBearing& h) {
            return std::array<double, 2>{h.range, h.bearing};
        };
        TRangeBearingJacobians Js, Jr;
        rangeBearingModel(robot, lm, &Js);  // the robot pose as the sensor pose
        rangeBearingModel(robot, mount, lm, &Jr);
        const auto bySensor = [&](const std::array<double, 3>& x) {
            return rb(rangeBearingModel(TPose2D(x[0], x[1], x[2]), lm));
        };
        const auto byRobot = [&](const std::array<double, 3>& x) {
            return rb(rangeBearingModel(TPose2D(x[0], x[1], x[2]), mount, lm, nullptr));
        };
        const auto byLandmark = [&](const std::array<double, 3>& x) {
            return rb(rangeBearingModel(robot, mount, {x[0], x[1]}, nullptr));
        };
        for (int j = 0; j < 3; j++) {
            const auto ns = numericColumn(bySensor, {robot.x, robot.y, robot.phi}, j);
            const auto nr = numericColumn(byRobot, {robot.x, robot.y, robot.phi}, j);
            for (int row = 0; row < 2; row++) {
                EXPECT_NEAR(Js.sensor[row][j], ns[row], kTol) << row << j;
                EXPECT_NEAR(Jr.sensor[row][j], nr[row], kTol) << row << j;
            }
        }
        for (int j = 0; j < 2; j++) {
            const auto n = numericColumn(byLandmark, {lm.x, lm.y, 0}, j);
            EXPECT_NEAR(Jr.landmark[0][j], n[0], kTol) << j;
            EXPECT_NEAR(Jr.landmark[1][j], n[1], kTol) << j;
        }
    }
}

TEST(RangeBearingModel, InverseAndItsJacobian) {
    TRandom rng(6);
    for (int i = 0; i < 50; i++) {
        const TPose2D s(rng.drawUniform(-3, 3), rng.drawUniform(-3, 3),
                        rng.drawUniform(-M_PI, M_PI));
        const double range = rng.drawUniform(0.1, 4), bearing = rng.drawUniform(-3, 3);
        double G[2][2];
        const auto p = rangeBearingToPoint(s, range, bearing, G);
        // Forward model of the inverse gives the reading back.
        const auto h = rangeBearingModel(s, p);
        EXPECT_NEAR(h.range, range, 1e-9);
        EXPECT_NEAR(mrpt::math::wrapToPi(h.bearing - bearing), 0, 1e-9);
        // predictRangeBearing is the same model, bearing wrapped.
        double r2, b2;
        predictRangeBearing(s, p, r2, b2);
        EXPECT_EQ(r2, h.range);
        EXPECT_EQ(b2, mrpt::math::wrapToPi(h.bearing));
        const auto byReading = [&](const std::array<double, 3>& x) {
            const auto q = rangeBearingToPoint(s, x[0], x[1]);
            return std::array<double, 2>{q.x, q.y};
        };
        for (int j = 0; j < 2; j++) {
            const auto n = numericColumn(byReading, {range, bearing, 0}, j);
            EXPECT_NEAR(G[0][j], n[0], kTol) << j;
            EXPECT_NEAR(G[1][j], n[1], kTol) << j;
        }
    }
}
