/* CIREmitterMap: likelihood by hand, association modes, INI creation through
 * MRPT's map factory, emitter file errors, serialization. */
#include <rfir/maps/CIREmitterMap.h>
#include <rfir/obs/ir_codes.h>

#include "test_tmpdir.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace rfir::maps;
using rfir::obs::CObservationIRSignals;

namespace {
/** This process's folder, made on first use and removed when the process
 * ends. */
std::string tmpDir() {
    static const rfir_test::TmpDir d;
    return d.p.string();
}

std::string writeFile(const std::string& name, const std::string& text) {
    const std::string p = tmpDir() + "/" + name;
    std::ofstream(p) << text;
    return p;
}

// Two repeated "1" emitters 0.8 m apart and a unique "39" between them, 1.5 m
// up; receivers 0.3 m up (1.2 m below the emitters, the fit height).
const char* kEmitters =
    "# test map\n"
    "emitter 1 0.0 0.0 1.5\n"
    "emitter 1 0.8 0.0 1.5\n"
    "emitter 39 0.4 0.4 1.5\n";

CObservationIRSignals reading(const char* codes, double volts) {
    CObservationIRSignals o;
    CObservationIRSignals::TReading r;
    r.receiver.id = "R";
    r.receiver.x = 0.1;
    r.receiver.z = 0.3;
    r.codes = *rfir::ir::parseCodeList(codes);
    r.volts = volts;
    o.readings.push_back(r);
    return o;
}

double ll(const CIREmitterMap& m, const CObservationIRSignals& o, double x, double y) {
    return m.computeObservationLikelihood(o, mrpt::poses::CPose3D(x, y, 0, 0, 0, 0));
}
}  // namespace

TEST(IREmitterMap, UniqueReadingLikelihoodByHand) {
    CIREmitterMap m;
    m.likelihoodOptions.params.sigmaVolts = 0.1;
    m.loadEmitterFile(writeFile("a.txt", kEmitters));
    EXPECT_EQ(m.emitters().emitters().size(), 3u);
    EXPECT_EQ(m.emitters().uniqueEmitterCount(), 1u);
    EXPECT_TRUE(m.emitters().isUnambiguous("39"));
    EXPECT_FALSE(m.emitters().isUnambiguous("1"));
    // Receiver at (0.2, 0.4): d = 0.2, Vbar = 1.08297, sigma 0.1.
    EXPECT_NEAR(ll(m, reading("3,9", 1.0), 0.1, 0.4), -0.0068840209 / 0.02, 1e-9);
    // Two readings add up.
    auto two = reading("3,9", 1.0);
    two.readings.push_back(two.readings[0]);
    EXPECT_NEAR(ll(m, two, 0.1, 0.4), -2 * 0.0068840209 / 0.02, 1e-9);
    // Unknown ID, or no code: no information.
    EXPECT_EQ(ll(m, reading("5", 1.0), 0.1, 0.4), 0.0);
    auto none = reading("5", 1.0);
    none.readings[0].codes.clear();
    EXPECT_EQ(ll(m, none, 0.1, 0.4), 0.0);
}

TEST(IREmitterMap, RepeatedIdAssociationAgainstEstimate) {
    CIREmitterMap m;
    m.likelihoodOptions.params.sigmaVolts = 0.1;
    m.loadEmitterFile(writeFile("b.txt", kEmitters));
    const auto obs = reading("1", 1.77847);  // exactly Vbar at d = 0.1
    // No estimate yet: the thesis cannot compute eq. 5.1, the reading is skipped.
    EXPECT_EQ(ll(m, obs, 0.0, 0.0), 0.0);
    // Estimate near the second emitter: every particle is weighed against it.
    m.setAssociationReference(mrpt::math::TPose2D(0.6, 0, 0));
    EXPECT_NEAR(ll(m, obs, 0.6, 0.0), 0.0, 1e-9);  // receiver 0.1 m from it
    // A particle under the first emitter: receiver 0.7 m from the chosen one.
    EXPECT_NEAR(ll(m, obs, -0.1, 0.0), -1.77847 * 1.77847 / 0.02 - 8, 1e-6);
    // Per-particle association: that particle takes its own nearest emitter.
    m.likelihoodOptions.association = CIREmitterMap::TAssociation::Particle;
    EXPECT_NEAR(ll(m, obs, -0.1, 0.0), -(1.81997 - 1.77847) * (1.81997 - 1.77847) / 0.02,
                1e-9);
    EXPECT_NEAR(ll(m, obs, 0.6, 0.0), 0.0, 1e-9);
    EXPECT_EQ(*m.associate(obs.readings[0], {0, 0, 0}), 0u);
    EXPECT_EQ(*m.associate(obs.readings[0], {0.6, 0, 0}), 1u);
}

TEST(IREmitterMap, VerticalDistance) {
    CIREmitterMap m;
    m.loadEmitterFile(writeFile("c.txt", kEmitters));
    auto& o = m.likelihoodOptions;
    o.params.curve.heightModel = rfir::ir::TVoltageCurve::HeightModel::Angular;
    rfir::obs::TIRReceiver r;
    r.z = 0.5;  // 1.0 m below the emitters
    EXPECT_NEAR(m.verticalDistance(m.emitters().emitters()[0], r), 1.0, 1e-12);
    o.verticalDistance = 1.25;
    EXPECT_NEAR(m.verticalDistance(m.emitters().emitters()[0], r), 1.25, 1e-12);
}

