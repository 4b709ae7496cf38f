/* IR sensor-model functors (thesis eqs. 5.1-5.3): values computed by hand. */
#include <rfir/ir/sensor_model.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace rfir::ir;

// Eq. 5.3 in metres equals the thesis' millimetre form.
TEST(IRModel, CurveMatchesThesisInMillimetres) {
    const TVoltageCurve c;
    for (double dmm : {0.0, 50.0, 100.0, 200.0, 250.0}) {
        const double seed = -3.27e-5 * dmm * dmm + 2.855e-3 * dmm + 1.81997;
        EXPECT_NEAR(c.expected(dmm / 1000, 1.2), seed, 1e-12) << dmm;
    }
    EXPECT_NEAR(c.expected(0.1, 1.2), 1.77847, 1e-9);
    EXPECT_NEAR(c.expected(0.2, 1.2), 1.08297, 1e-9);
    EXPECT_EQ(c.expected(0.29, 1.2), 0.0);  // beyond the visible radius
    EXPECT_EQ(c.visibleRadius(1.0), 0.28);  // Fixed ignores the height
    EXPECT_NEAR(c.expected(0.1, 1.0), 1.77847, 1e-9);
}

// Angular height model: V(d, h) = (h0/h)^2 V(d h0/h).
TEST(IRModel, AngularHeightModel) {
    TVoltageCurve c;
    c.heightModel = TVoltageCurve::HeightModel::Angular;
    // h = 1.0: dd = 0.12, curve = -32.7*0.0144 + 2.855*0.12 + 1.81997 = 1.69169
    EXPECT_NEAR(c.expected(0.1, 1.0), 1.44 * 1.69169, 1e-6);
    EXPECT_NEAR(c.visibleRadius(1.0), 0.28 / 1.2, 1e-12);
    EXPECT_NEAR(c.expected(0.1, 1.2), 1.77847, 1e-9);  // at the fit height: eq. 5.3
    EXPECT_EQ(c.expected(0.25, 1.0), 0.0);
}

TEST(IRModel, VoltageLikelihoodEq52) {
    EXPECT_NEAR(voltageLogLikelihood(1.5, 1.3, 0.1), -2.0, 1e-12);
    EXPECT_EQ(voltageLogLikelihood(0.7, 0.7, 0.05), 0.0);
}

TEST(IRModel, BeliefEq51) {
    std::vector<TEmitter> em(3);
    em[0].x = 0;
    em[1].x = 0.8;
    em[2].x = 1.6;
    // Far from every candidate (all beliefs underflow to 0): still the nearest.
    EXPECT_EQ(mostLikelyEmitter({0, 1, 2}, em, {1.3, 5.0}), 2u);
    EXPECT_EQ(mostLikelyEmitter({0, 1, 2}, em, {0.5, 0.0}), 1u);
    EXPECT_EQ(mostLikelyEmitter({0, 2}, em, {0.5, 0.0}), 0u);
    EXPECT_THROW(mostLikelyEmitter({}, em, {0, 0}), std::invalid_argument);
}

TEST(IRModel, ReceiverInWorld) {
    rfir::obs::TIRReceiver r;
    r.x = 0.1;
    r.y = 0.2;
    const auto p = receiverInWorld({1, 2, M_PI / 2}, r);
    EXPECT_NEAR(p.x, 0.8, 1e-12);
    EXPECT_NEAR(p.y, 2.1, 1e-12);
}

TEST(IRModel, ReadingLikelihood) {
    TIRLikelihoodParams p;  // out of range -8, ramp 0.05 m
    p.sigmaVolts = 0.1;
    TEmitter e;
    e.x = 0.2;
    // d = 0.2: Vbar = 1.08297; -(1 - 1.08297)^2 / 0.02
    EXPECT_NEAR(readingLogLikelihood(1.0, {0, 0}, e, 1.2, p), -0.0068840209 / 0.02, 1e-9);
    e.x = 0.4;  // out of sight: Vbar = 0, -1/0.02 - 8
    EXPECT_NEAR(readingLogLikelihood(1.0, {0, 0}, e, 1.2, p), -58.0, 1e-9);
    e.x = 0.305;  // 0.025 m past the visible radius: half the out-of-range term
    EXPECT_NEAR(readingLogLikelihood(1.0, {0, 0}, e, 1.2, p), -50.0 - 4.0, 1e-9);
    p.outOfRangeLogLik = 0;  // the thesis' eq. 5.2 alone
    e.x = 0.4;
    EXPECT_NEAR(readingLogLikelihood(1.0, {0, 0}, e, 1.2, p), -50.0, 1e-9);
}

TEST(IRModel, DistancesForVoltage) {
    const TVoltageCurve c;
    auto d = distancesForVoltage(c, 1.08297, 1.2);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NEAR(d[0], 0.2, 1e-6);
    // Between V(0) = 1.82 and the maximum 1.882 at 43.7 mm: two roots.
    d = distancesForVoltage(c, 1.85, 1.2);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_NEAR(d[0], 0.012230, 1e-5);
    EXPECT_NEAR(d[1], 0.075077, 1e-5);
    // Above the maximum: the distance of the maximum.
    d = distancesForVoltage(c, 2.5, 1.2);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NEAR(d[0], 2.855 / 65.4, 1e-9);
    for (double v : {0.1, 0.6, 1.2, 1.7})
        for (double r : distancesForVoltage(c, v, 1.2))
            EXPECT_NEAR(c.expected(r, 1.2), v, 1e-9);
}

// Inverse-square height model: V(d, h) = (h0/h)^2 V(d), same visible radius.
TEST(IRModel, InverseSquareHeightModel) {
    TVoltageCurve c;
    c.heightModel = TVoltageCurve::HeightModel::InverseSquare;
    EXPECT_NEAR(c.expected(0.1, 1.0), 1.44 * 1.77847, 1e-9);
    EXPECT_EQ(c.visibleRadius(1.0), 0.28);
    auto d = distancesForVoltage(c, 1.44 * 1.08297, 1.0);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NEAR(d[0], 0.2, 1e-6);
}
