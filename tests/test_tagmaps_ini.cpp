// CRFIDTagParticleMap: creation from INI text, rejected options, serialization
// round trips (direct and through CMultiMetricMap copies), text and 3D output.
#include "test_tagmaps_sim.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace tagmaps_test;
using rfir::maps::CRFIDTagParticleMap;

namespace {
const char* kIni = R"(
[MappingApplication]
rfidTagMap_count = 1

[MappingApplication_rfidTagMap_00_insertOpts]
estimator = fixed_lag_smoother
num_particles = 64
lag = 20
smoother_step_sigma = 0.004
resampling = stratified
seed = 77

[MappingApplication_rfidTagMap_00_likelihoodOpts]
detection_model = gaussian
gaussian_sigma_scale = 1.5
robot_update = revisit_all
revisit_min_gap = 3
rb_sigma_bearing_deg = 2
)";

std::string loadError(const std::string& section, const std::string& line) {
    std::string ini = std::string("[M]\nrfidTagMap_count=1\n[M_rfidTagMap_00_") +
                      section + "]\n" + line + "\n";
    mrpt::config::CConfigFileMemory cfg(ini);
    mrpt::maps::TSetOfMetricMapInitializers defs;
    // The definition keeps a refused value and the map's creation raises it:
    // MRPT leaks a definition whose loading throws.
    EXPECT_NO_THROW(defs.loadFromConfigFile(cfg, "M")) << line;
    try {
        const mrpt::maps::CMultiMetricMap mm(defs);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "no error";
}
}  // namespace

TEST(TagMapIni, CreatedThroughMultiMetricMap) {
    rfir::maps::registerAllClasses();
    mrpt::config::CConfigFileMemory cfg(kIni);
    mrpt::maps::TSetOfMetricMapInitializers defs;
    defs.loadFromConfigFile(cfg, "MappingApplication");
    ASSERT_EQ(defs.size(), 1u);
    mrpt::maps::CMultiMetricMap mm(defs);
    auto m = mm.mapByClass<CRFIDTagParticleMap>();
    ASSERT_TRUE(m);
    const auto& io = m->insertionOptions;
    EXPECT_EQ(io.estimator, rfir::models::kFixedLagSmootherName);
    EXPECT_EQ(io.params.numParticles, 64u);
    EXPECT_EQ(io.params.lag, 20u);
    EXPECT_DOUBLE_EQ(io.params.stepSigma, 0.004);
    EXPECT_EQ(io.params.resampling, rfir::models::ResamplingScheme::Stratified);
    EXPECT_EQ(io.seed, 77u);
    const auto& lo = m->likelihoodOptions;
    EXPECT_EQ(lo.detection.model, rfir::models::DetectionModel::Gaussian);
    EXPECT_DOUBLE_EQ(lo.detection.gaussianSigmaScale, 1.5);
    EXPECT_EQ(lo.robotUpdate, rfir::maps::TRobotUpdatePolicy::RevisitAll);
    EXPECT_EQ(lo.revisitMinGap, 3u);
    EXPECT_NEAR(lo.rangeBearing.sigmaBearing, 2 * M_PI / 180, 1e-12);
    EXPECT_FALSE(m->updateTagsBeforeWeighing());
    std::ostringstream dump;
    defs.dumpToTextStream(dump);
    EXPECT_NE(dump.str().find("fixed_lag_smoother"), std::string::npos);
    // The map works from the multi-map too.
    mm.insertObservation(*sense(ring(0.03), grid(2, 0.25), {0.163, 0.027, 0}),
                         pose3({0.163, 0.027, 0}));
    EXPECT_GT(m->tagCount(), 0u);
}

