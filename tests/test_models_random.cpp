/* Tests of the run's generator (rfir/models/random.h) and of the odometry
 * noise model (rfir/models/odometry_noise.h) and of the spatial grid. */
#include <rfir/models/odometry_noise.h>
#include <rfir/models/random.h>
#include <rfir/models/spatial_grid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using rfir::models::OdometryGaussian;
using rfir::models::OdometryNoiseParams;
using rfir::models::TRandom;

TEST(Random, SameSeedSameStreamOtherSeedOtherStream) {
    TRandom a(42), b(42), c(43);
    bool differs = false;
    for (int i = 0; i < 1000; i++) {
        const uint64_t x = a.drawUniform64bit();
        EXPECT_EQ(x, b.drawUniform64bit());
        differs = differs || x != c.drawUniform64bit();
    }
    EXPECT_TRUE(differs);
    a.randomize(7);
    b.randomize(7);
    EXPECT_EQ(a.drawGaussian1D_normalized(), b.drawGaussian1D_normalized());
}

TEST(Random, UniformAndGaussianMoments) {
    TRandom r(1);
    const int n = 400000;
    double su = 0, sg = 0, sg2 = 0, sg4 = 0, umin = 1, umax = 0;
    int tail = 0;
    for (int i = 0; i < n; i++) {
        const double u = r.drawUniform(0, 1);
        umin = std::min(umin, u), umax = std::max(umax, u);
        su += u;
        const double g = r.drawGaussian1D_normalized();
        sg += g, sg2 += g * g, sg4 += g * g * g * g;
        tail += std::abs(g) > 3.442619855899;  // beyond the ziggurat's base layer
    }
    EXPECT_GE(umin, 0.0);
    EXPECT_LT(umax, 1.0);
    EXPECT_NEAR(su / n, 0.5, 0.003);
    EXPECT_NEAR(sg / n, 0.0, 0.005);
    EXPECT_NEAR(sg2 / n, 1.0, 0.01);
    EXPECT_NEAR(sg4 / n, 3.0, 0.05);  // normal kurtosis: the tails are right
    // P(|g| > 3.4426) = 5.76e-4: about 230 of 400000.
    EXPECT_NEAR(double(tail), 230.0, 60.0);
    EXPECT_NEAR(r.drawGaussian1D(5.0, 0.0), 5.0, 0.0);
}

TEST(OdometryNoise, CovarianceIsMrptGaussianModelAndDrawsFollowIt) {
    OdometryNoiseParams p{0.05, 0.001, 0.02, 0.02, 0.001, 0.002};
    const double dx = 0.1, dy = 0.02, dphi = 0.3;
    const auto g = OdometryGaussian::fromOdometry(dx, dy, dphi, p);
    const double d = std::hypot(dx, dy);
    const double sxy = 0.05 * d + 0.001 * dphi + 0.001;
    const double sphi = 0.02 * d + 0.02 * dphi + 0.002;
    const double* C = g.covariance();
    EXPECT_NEAR(C[8], sphi * sphi, 1e-15);
    // The xy block: sxy^2 I plus the heading's lever arm (rank one).
    const double c = std::cos(dphi / 2), s = std::sin(dphi / 2);
    const double j02 = -s * dx - c * dy, j12 = c * dx - s * dy;
    EXPECT_NEAR(C[0], sxy * sxy + j02 * j02 * sphi * sphi, 1e-15);
    EXPECT_NEAR(C[1], j02 * j12 * sphi * sphi, 1e-15);
    EXPECT_NEAR(C[5], j12 * sphi * sphi, 1e-15);
    // Empirical covariance of the draws.
    TRandom r(3);
    const int n = 200000;
    double m[3] = {0, 0, 0}, S[9] = {0};
    std::vector<double> v(3 * n);
    for (int i = 0; i < n; i++) {
        g.draw(r, v[3 * i], v[3 * i + 1], v[3 * i + 2]);
        for (int k = 0; k < 3; k++) m[k] += v[3 * i + k] / n;
    }
    for (int i = 0; i < n; i++)
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                S[3 * a + b] += (v[3 * i + a] - m[a]) * (v[3 * i + b] - m[b]) / n;
    EXPECT_NEAR(m[0], dx, 1e-4);
    EXPECT_NEAR(m[2], dphi, 1e-4);
    for (int k = 0; k < 9; k++) EXPECT_NEAR(S[k], C[k], 0.02 * C[8] + 1e-9) << k;
}

TEST(OdometryNoise, PropagateComposesAndWraps) {
    OdometryNoiseParams zero{0, 0, 0, 0, 0, 0};
    const auto g = OdometryGaussian::fromOdometry(1.0, 0.0, 0.5, zero);
    TRandom r(1);
    double x = 1, y = 2, phi = M_PI / 2;
    g.propagate(r, x, y, phi);  // noiseless: exactly the composition
    EXPECT_NEAR(x, 1.0, 1e-12);
    EXPECT_NEAR(y, 3.0, 1e-12);
    EXPECT_NEAR(phi, M_PI / 2 + 0.5, 1e-12);
    phi = 3.0;
    g.propagate(r, x, y, phi);
    EXPECT_NEAR(phi, 3.5 - 2 * M_PI, 1e-12);
}

