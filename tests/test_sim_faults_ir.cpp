// The simulator's IR faults (docs/simulator.md, "Faults"): failed emitters
// are never seen, wrong codes and voltage outliers come at their rates and are
// the only differences from the clean run, a moved emitter is moved in the
// localizer's map only; fault runs are deterministic.
#include <rfir/common/map_io.h>
#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/ir_codes.h>
#include <rfir/sim/simulator.h>
#include <cstddef>  // before ir_codes.h

#include "test_tmpdir.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

using namespace rfir::sim;
namespace fs = std::filesystem;

namespace {
TSimConfig stock(const std::string& name, const std::vector<std::string>& sets = {}) {
    return loadSimConfig(std::string(RFIR_SOURCE_DIR) + "/config_ini/" + name + ".ini",
                         sets);
}

using TReading = rfir::obs::CObservationIRSignals::TReading;

/** IR readings by (step, receiver). */
std::map<std::pair<size_t, std::string>, TReading> irOf(const TSimOutput& out) {
    std::map<std::pair<size_t, std::string>, TReading> m;
    for (size_t k = 0; k < out.steps.size(); k++)
        for (const auto& o : out.steps[k].obs)
            if (auto ir = std::dynamic_pointer_cast<rfir::obs::CObservationIRSignals>(o))
                for (const auto& rd : ir->readings) m[{k, rd.receiver.id}] = rd;
    return m;
}

/** Records "kind t receiver a b", keyed by "t receiver". */
std::map<std::pair<std::string, std::string>, std::pair<std::string, std::string>>
irRecords(const TSimOutput& out, const std::string& kind) {
    std::map<std::pair<std::string, std::string>, std::pair<std::string, std::string>> m;
    for (const auto& line : out.faults) {
        std::istringstream is(line);
        std::string k, t, rx, a, b;
        if (is >> k >> t >> rx >> a >> b && k == kind) m[{t, rx}] = {a, b};
    }
    return m;
}

std::string number(double v) {
    for (int p = 15;; p++) {
        std::ostringstream o;
        o << std::setprecision(p) << v;
        if (p == 17 || std::stod(o.str()) == v) return o.str();
    }
}

void expectBinomial(size_t k, size_t n, double p) {
    const double sd = std::sqrt(n * p * (1 - p));
    EXPECT_LT(std::abs(double(k) - n * p), 4.5 * sd) << k << " of " << n << " at " << p;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}
}  // namespace

TEST(SimFaultsIR, FailedEmittersAreNeverSeen) {
    auto cfg = stock("sim_faults_ir_failed");
    ASSERT_EQ(cfg.ir.failed.size(), 2u);
    const auto out = simulate(cfg, 1);
    EXPECT_EQ(out.failedEmitters.size(), 2u);
    cfg.ir.failed.clear();
    const auto clean = simulate(cfg, 1);
    auto seen = [](const TSimOutput& o) {
        std::set<std::string> ids;
        for (const auto& [k, rd] : irOf(o))
            if (!rd.codes.empty()) ids.insert(rfir::ir::emitterIdFromCodes(rd.codes));
        return ids;
    };
    const auto ids = seen(out), cleanIds = seen(clean);
    for (const char* id : {"13", "19"}) {
        EXPECT_EQ(ids.count(id), 0u) << id;
        EXPECT_EQ(cleanIds.count(id), 1u) << id;  // under the path
    }
}

// Wrong codes: exactly the recorded readings differ from the clean run, at the
// configured rate; about half spell another emitter's ID; voltages untouched.
TEST(SimFaultsIR, WrongCodesAtTheirRate) {
    const auto cfg = stock("sim_faults_ir_wrong_codes", {"ir.wrong_code_rate=0.05"});
    const auto out = simulate(cfg, 2);
    auto cleanCfg = cfg;
    cleanCfg.ir.wrongCodeRate = 0;
    const auto clean = simulate(cleanCfg, 2);
    std::set<std::string> lattice;
    for (const auto& e : out.gtMap)
        if (e.kind == rfir::common::TMapEntry::Kind::Emitter) lattice.insert(e.id);
    const auto rec = irRecords(out, "wrong_code");
    const auto a = irOf(out), b = irOf(clean);
    ASSERT_EQ(a.size(), b.size());
    size_t inView = 0, wrong = 0, otherId = 0;
    for (const auto& [key, rd] : a) {
        const auto& c = b.at(key);
        EXPECT_EQ(rd.volts, c.volts);
        if (c.codes.empty()) continue;
        inView++;
        if (rd.codes == c.codes) continue;
        wrong++;
        auto it = rec.find({number(out.steps[key.first].t), key.second});
        ASSERT_NE(it, rec.end()) << out.steps[key.first].t;
        EXPECT_EQ(it->second.first, rfir::ir::emitterIdFromCodes(c.codes));
        EXPECT_EQ(it->second.second, rfir::ir::emitterIdFromCodes(rd.codes));
        otherId += lattice.count(it->second.second);
    }
    EXPECT_EQ(wrong, rec.size());
    expectBinomial(wrong, inView, 0.05);
    EXPECT_GT(double(otherId), 0.4 * double(wrong));
}

