// Likelihood values computed by hand, resampling and INI key checks.
#include <rfir/models/detection_likelihood.h>
#include <rfir/models/ini_reader.h>
#include <rfir/models/random.h>
#include <rfir/models/range_bearing.h>
#include <rfir/models/resampling.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>

using namespace rfir::models;

TEST(DetectionLikelihood, StepInsideEdgeOutside) {
    const double h = 0.03, beta = 1.618;
    // Inside the square: w = 1 exactly.
    EXPECT_EQ(std::exp(CStepReadNoise(beta).logLik(0.01, -0.02, h, h)), 1.0);
    // On the edge (|ex| = sigma is not "< sigma"): beta e^{-1/2} = 0.98137
    EXPECT_NEAR(std::exp(CStepReadNoise(beta).logLik(0.03, 0.0, h, h)), 0.9813666074,
                1e-9);
    // Two sigmas out: 1.618 e^{-2} = 0.21897
    EXPECT_NEAR(std::exp(CStepReadNoise(beta).logLik(0.06, 0.0, h, h)), 0.2189724883,
                1e-9);
    // Outside in x, inside in y: e^T e uses both components (thesis eq. 3.7)
    EXPECT_NEAR(std::exp(CStepReadNoise(beta).logLik(0.04, 0.01, h, h)), 0.6292330225,
                1e-9);
    // Rectangular reader: per-axis sigma = half-size (0.15 x 0.05)
    EXPECT_NEAR(std::exp(CStepReadNoise(beta).logLik(0.2, 0.0, 0.15, 0.05)), 0.6651796860,
                1e-9);
    EXPECT_EQ(CStepReadNoise(beta).logLik(0.14, 0.04, 0.15, 0.05), 0.0);
}

TEST(DetectionLikelihood, GaussianAndFunctor) {
    EXPECT_NEAR(CGaussianReadNoise(1.0).logLik(0.03, 0.03, 0.03, 0.03), -1.0, 1e-12);
    DetectionModelParams p;
    p.model = DetectionModel::Gaussian;
    p.gaussianSigmaScale = 2.0;  // sigma = 2 * half = 0.06
    const DetectionLikelihood g(p);
    EXPECT_NEAR(g.logLikelihoodOffset(0.06, 0.0, 0.03, 0.03), -0.5, 1e-12);
}

TEST(DetectionLikelihood, OffsetIsInRobotFrame) {
    const DetectionLikelihood step;  // defaults: step, beta 1.618
    const mrpt::math::TPose2D robot(1.0, 2.0, M_PI / 2);
    const ReaderArea r{0.1, 0.0, 0.03, 0.03};
    const auto c = readerCentreInWorld(robot, r);
    EXPECT_NEAR(c.x, 1.0, 1e-12);
    EXPECT_NEAR(c.y, 2.1, 1e-12);
    EXPECT_EQ(std::exp(step.logLikelihood(robot, r, {1.0, 2.1})), 1.0);
    // 60 mm to the world -x is 60 mm to the robot's +y (two sigmas out).
    EXPECT_NEAR(std::exp(step.logLikelihood(robot, r, {0.94, 2.1})), 0.2189724883, 1e-9);
    // A 0.3 x 0.06 reader rotated by 90 deg: 0.1 m along world -x is inside.
    const ReaderArea wide{0.1, 0.0, 0.03, 0.15};
    EXPECT_EQ(std::exp(step.logLikelihood(robot, wide, {0.9, 2.1})), 1.0);
    EXPECT_LT(std::exp(step.logLikelihood(robot, wide, {1.0, 2.2})), 0.5);
}

TEST(RangeBearing, LikelihoodAndInverse) {
    RangeBearingParams p;
    p.sigmaRange = 0.01;
    p.sigmaBearing = 0.05;
    const mrpt::math::TPose2D s(0, 0, 0);
    EXPECT_NEAR(rangeBearingLogLikelihood(s, {1, 0}, 1.01, 0.0, p), -0.5, 1e-9);
    EXPECT_NEAR(rangeBearingLogLikelihood(s, {1, 0}, 1.0, 0.1, p), -2.0, 1e-9);
    // Bearing error wraps: sensor looking at -x, reading +pi-0.01 vs -pi+0.01.
    const mrpt::math::TPose2D back(0, 0, M_PI);
    EXPECT_NEAR(rangeBearingLogLikelihood(back, {-1, -0.01}, 1.0, -M_PI + 0.01, p),
                rangeBearingLogLikelihood(back, {-1, -0.01}, 1.0, M_PI + 0.01, p), 1e-9);
    EXPECT_GT(rangeBearingLogLikelihood(back, {-1, -0.01}, 1.00005, 0.01, p), -0.1);
    const auto q = rangeBearingToPoint({1, 1, M_PI / 2}, 2.0, M_PI / 2);
    EXPECT_NEAR(q.x, -1.0, 1e-12);
    EXPECT_NEAR(q.y, 1.0, 1e-12);
    double r, br;
    predictRangeBearing({1, 1, M_PI / 2}, q, r, br);
    EXPECT_NEAR(r, 2.0, 1e-12);
    EXPECT_NEAR(br, M_PI / 2, 1e-12);
    rfir::models::TRandom rng(3);
    const auto pts = sampleRangeBearingInverse(s, 0.4, 0.0, p, 4000, rng);
    double mx = 0, vy = 0;
    for (const auto& pt : pts) mx += pt.x / pts.size();
    for (const auto& pt : pts) vy += pt.y * pt.y / pts.size();
    EXPECT_NEAR(mx, 0.4, 0.002);
    EXPECT_NEAR(std::sqrt(vy), 0.4 * 0.05, 0.002);  // lateral spread = r sigma_b
}