TEST(IREmitterMap, CreatedFromIniLikeMrptMaps) {
    writeFile("ini_emitters.txt", kEmitters);
    const std::string ini = writeFile("map.ini",
                                      "[MetricMap]\n"
                                      "irEmitterMap_count = 1\n"
                                      "[MetricMap_irEmitterMap_00_creationOpts]\n"
                                      "emitter_file = ini_emitters.txt\n"
                                      "[MetricMap_irEmitterMap_00_likelihoodOpts]\n"
                                      "sigma_volts = 0.2\n"
                                      "association = particle\n"
                                      "curve_c2 = -30.0\n");
    mrpt::config::CConfigFile cfg(ini);
    mrpt::maps::TSetOfMetricMapInitializers inits;
    inits.loadFromConfigFile(cfg, "MetricMap");
    ASSERT_EQ(inits.size(), 1u);
    mrpt::maps::CMultiMetricMap mm;
    mm.setListOfMaps(inits);
    const auto m = mm.mapByClass<CIREmitterMap>();
    ASSERT_TRUE(m);
    EXPECT_EQ(m->emitters().emitters().size(), 3u);
    EXPECT_EQ(m->likelihoodOptions.params.sigmaVolts, 0.2);
    EXPECT_EQ(m->likelihoodOptions.params.curve.c2, -30.0);
    EXPECT_EQ(m->likelihoodOptions.association, CIREmitterMap::TAssociation::Particle);
    // The multi-map sums its maps' likelihoods: ours through MRPT's path.
    const auto obs = reading("3,9", 1.0);
    const double vbar = -30.0 * 0.04 + 2.855 * 0.2 + 1.81997;
    EXPECT_NEAR(
        mm.computeObservationLikelihood(obs, mrpt::poses::CPose3D(0.1, 0.4, 0, 0, 0, 0)),
        -(1.0 - vbar) * (1.0 - vbar) / (2 * 0.04), 1e-9);
}

TEST(IREmitterMap, IniRejectsUnknownKey) {
    const std::string ini = writeFile("bad.ini",
                                      "[MetricMap]\n"
                                      "irEmitterMap_count = 1\n"
                                      "[MetricMap_irEmitterMap_00_likelihoodOpts]\n"
                                      "sigma_volt = 0.2\n");
    mrpt::config::CConfigFile cfg(ini);
    mrpt::maps::TSetOfMetricMapInitializers inits;
    // Raised when the map is created (MRPT leaks a definition that throws).
    EXPECT_NO_THROW(inits.loadFromConfigFile(cfg, "MetricMap"));
    try {
        const mrpt::maps::CMultiMetricMap mm(inits);
        FAIL() << "no error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("sigma_volt: unknown key"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("MetricMap_irEmitterMap_00_likelihoodOpts"),
                  std::string::npos)
            << e.what();
    }
}

TEST(IREmitterMap, BadEmitterFileNamesFileAndLine) {
    auto expectError = [](const std::string& text, const std::string& what) {
        const std::string p = writeFile("bad_emitters.txt", text);
        try {
            rfir::ir::TEmitterSet::load(p);
            FAIL() << "no error for: " << what;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    };
    const std::string f = tmpDir() + "/bad_emitters.txt";
    expectError("emitter 1 0 0 1.5\n\nemitter 93 0.4 0.4 1.5\n",
                f + ":3: emitter ID '93' is not an ascending set");
    expectError("emitter 39 0 0 1.5\nemitter 39 1 1 1.5\n",
                f + ":2: duplicate emitter ID");
    expectError("emitter 1 0 0\n", f + ":1:");
    expectError("emitter 1 0 zero 1.5\n", f + ":1:");
    expectError("emitter 0 0 0 1.5\n", f + ":1: emitter ID '0'");
    expectError("tag A 0 0\n", f + ": no emitter");
    expectError("emitter 1 0 0 1.5\nemitter 1 0.8 0 1.5\nemitter 2x 1 1 1\n", f + ":3:");
}

TEST(IREmitterMap, SerializationRoundTrip) {
    CIREmitterMap m;
    m.loadEmitterFile(writeFile("d.txt", kEmitters));
    auto& p = m.likelihoodOptions.params;
    p.sigmaVolts = 0.07;
    // Every field of versions 1-3, away from its default, so that a read order
    // that differs from the write order fails.
    p.missLogLik = -1.5;
    p.missRadiusFraction = 0.6;
    p.areaMargin = 0.35;
    p.outOfAreaLogLik = -3.25;
    p.outOfRangeRamp = 0.125;
    m.likelihoodOptions.association = CIREmitterMap::TAssociation::Particle;
    m.setAssociationReference(mrpt::math::TPose2D(1, 2, 0.5));
    mrpt::io::CMemoryStream buf;
    auto ar = mrpt::serialization::archiveFrom(buf);
    ar << m;
    buf.Seek(0);
    CIREmitterMap b;
    ar >> b;
    EXPECT_EQ(b.emitters().emitters().size(), 3u);
    EXPECT_EQ(b.emitters().emitters()[2].id, "39");
    const auto& q = b.likelihoodOptions.params;
    EXPECT_EQ(q.sigmaVolts, 0.07);
    EXPECT_EQ(q.missLogLik, -1.5);
    EXPECT_EQ(q.missRadiusFraction, 0.6);
    EXPECT_EQ(q.areaMargin, 0.35);
    EXPECT_EQ(q.outOfAreaLogLik, -3.25);
    EXPECT_EQ(q.outOfRangeRamp, 0.125);
    EXPECT_EQ(b.likelihoodOptions.association, CIREmitterMap::TAssociation::Particle);
    ASSERT_TRUE(b.associationReference());
    EXPECT_EQ(b.associationReference()->y, 2.0);
    const auto obs = reading("1", 1.2);
    EXPECT_EQ(ll(m, obs, 0.3, 0.1), ll(b, obs, 0.3, 0.1));
}