TEST(SimFaultsIR, VoltageOutliersAtTheirRate) {
    const auto cfg = stock("sim_faults_ir_volt_outliers", {"ir.volt_outlier_rate=0.05"});
    const auto out = simulate(cfg, 3);
    auto cleanCfg = cfg;
    cleanCfg.ir.voltOutlierRate = 0;
    const auto clean = simulate(cleanCfg, 3);
    const auto rec = irRecords(out, "volt_outlier");
    const auto a = irOf(out), b = irOf(clean);
    ASSERT_EQ(a.size(), b.size());
    size_t inView = 0, outliers = 0;
    for (const auto& [key, rd] : a) {
        const auto& c = b.at(key);
        EXPECT_EQ(rd.codes, c.codes);
        if (c.codes.empty()) continue;
        inView++;
        if (rd.volts == c.volts) continue;
        outliers++;
        auto it = rec.find({number(out.steps[key.first].t), key.second});
        ASSERT_NE(it, rec.end());
        EXPECT_EQ(std::stod(it->second.first), c.volts);
        EXPECT_EQ(std::stod(it->second.second), rd.volts);
        EXPECT_GE(rd.volts, 0);
        EXPECT_LE(rd.volts, cfg.ir.voltOutlierMax);
    }
    EXPECT_EQ(outliers, rec.size());
    expectBinomial(outliers, inView, 0.05);
}

// A moved emitter: the localizer's map (NAME.map.txt) has it 0.25 m off, the
// truth where it is; both files and the fault records are written, and the
// same seed gives the same bytes.
TEST(SimFaultsIR, MovedEmitterAndDeterministicFiles) {
    auto cfg = stock("sim_faults_ir_combined");
    cfg.maxDuration = 30;
    const rfir_test::TmpDir d;
    writeOutputs(simulate(cfg, 4), (d.p / "a").string(), "run");
    writeOutputs(simulate(cfg, 4), (d.p / "b").string(), "run");
    for (const char* f : {"run.rawlog", "run.gt.tum", "run.gt_map.txt", "run.map.txt",
                          "run.gt_faults.txt", "run.spots.tum"}) {
        ASSERT_TRUE(fs::exists(d.p / "a" / f)) << f;
        EXPECT_TRUE(slurp(d.p / "a" / f) == slurp(d.p / "b" / f)) << f;
    }
    const auto truth = rfir::common::loadMapFile((d.p / "a" / "run.gt_map.txt").string());
    const auto given = rfir::common::loadMapFile((d.p / "a" / "run.map.txt").string());
    ASSERT_EQ(truth.size(), given.size());
    size_t moved = 0;
    for (size_t i = 0; i < truth.size(); i++) {
        ASSERT_EQ(truth[i].id, given[i].id);
        if (truth[i].x == given[i].x && truth[i].y == given[i].y) continue;
        moved++;
        EXPECT_EQ(truth[i].id, "14");
        EXPECT_NEAR(given[i].x - truth[i].x, 0.25, 1e-6);
        EXPECT_NEAR(given[i].y - truth[i].y, 0, 1e-6);
    }
    EXPECT_EQ(moved, 1u);
    const std::string faults = slurp(d.p / "a" / "run.gt_faults.txt");
    EXPECT_NE(faults.find("moved_emitter 14 2 0.4 2.25 0.4\n"), std::string::npos);
    EXPECT_NE(faults.find("failed_emitter 13 1.2 0.4\n"), std::string::npos);
    // A clean run writes neither extra file.
    cfg = stock("sim_ir_loop");
    cfg.maxDuration = 5;
    writeOutputs(simulate(cfg, 4), (d.p / "c").string(), "run");
    EXPECT_FALSE(fs::exists(d.p / "c" / "run.map.txt"));
    EXPECT_FALSE(fs::exists(d.p / "c" / "run.gt_faults.txt"));
    EXPECT_THROW(simulate(stock("sim_faults_ir_moved", {"ir.moved=1.9 0.1 0.2 0"}), 1),
                 std::invalid_argument);
}