TEST(Resampling, SystematicIsExactAndSeeded) {
    rfir::models::TRandom rng(7);
    const std::vector<double> lw = {0.0, std::log(3.0)};
    const auto idx = resampleIndices(lw, 4, ResamplingScheme::Systematic, rng);
    EXPECT_EQ(idx, (std::vector<size_t>{0, 1, 1, 1}));
    const std::vector<double> lw2 = {-1e300, 0.0,
                                     -std::numeric_limits<double>::infinity()};
    for (auto s : {ResamplingScheme::Systematic, ResamplingScheme::Stratified,
                   ResamplingScheme::Multinomial}) {
        for (size_t i : resampleIndices(lw2, 10, s, rng)) EXPECT_EQ(i, 1u);
        rfir::models::TRandom a(11), b(11);
        const std::vector<double> w = {0.1, 0.5, -0.3, 0.0, 1.0};
        EXPECT_EQ(resampleIndices(w, 50, s, a), resampleIndices(w, 50, s, b));
    }
    rfir::models::TRandom m(5);
    const auto many = resampleIndices(lw, 20000, ResamplingScheme::Multinomial, m);
    const double frac0 = std::count(many.begin(), many.end(), 0u) / 20000.0;
    EXPECT_NEAR(frac0, 0.25, 0.015);
    EXPECT_NEAR(effectiveSampleSize({0, 0, 0, 0}), 4.0, 1e-12);
    EXPECT_THROW(resampleIndices({}, 3, ResamplingScheme::Systematic, rng),
                 std::invalid_argument);
}

TEST(IniCheck, UnknownKeysAndBadValuesNameTheKey) {
    using rfir::ini::CIniSection;
    using rfir::ini::TRange;
    mrpt::config::CConfigFileMemory cfg(
        "[s]\nalpha = 1\nbeta = x\nmode = fast\nn = 0\nm = -2\n");
    const std::vector<std::string> all = {"alpha", "beta", "mode", "n", "m", "absent"};
    EXPECT_NO_THROW(CIniSection(cfg, "s", all));
    EXPECT_NO_THROW(CIniSection(cfg, "missing", {}));
    try {
        CIniSection(cfg, "s", {"alpha", "beta", "n", "m"});
        FAIL();
    } catch (const rfir::ini::CIniError& e) {
        EXPECT_NE(std::string(e.what()).find("mode"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("[s]"), std::string::npos) << e.what();
    }
    auto msg = [&](auto f) {
        try {
            f();
        } catch (const rfir::ini::CIniError& e) {
            return std::string(e.what());
        }
        return std::string("no throw");
    };
    const CIniSection s(cfg, "s", all);
    EXPECT_NE(msg([&] {
                  s.getEnum("mode", {"slow", "exact"}, 0);
              }).find("mode"),
              std::string::npos);
    EXPECT_NE(msg([&] { s.getInt("n", 5, 1, 10); }).find("[s] n"), std::string::npos);
    EXPECT_NE(msg([&] { s.getInt("m", 5, 1, 10); }).find("[s] m"), std::string::npos);
    EXPECT_NE(msg([&] { s.getDouble("beta", 1, TRange::aboveZero(10)); }).find("beta"),
              std::string::npos);
    EXPECT_EQ(s.getInt("absent", 5, 1, 10), 5);
    EXPECT_EQ(s.getEnum("absent", {"a", "b"}, 1), 1u);
    EXPECT_EQ(s.getDouble("alpha", 7, TRange::aboveZero(10)), 1.0);
}

// The values MRPT's read_int and read_double let through: a
// leading integer kept, nan and 1e308 taken as numbers.
TEST(IniCheck, StrictNumbers) {
    using rfir::ini::TRange;
    mrpt::config::CConfigFileMemory cfg(
        "[s]\na = 5e2\nb = 2.9\nc = 500x\nd = nan\ne = 1e308\nf = 500\ng = inf\n"
        "h = 1e999\ni = 99999999999999999999\nj =\n");
    const rfir::ini::CIniSection s(cfg, "s",
                                   {"a", "b", "c", "d", "e", "f", "g", "h", "i", "j"});
    for (const char* k : {"a", "b", "c", "d", "e", "i", "j"})
        EXPECT_THROW(s.getInt(k, 1, 1, 1000000), rfir::ini::CIniError) << k;
    EXPECT_EQ(s.getInt("f", 1, 1, 1000000), 500);
    for (const char* k : {"c", "d", "e", "g", "h", "j"})
        EXPECT_THROW(s.getDouble(k, 1, TRange::closed(-10, 1000)), rfir::ini::CIniError)
            << k;
    EXPECT_EQ(s.getDouble("a", 1, TRange::closed(0, 1000)), 500.0);
    EXPECT_THROW(s.getDouble("f", 1, TRange::closed(0, 100)), rfir::ini::CIniError);
}
