// The tag-estimator interface: registry, the compact smoother against a plain
// double implementation fed the same steps, state round trips, and the bytes a
// mapped tag costs (PS-SLAM <= 8 KB, PF-SLAM <= 2 KB at L = 100, lag 25).
#include "test_tagmaps_sim.h"

#include <rfir/models/tag_fixed_lag_smoother.h>
#include <rfir/models/tag_particle_filter.h>

#include <mrpt/io/CFileInputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

using namespace rfir::models;
using mrpt::math::TPoint2D;

TEST(TagEstimatorRegistry, NamesCreateAndRejectUnknown) {
    const auto names = tagEstimatorNames();
    EXPECT_NE(std::find(names.begin(), names.end(), kParticleFilterName), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), kFixedLagSmootherName), names.end());
    TTagEstimatorParams p;
    p.numParticles = 7;
    auto ps = createTagEstimator(kFixedLagSmootherName, p);
    EXPECT_STREQ(ps->name(), kFixedLagSmootherName);
    EXPECT_EQ(ps->numParticles(), 7u);
    EXPECT_THROW(createTagEstimator("no_such_estimator", p), std::invalid_argument);
    EXPECT_THROW(registerTagEstimator(kParticleFilterName, nullptr), std::logic_error);
}

namespace {

double maxDiff(const std::vector<TPoint2D>& a, const std::vector<TPoint2D>& b) {
    double d = 0;
    for (size_t j = 0; j < a.size(); j++)
        d = std::max({d, std::abs(a[j].x - b[j].x), std::abs(a[j].y - b[j].y)});
    return d;
}
}  // namespace

TEST(TagFixedLagSmoother, CompactStorageMatchesWholeHistories) {
    // The compact smoother's particles after each update are mapped back to
    // the exact one's by matching current states (resampling copies rows).
    TRandom rng(5);
    TagFixedLagSmootherParams p;
    p.lag = 6;
    TagFixedLagSmoother ps(p);
    ps.initUniform({1.0, 2.0, 0.4}, {0.1, 0.0, 0.03, 0.03}, rng);
    const auto like = [](const TPoint2D& q) {
        return -((q.x - 1.09) * (q.x - 1.09) + (q.y - 2.04) * (q.y - 2.04)) / 2e-4;
    };
    for (int k = 0; k < 40; k++) {
        ps.update(like, rng);
        const auto sm = ps.smoothedParticles();
        const auto cur = ps.particles();
        double worst = 0;
        for (size_t j = 0; j < ps.size(); j++) {
            const auto h = ps.history(j);
            ASSERT_EQ(h.size(), std::min<size_t>(k + 2, p.lag));
            EXPECT_EQ(h.back().x, cur[j].x);  // the rebuilt path ends at the state
            EXPECT_EQ(h.back().y, cur[j].y);
            double sx = 0, sy = 0;
            for (size_t i = 0; i < h.size(); i++) {
                sx += h[i].x, sy += h[i].y;
                if (i) {
                    EXPECT_LT(std::hypot(h[i].x - h[i - 1].x, h[i].y - h[i - 1].y), 0.01);
                }
            }
            worst = std::max({worst, std::abs(sm[j].x - sx / h.size()),
                              std::abs(sm[j].y - sy / h.size())});
        }
        EXPECT_LT(worst, 1e-9) << "update " << k;
    }
}

TEST(TagFixedLagSmoother, MoveIsExactOnceTheOldStatesLeave) {
    // A rigid move per particle (the map's samples_visit commit): right after
    // it the smoothed set is the moved one; lag - 1 updates later every state
    // stored before the move has left, and the sums are exact again.
    TRandom rng(8);
    TagFixedLagSmootherParams p;
    p.lag = 5;
    TagFixedLagSmoother a(p);
    a.initUniform({0, 0, 0}, {0.2, 0.0, 0.03, 0.03}, rng);
    const auto flat = [](const TPoint2D&) { return 0.0; };
    for (int k = 0; k < 7; k++) a.update(flat, rng);
    const auto move = [](size_t j, const TPoint2D& q) {
        const double t = 0.01 * double(j % 5), c = std::cos(t), s = std::sin(t);
        return TPoint2D(0.3 + c * q.x - s * q.y, -0.1 + s * q.x + c * q.y);
    };
    std::vector<TPoint2D> expect;
    for (size_t j = 0; j < a.size(); j++)
        expect.push_back(move(j, a.smoothedParticles()[j]));
    a.moveStates(move);
    EXPECT_LT(maxDiff(a.smoothedParticles(), expect), 1e-5);
    for (size_t k = 0; k + 1 < p.lag; k++) a.update(flat, rng);
    const auto sm = a.smoothedParticles();
    for (size_t j = 0; j < a.size(); j++) {
        const auto h = a.history(j);
        double sx = 0;
        for (const auto& s : h) sx += s.x;
        EXPECT_NEAR(sm[j].x, sx / h.size(), 1e-9);
    }
}