// The filters carry a particle's heading cos and sin through the motion
// draw: the small-angle series is within rounding of std::cos / std::sin, and
// the carried values follow the heading the same draws give.
TEST(OdometryNoise, SmallAngleCosSinIsWithinRounding) {
    double c = 7, s = 7;
    for (double a = -0.5; a <= 0.5; a += 1.0 / 4096) {
        ASSERT_TRUE(rfir::models::smallAngleCosSin(a, c, s)) << a;
        EXPECT_NEAR(c, std::cos(a), 2.3e-16) << a;
        EXPECT_NEAR(s, std::sin(a), 2.3e-16) << a;
    }
    c = s = 7;
    EXPECT_FALSE(rfir::models::smallAngleCosSin(0.51, c, s));
    EXPECT_FALSE(rfir::models::smallAngleCosSin(-3.0, c, s));
    EXPECT_FALSE(rfir::models::smallAngleCosSin(std::nan(""), c, s));
    EXPECT_EQ(c, 7.0);
    EXPECT_EQ(s, 7.0);
}

TEST(OdometryNoise, CarriedHeadingFollowsTheSameDraws) {
    // Noisy increments with turns of both signs, one with a noise wide enough
    // (heading std 0.3 rad) that some draws take the exact fallback.
    const OdometryNoiseParams quiet{0.05, 0.001, 0.02, 0.02, 0.001, 0.002};
    const OdometryNoiseParams wide{0.05, 0.001, 0.02, 0.02, 0.001, 0.3};
    TRandom a(3), b(3);
    double x1 = 0, y1 = 0, p1 = 3.1, x2 = 0, y2 = 0, p2 = 3.1;
    double c = std::cos(p2), s = std::sin(p2);
    for (int k = 0; k < 2000; k++) {
        const auto g = OdometryGaussian::fromOdometry(0.05, 0.002, k % 2 ? 0.2 : -0.15,
                                                      k % 7 ? quiet : wide);
        g.propagate(a, x1, y1, p1);
        g.propagateCarryingHeading(b, x2, y2, p2, c, s);
        ASSERT_GT(p2, -M_PI);
        ASSERT_LE(p2, M_PI);
        // The same draws: the heading is the same sum; the position uses the
        // carried cos, sin (within rounding of the exact ones).
        ASSERT_EQ(p1, p2) << k;
        ASSERT_NEAR(c, std::cos(p2), 1e-12) << k;
        ASSERT_NEAR(s, std::sin(p2), 1e-12) << k;
    }
    EXPECT_NEAR(x1, x2, 1e-9);
    EXPECT_NEAR(y1, y2, 1e-9);
}

// The one spatial grid: a square query returns every value within r, a 3 x 3
// query every value within one cell side, in the same order each time.
TEST(SpatialGrid, QueriesCoverTheirRadiusInAFixedOrder) {
    rfir::models::TSpatialGrid<size_t> g(0.5);
    std::vector<std::pair<double, double>> pts;
    TRandom rng(3);
    for (size_t i = 0; i < 400; i++) {
        pts.emplace_back(rng.drawUniform(-3.0, 3.0), rng.drawUniform(-3.0, 3.0));
        g.insert(pts.back().first, pts.back().second, i);
    }
    for (int q = 0; q < 50; q++) {
        const double x = rng.drawUniform(-3.0, 3.0), y = rng.drawUniform(-3.0, 3.0);
        std::vector<size_t> sq, sq2, around;
        g.forEachInSquare(x, y, 0.8, [&](size_t i) { sq.push_back(i); });
        g.forEachInSquare(x, y, 0.8, [&](size_t i) { sq2.push_back(i); });
        g.forEachAround(x, y, [&](size_t i) { around.push_back(i); });
        EXPECT_EQ(sq, sq2);
        for (size_t i = 0; i < pts.size(); i++) {
            const double d = std::hypot(pts[i].first - x, pts[i].second - y);
            const auto has = [i](const std::vector<size_t>& v) {
                return std::find(v.begin(), v.end(), i) != v.end();
            };
            if (d <= 0.8) {
                EXPECT_TRUE(has(sq)) << i;
            }
            if (d <= 0.5) {
                EXPECT_TRUE(has(around)) << i;
            }
        }
    }
    // Within a cell, the insertion order.
    rfir::models::TSpatialGrid<int> c(1.0);
    for (int v : {5, 2, 9}) c.insert(0.5, 0.5, v);
    std::vector<int> got;
    c.forEachAround(0.5, 0.5, [&](int v) { got.push_back(v); });
    EXPECT_EQ(got, (std::vector<int>{5, 2, 9}));
    // A query far beyond any cell key does not overflow.
    got.clear();
    c.forEachAround(1e300, -1e300, [&](int v) { got.push_back(v); });
    EXPECT_TRUE(got.empty());
}