TEST(TagMapIni, BadOptionsAreRejectedNamingTheKey) {
    struct Case {
        const char* section;
        const char* line;
        const char* key;
    };
    const Case cases[] = {
        {"insertOpts", "num_particles = 0", "num_particles"},
        {"insertOpts", "num_particles = -5", "num_particles"},
        {"insertOpts", "lag = 0", "lag"},
        {"insertOpts", "lag = 2.5", "lag"},
        {"insertOpts", "estimator = kalman", "estimator"},
        {"insertOpts", "resampling = residual", "resampling"},
        {"insertOpts", "num_particle = 10", "num_particle"},
        {"insertOpts", "smoother_step_sigma = -1", "smoother_step_sigma"},
        {"likelihoodOpts", "detection_model = box", "detection_model"},
        {"likelihoodOpts", "robot_update = sometimes", "robot_update"},
        {"likelihoodOpts", "beta = 0", "beta"},
        {"likelihoodOpts", "revisit_min_gap = 0", "revisit_min_gap"},
        {"likelihoodOpts", "revisit_min_travel = -0.1", "revisit_min_travel"},
        {"likelihoodOpts", "robot_likelihood_k = 65", "robot_likelihood_k"},
        {"likelihoodOpts", "robotupdate = literal", "robotupdate"},
        {"insertOpts", "tag_robot_pose = median", "tag_robot_pose"},
        {"insertOpts", "spread_commit_travel = -1", "spread_commit_travel"},
        {"likelihoodOpts", "robot_likelihood = tags", "robot_likelihood"},
        {"likelihoodOpts", "robot_likelihood_k = 0", "robot_likelihood_k"},
    };
    for (const auto& c : cases) {
        const std::string err = loadError(c.section, c.line);
        EXPECT_NE(err.find(c.key), std::string::npos) << c.line << " -> " << err;
        EXPECT_NE(err.find(c.section), std::string::npos) << c.line << " -> " << err;
    }
    EXPECT_EQ(loadError("insertOpts", "num_particles = 7"), "no error");
}

namespace {
void buildMap(CRFIDTagParticleMap& m, const std::string& kind, double x1) {
    m.insertionOptions.estimator = kind;
    m.insertionOptions.params.numParticles = 40;
    m.insertionOptions.params.lag = 7;
    m.setLandmarkNames({"a", "b"});
    const auto tags = grid(3, 0.25);
    for (const auto& p : lawnmower(0.0, x1, 0.0, 0.5, 0.1, 0.02))
        m.insertObservation(*sense(ring(0.05), tags, p), pose3(p));
}

void expectSame(const CRFIDTagParticleMap& a, const CRFIDTagParticleMap& b) {
    ASSERT_EQ(a.tagCount(), b.tagCount());
    const auto ta = a.tags(), tb = b.tags();
    for (size_t i = 0; i < ta.size(); i++) {
        EXPECT_EQ(ta[i]->id, tb[i]->id);
        EXPECT_EQ(ta[i]->detections, tb[i]->detections);
        EXPECT_EQ(ta[i]->visits, tb[i]->visits);
        EXPECT_EQ(ta[i]->lastReadStep, tb[i]->lastReadStep);
        EXPECT_EQ(ta[i]->lastReadTravel, tb[i]->lastReadTravel);
        EXPECT_EQ(ta[i]->estimate.mean.x, tb[i]->estimate.mean.x);
        EXPECT_EQ(ta[i]->estimate.cov(0, 1), tb[i]->estimate.cov(0, 1));
        const auto &pa = ta[i]->particles(), &pb = tb[i]->particles();
        ASSERT_EQ(pa.size(), pb.size());
        for (size_t k = 0; k < pa.size(); k++) {
            EXPECT_EQ(pa[k].x, pb[k].x);
            EXPECT_EQ(pa[k].y, pb[k].y);
        }
        EXPECT_STREQ(ta[i]->estimator->name(), tb[i]->estimator->name());
    }
    EXPECT_EQ(a.landmarkNames(), b.landmarkNames());
}
}  // namespace