TEST(TagFixedLagSmoother, TranslateMovesEveryStoredStateByTheShift) {
    // The map correction's shift moves the anchor: every current, smoothed
    // and history state by (dx, dy) to within the 2^-20 m grid, and the
    // estimate with them; the updates that follow draw as before.
    TRandom rng(9), rngB(9);
    TagFixedLagSmootherParams p;
    p.lag = 5;
    TagFixedLagSmoother a(p);
    a.initUniform({1, 2, 0}, {0.2, 0.0, 0.03, 0.03}, rng);
    const auto like = [](const TPoint2D& q) { return -(q.x - 1) * (q.x - 1) / 2e-4; };
    for (int k = 0; k < 7; k++) a.update(like, rng);
    TagFixedLagSmoother b = a;
    const double dx = 0.123456, dy = -0.0421;
    auto shifted = [&](std::vector<TPoint2D> v) {
        for (auto& q : v) q.x += dx, q.y += dy;
        return v;
    };
    const auto cur = shifted(a.particles()), sm = shifted(a.smoothedParticles()),
               hist = shifted(a.history(3));
    const auto est = a.estimate();
    a.translate(dx, dy);
    EXPECT_LT(maxDiff(a.particles(), cur), 1e-6);
    EXPECT_LT(maxDiff(a.smoothedParticles(), sm), 1e-6);
    EXPECT_LT(maxDiff(a.history(3), hist), 1e-6);
    EXPECT_NEAR(a.estimate().mean.x, est.mean.x + dx, 1e-6);
    EXPECT_NEAR(a.estimate().mean.y, est.mean.y + dy, 1e-6);
    EXPECT_NEAR(a.estimate().cov(0, 0), est.cov(0, 0), 1e-9);
    // The same move through moveStates, then the same updates: the same
    // states to within the grid.
    b.moveStates([&](size_t, const TPoint2D& q) { return TPoint2D(q.x + dx, q.y + dy); });
    rngB = rng;
    const auto likeMoved = [&](const TPoint2D& q) { return like({q.x - dx, q.y - dy}); };
    for (int k = 0; k < 3; k++) {
        a.update(likeMoved, rng);
        b.update(likeMoved, rngB);
    }
    EXPECT_LT(maxDiff(a.particles(), b.particles()), 1e-5);
}

TEST(TagEstimators, StateRoundTripContinuesIdentically) {
    for (const char* name : {kParticleFilterName, kFixedLagSmootherName}) {
        TTagEstimatorParams p;
        p.essThreshold = 0.5;
        auto a = createTagEstimator(name, p);
        TRandom rng(3);
        a->initUniform({0, 0, 0.2}, {0.1, 0, 0.15, 0.15}, rng);
        const auto like = [](const TPoint2D& q) { return -q.x * q.x * 50; };
        for (int k = 0; k < 30; k++) a->update(like, rng);
        mrpt::io::CMemoryStream buf;
        auto out = mrpt::serialization::archiveFrom(buf);
        a->writeState(out);
        buf.Seek(0);
        auto b = createTagEstimator(name, {});
        auto in = mrpt::serialization::archiveFrom(buf);
        b->readState(in);
        TRandom r1(9), r2(9);
        for (int k = 0; k < 30; k++) a->update(like, r1), b->update(like, r2);
        EXPECT_EQ(maxDiff(a->smoothedParticles(), b->smoothedParticles()), 0.0) << name;
        EXPECT_EQ(a->estimate().mean.x, b->estimate().mean.x) << name;
    }
}

TEST(TagFixedLagSmoother, LegacyWholeHistoryStateKeepsItsSmoothedSet) {
    // A version 0-2 state: 3 particles, lag 4, ring head 1, 4 stored states.
    TagFixedLagSmootherParams p;
    p.lag = 4;
    std::vector<TPoint2D> hist, pts;
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 4; k++) hist.push_back({j + 0.01 * k, -0.02 * k});
    for (int j = 0; j < 3; j++) pts.push_back(hist[j * 4 + 0]);  // newest: slot head-1
    TagFixedLagSmoother ps;
    ps.setLegacyState(p, pts, hist, 1, 4, 9);
    for (int j = 0; j < 3; j++) {
        EXPECT_NEAR(ps.smoothedParticles()[j].x, j + 0.015, 2e-6);
        EXPECT_NEAR(ps.smoothedParticles()[j].y, -0.03, 2e-6);
    }
    EXPECT_THROW(ps.setLegacyState(p, pts, hist, 4, 4, 9), std::invalid_argument);
}

