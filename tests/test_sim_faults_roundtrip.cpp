// Every stock fault simulation (config_ini/sim_faults_*.ini, whole runs, so
// that the late faults are in) goes to the text log and back, as rfir-import
// does, with the same bytes and without --lossy; the faults are visible in the
// text; the event-driven timing survives a kidnapping.
#include <rfir/sim/simulator.h>

#include "test_import_util.h"

#include <map>
#include <set>

using namespace rfir::common;
using rfir_test::TmpDir;

namespace {
/** Simulates, writes, exports (strict), imports: the same rawlog bytes.
 * Returns the text log. */
std::string roundTrip(const rfir::sim::TSimConfig& cfg, uint64_t seed) {
    TmpDir d;
    rfir::sim::writeOutputs(rfir::sim::simulate(cfg, seed), d.p.string(), "s");
    const auto rep = convertRawlogToTextLog(d / "s.rawlog", d / "s.txt");
    EXPECT_TRUE(rep.dropped.empty());
    convertTextLogToRawlog(d / "s.txt", d / "back.rawlog");
    EXPECT_EQ(rfir_test::compareRawlogs(d / "s.rawlog", d / "back.rawlog"), "");
    EXPECT_TRUE(rfir_test::gunzip(d / "s.rawlog") == rfir_test::gunzip(d / "back.rawlog"))
        << "the rawlogs differ byte for byte";
    return rfir_test::slurp(d / "s.txt");
}

rfir::sim::TSimConfig stock(const std::string& stem,
                            const std::vector<std::string>& sets = {}) {
    return rfir::sim::loadSimConfig(
        std::string(RFIR_SOURCE_DIR) + "/config_ini/" + stem + ".ini", sets);
}

/** Records of the text by kind: "rfid" -> lines. */
std::map<std::string, std::vector<std::vector<std::string>>> records(
    const std::string& text) {
    std::map<std::string, std::vector<std::vector<std::string>>> m;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::istringstream is(line);
        std::vector<std::string> f;
        for (std::string w; is >> w;) f.push_back(w);
        if (!f.empty()) m[f[0]].push_back(f);
    }
    return m;
}
}  // namespace

TEST(SimFaultsRoundTrip, EveryStockFaultSimulation) {
    std::vector<std::string> inis;
    for (const auto& e :
         fs::directory_iterator(std::string(RFIR_SOURCE_DIR) + "/config_ini")) {
        const std::string n = e.path().stem().string();
        if (n.rfind("sim_faults_", 0) == 0 && e.path().extension() == ".ini")
            inis.push_back(n);
    }
    std::sort(inis.begin(), inis.end());
    ASSERT_GE(inis.size(), 11u);
    for (const auto& n : inis) {
        SCOPED_TRACE(n);
        const auto cfg = stock(n);
        const auto text = roundTrip(cfg, 2);
        const auto rec = records(text);
        if (n == "sim_faults_combined" || n == "sim_faults_dead_reader") {
            // The dead reader's empty polls are in the text: "rfid t R3".
            const std::string dead = cfg.readers[cfg.rfid.deadReaders[0].reader].id;
            const double from = cfg.startTime + cfg.rfid.deadReaders[0].from;
            const double to = cfg.startTime + cfg.rfid.deadReaders[0].to;
            size_t emptyDead = 0, readDead = 0;
            for (const auto& r : rec.at("rfid")) {
                const double t = std::stod(r[1]);
                if (r[2] != dead || t < from || t >= to) continue;
                (r.size() == 3 ? emptyDead : readDead)++;
            }
            EXPECT_EQ(readDead, 0u);
            EXPECT_GT(emptyDead, 500u);
        }
        if (n == "sim_faults_async") {
            // Odometry and polls at their own times: one reader per record.
            std::set<std::string> odoT, rfidT;
            for (const auto& r : rec.at("odom")) odoT.insert(r[1]);
            for (const auto& r : rec.at("rfid")) rfidT.insert(r[1]);
            EXPECT_GT(odoT.size(), 4000u);
            EXPECT_GT(rfidT.size(), 7000u);
            size_t shared = 0;
            for (const auto& t : rfidT) shared += odoT.count(t);
            EXPECT_LT(shared, rfidT.size() / 5);
        }
    }
}

// Event-driven timing with a kidnapping, odometry stopped while carried, and
// a wrong-code raw IR run: still text and back.
TEST(SimFaultsRoundTrip, AsyncKidnapAndRawIR) {
    auto k = stock("sim_kidnap", {"odometry.rate=25", "odometry.latency=0.03",
                                  "rfid.polling=round_robin", "rfid.poll_jitter=0.004",
                                  "kidnap.odometry=stop", "rfid.ghost_rate=0.01"});
    k.maxDuration = 130;
    roundTrip(k, 5);
    auto raw = stock("sim_ir_raw", {"ir.wrong_code_rate=0.05",
                                    "ir.volt_outlier_rate=0.05", "odometry.rate=20"});
    raw.maxDuration = 8;
    roundTrip(raw, 5);
}