TEST(TagMapIo, SerializationRoundTripIsExactAndContinuesIdentically) {
    for (auto kind :
         {rfir::models::kParticleFilterName, rfir::models::kFixedLagSmootherName}) {
        CRFIDTagParticleMap a;
        a.likelihoodOptions.robotUpdate = rfir::maps::TRobotUpdatePolicy::Revisit;
        a.insertionOptions.params.rougheningSigma = 0.001;
        a.likelihoodOptions.revisitMinTravel = 0.05;
        a.likelihoodOptions.robotLikelihood = rfir::maps::TRobotLikelihood::TagParticles;
        a.likelihoodOptions.robotLikelihoodK = 5;
        buildMap(a, kind, 0.6);
        mrpt::io::CMemoryStream buf;
        mrpt::serialization::archiveFrom(buf) << a;
        buf.Seek(0);
        CRFIDTagParticleMap b;
        mrpt::serialization::archiveFrom(buf) >> b;
        expectSame(a, b);
        EXPECT_EQ(b.insertionOptions.estimator, kind);
        EXPECT_EQ(b.insertionOptions.params.lag, 7u);
        EXPECT_EQ(b.insertionOptions.params.rougheningSigma, 0.001);
        EXPECT_EQ(b.likelihoodOptions.robotUpdate,
                  rfir::maps::TRobotUpdatePolicy::Revisit);
        EXPECT_EQ(b.likelihoodOptions.robotLikelihoodK, 5u);
        EXPECT_EQ(b.tags().front()->sample, a.tags().front()->sample);
        // Both copies continue identically (per-step generators from the seed).
        const auto tags = grid(3, 0.25);
        for (const auto& p : lawnmower(0.0, 0.6, 0.05, 0.5, 0.1, 0.03)) {
            const auto o = sense(ring(0.05), tags, p);
            EXPECT_EQ(a.computeObservationLikelihood(*o, pose3(p)),
                      b.computeObservationLikelihood(*o, pose3(p)));
            a.insertObservation(*o, pose3(p));
            b.insertObservation(*o, pose3(p));
        }
        expectSame(a, b);
    }
}

TEST(TagMapIo, MultiMetricMapCopyKeepsTheMap) {
    rfir::maps::registerAllClasses();
    mrpt::config::CConfigFileMemory cfg(kIni);
    mrpt::maps::TSetOfMetricMapInitializers defs;
    defs.loadFromConfigFile(cfg, "MappingApplication");
    mrpt::maps::CMultiMetricMap mm(defs);
    buildMap(*mm.mapByClass<CRFIDTagParticleMap>(), rfir::models::kFixedLagSmootherName,
             0.4);
    const mrpt::maps::CMultiMetricMap copy(mm);  // copies by serialization
    auto a = mm.mapByClass<CRFIDTagParticleMap>();
    auto b = copy.mapByClass<CRFIDTagParticleMap>();
    ASSERT_TRUE(b);
    EXPECT_NE(a.get(), b.get());
    expectSame(*a, *b);
}

TEST(TagMapIo, TextFileAndVisualization) {
    CRFIDTagParticleMap m;
    buildMap(m, rfir::models::kParticleFilterName, 0.6);
    const std::string prefix = std::string(RFIR_BINARY_DIR) + "/test_tagmaps_out";
    m.saveMetricMapRepresentationToFile(prefix);
    std::ifstream f(prefix + "_tags.txt");
    ASSERT_TRUE(f.good());
    std::string line;
    size_t n = 0;
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ss(line);
        std::string kind, id;
        double x, y, sx, sy;
        ASSERT_TRUE(static_cast<bool>(ss >> kind >> id >> x >> y >> sx >> sy)) << line;
        EXPECT_EQ(kind, "tag");
        const auto* t = m.getTag(id);
        ASSERT_NE(t, nullptr) << id;
        EXPECT_NEAR(x, t->estimate.mean.x, 1e-8);
        EXPECT_NEAR(sy, std::sqrt(t->estimate.cov(1, 1)), 1e-8);
        n++;
    }
    EXPECT_EQ(n, m.tagCount());
    std::remove((prefix + "_tags.txt").c_str());
    mrpt::opengl::CSetOfObjects scene;
    m.getVisualizationInto(scene);
    EXPECT_EQ(scene.size(), m.tagCount() + 2 + 2);  // ellipses + 2 clouds per kind
    EXPECT_NE(m.asString().find("tags"), std::string::npos);
}