namespace {
/** Bytes per mapped tag of a map built by insertion: a lawn-mower pass over a
 * tag grid with the 8-reader ring, so every tag is read several times. */
double bytesPerTag(const std::string& estimator, size_t& tags) {
    rfir::maps::CRFIDTagParticleMap m;
    m.insertionOptions.estimator = estimator;
    m.insertionOptions.params.numParticles = 100;
    m.insertionOptions.params.lag = 25;
    const auto grid = tagmaps_test::grid(12, 0.25);
    const auto readers = tagmaps_test::ring(0.03);
    const auto poses = tagmaps_test::lawnmower(-0.2, 3.0, -0.2, 3.0, 0.07, 0.02);
    for (const auto& q : poses) {
        const auto o = tagmaps_test::sense(readers, grid, q);
        m.insertObservation(*o, mrpt::poses::CPose3D(mrpt::poses::CPose2D(q)));
    }
    tags = m.tagCount();
    return double(m.memoryBytes()) / double(tags);
}
}  // namespace

TEST(TagMapMemory, BytesPerMappedTag) {
    size_t nPs = 0, nPf = 0;
    const double ps = bytesPerTag(kFixedLagSmootherName, nPs);
    const double pf = bytesPerTag(kParticleFilterName, nPf);
    std::printf(
        "[L = 100, lag 25] bytes per mapped tag: PS-SLAM %.0f (%zu tags), "
        "PF-SLAM %.0f (%zu tags)\n",
        ps, nPs, pf, nPf);
    EXPECT_GT(nPs, 100u);
    EXPECT_EQ(nPs, nPf);
    EXPECT_LE(ps, 8192);
    EXPECT_LE(pf, 2048);
    // The count is not trivially small: it holds the particles themselves.
    EXPECT_GT(ps, 100 * (8 + 16 + 8 + 25));
    EXPECT_GT(pf, 100 * 8);
}

TEST(TagMapIo, ReadsVersion2Streams) {
    // Maps written by the whole-history code (tests/data/tagmap_v2/README.md):
    // the estimates come back (the smoother's from the sums of its stored
    // states, to the storage quantum), and the maps keep mapping.
    rfir::maps::registerAllClasses();
    for (const std::string kind : {"pf", "ps"}) {
        const std::string base =
            std::string(RFIR_SOURCE_DIR) + "/tests/data/tagmap_v2/tagmap_v2_" + kind;
        rfir::maps::CRFIDTagParticleMap m;
        {
            mrpt::io::CFileInputStream f(base + ".bin");
            mrpt::serialization::archiveFrom(f) >> m;
        }
        ASSERT_EQ(m.tagCount(), 9u) << kind;
        EXPECT_EQ(m.insertionOptions.estimator,
                  kind == "pf" ? kParticleFilterName : kFixedLagSmootherName);
        std::ifstream want(base + ".txt");
        std::string line;
        size_t n = 0;
        while (std::getline(want, line)) {
            std::istringstream in(line);
            std::string rec, id;
            double x, y, sx, sy;
            if (!(in >> rec >> id >> x >> y >> sx >> sy) || rec != "tag") continue;
            const auto* t = m.getTag(id);
            ASSERT_NE(t, nullptr) << id;
            EXPECT_NEAR(t->estimate.mean.x, x, 2e-6) << kind << " " << id;
            EXPECT_NEAR(t->estimate.mean.y, y, 2e-6) << kind << " " << id;
            EXPECT_NEAR(std::sqrt(t->estimate.cov(0, 0)), sx, 2e-6) << kind << " " << id;
            EXPECT_EQ(t->particles().size(), 20u);
            n++;
        }
        EXPECT_EQ(n, 9u);
        const auto grid = tagmaps_test::grid(3, 0.25);
        const auto readers = tagmaps_test::ring(0.03);
        for (const auto& q : tagmaps_test::lawnmower(-0.2, 0.8, -0.2, 0.8, 0.07, 0.02))
            m.insertObservation(*tagmaps_test::sense(readers, grid, q),
                                mrpt::poses::CPose3D(mrpt::poses::CPose2D(q)));
        for (const auto& g : grid)
            EXPECT_LT(std::hypot(m.getTag(g.id)->estimate.mean.x - g.x,
                                 m.getTag(g.id)->estimate.mean.y - g.y),
                      0.03)
                << kind << " " << g.id;
    }
}
