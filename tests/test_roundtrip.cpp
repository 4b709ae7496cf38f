// Every stock simulation (config_ini/sim_*.ini, shortened) survives
// rawlog -> text -> rawlog with identical observations and header, without
// --lossy; text -> rawlog -> text gives the same text; and the conventions
// the simulator shares with the import (docs/import.md) hold.
#include <rfir/sim/simulator.h>

#include "test_import_util.h"

#include <mrpt/obs/CObservationOdometry.h>

#include <iostream>
#include <set>

using namespace rfir::common;
using rfir_test::TmpDir;

namespace {
/** Every stock simulation INI, by stem. */
std::vector<std::string> stockSimInis() {
    std::vector<std::string> v;
    for (const auto& e :
         fs::directory_iterator(std::string(RFIR_SOURCE_DIR) + "/config_ini")) {
        const std::string n = e.path().filename().string();
        if (n.rfind("sim_", 0) == 0 && e.path().extension() == ".ini")
            v.push_back(e.path().stem().string());
    }
    std::sort(v.begin(), v.end());
    return v;
}

/** The rawlog's instants against the simulated steps, observation by
 * observation (steps with nothing are not written). */
void expectRawlogHoldsSteps(const std::string& rawlog, const rfir::sim::TSimOutput& out) {
    CRawlogReader r(rawlog);
    auto hdr = out.header;
    hdr.timestamp = r.header().timestamp;
    EXPECT_TRUE(sameSerialization(r.header(), hdr));
    TRawlogStep st;
    for (const auto& s : out.steps) {
        if (!s.odometry && s.obs.empty()) continue;
        ASSERT_TRUE(r.next(st)) << s.t;
        size_t k = 0;
        if (s.odometry) {
            auto od = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(
                st.sf->getObservationByIndex(k++));
            ASSERT_TRUE(od) << s.t;
            EXPECT_TRUE(sameSerialization(od->odometry, *s.odometry)) << s.t;
        }
        ASSERT_EQ(st.sf->size(), k + s.obs.size()) << s.t;
        for (const auto& o : s.obs)
            EXPECT_TRUE(sameSerialization(*st.sf->getObservationByIndex(k++), *o)) << s.t;
    }
    EXPECT_FALSE(r.next(st));
}

struct TCounts {
    size_t ir = 0, irDark = 0, irRaw = 0, rb = 0;
};

TCounts count(const std::string& rawlog) {
    TCounts c;
    CRawlogReader r(rawlog);
    TRawlogStep st;
    while (r.next(st)) {
        if (st.ir)
            for (const auto& rd : st.ir->readings) {
                c.ir++;
                c.irRaw += rd.hasRaw();
                c.irDark += rd.codes.empty() && !rd.hasRaw();
            }
        if (st.rb) c.rb += st.rb->sensedData.size();
    }
    return c;
}

/** Simulates, writes, exports (strict), imports, exports again: every step
 * must give back the same bytes. Returns what the log holds. */
TCounts roundTrip(const std::string& name, const std::vector<std::string>& sets) {
    SCOPED_TRACE(name);
    TmpDir d;
    const auto cfg = rfir::sim::loadSimConfig(
        std::string(RFIR_SOURCE_DIR) + "/config_ini/" + name + ".ini", sets);
    const auto out = rfir::sim::simulate(cfg, 3);
    rfir::sim::writeOutputs(out, d.p.string(), "s");
    expectRawlogHoldsSteps(d / "s.rawlog", out);

    const auto rep = convertRawlogToTextLog(d / "s.rawlog", d / "s.txt");  // not lossy
    EXPECT_TRUE(rep.dropped.empty());
    convertTextLogToRawlog(d / "s.txt", d / "back.rawlog");
    EXPECT_EQ(rfir_test::compareRawlogs(d / "s.rawlog", d / "back.rawlog"), "");
    EXPECT_TRUE(rfir_test::gunzip(d / "s.rawlog") == rfir_test::gunzip(d / "back.rawlog"))
        << "the rawlogs differ byte for byte";
    // text -> rawlog -> text
    convertRawlogToTextLog(d / "back.rawlog", d / "back.txt");
    EXPECT_TRUE(rfir_test::slurp(d / "s.txt") == rfir_test::slurp(d / "back.txt"));
    // The header names only landmarks of the map.
    std::set<std::string> mapIds;
    for (const auto& e : out.gtMap) mapIds.insert(e.id);
    for (const auto& n : out.header.rbLandmarkNames) EXPECT_TRUE(mapIds.count(n)) << n;
    return count(d / "back.rawlog");
}
}  // namespace

TEST(RoundTrip, EveryStockSimulationSurvivesTextAndBack) {
    const auto inis = stockSimInis();
    ASSERT_GE(inis.size(), 20u);
    TCounts all;
    for (const auto& n : inis) {
        // Raw IR windows (800 samples each) make long texts: fewer seconds.
        const std::string dur = n == "sim_ir_raw" ? "8" : "30";
        const auto c = roundTrip(n, {"simulation.max_duration=" + dur});
        if (c.ir || c.rb)
            std::cout << n << ": IR readings " << c.ir << " (nothing in view " << c.irDark
                      << ", raw " << c.irRaw << "), range-bearing measurements " << c.rb
                      << "\n";
        all.ir += c.ir, all.irDark += c.irDark, all.irRaw += c.irRaw, all.rb += c.rb;
    }
    std::cout << "IR readings " << all.ir << " (nothing in view " << all.irDark
              << ", raw " << all.irRaw << "), range-bearing measurements " << all.rb
              << "\n";
    // Each kind went through: negative IR readings survive the text.
    EXPECT_GT(all.irDark, 20u);
    EXPECT_GT(all.irRaw, 40u);
    EXPECT_GT(all.rb, 100u);
}

TEST(RoundTrip, KidnappingHeadingPiAndSlowIR) {
    // Carried with and without odometry records (a carried step with neither
    // is not written), a start facing -x (heading pi, which CPose2D would
    // store as -pi), IR read every third step.
    for (const char* odo : {"frozen", "stop"})
        roundTrip("sim_kidnap",
                  {"kidnap.time=6", "kidnap.to_time=2", "kidnap.carry_time=1.5",
                   std::string("kidnap.odometry=") + odo, "simulation.max_duration=12"});
    roundTrip("sim_rfid_60mm_16tags_loop",
              {"kidnap.enabled=true", "kidnap.time=0", "kidnap.odometry=stop",
               "kidnap.to_pose=1 1 0", "simulation.max_duration=5"});
    roundTrip("sim_rb_norotation",
              {"trajectory.start_phi_deg=180", "simulation.max_duration=10"});
    roundTrip("sim_rb_rotation",
              {"trajectory.rotation=spin", "simulation.max_duration=20"});
    roundTrip("sim_ir_loop", {"trajectory.start_phi_deg=180", "ir.period=0.3",
                              "simulation.max_duration=15"});
}

TEST(RoundTrip, ImportAddsTheDarkReceiversAfterTheOthers) {
    // At an instant with IR records, a declared receiver without one saw
    // nothing; the export writes no record for it.
    TmpDir d;
    {
        std::ofstream f(d / "a.txt");
        f << "format textlog 1\nreceiver A 0 0 0.3\nreceiver B 0 0.1 0.3\n"
             "receiver C 0 0.2 0.3\nodom 1 0 0 0\nir 1 C 4 1.5\nodom 2 0 0 0\n"
             "ir 2 B 1,2 1.25\nir 2 A 3 1\n";
    }
    convertTextLogToRawlog(d / "a.txt", d / "a.rawlog");
    CRawlogReader r(d / "a.rawlog");
    TRawlogStep st;
    ASSERT_TRUE(r.next(st) && st.ir);
    ASSERT_EQ(st.ir->readings.size(), 3u);
    EXPECT_EQ(st.ir->readings[0].receiver.id, "C");
    EXPECT_EQ(st.ir->readings[1].receiver.id, "A");
    EXPECT_EQ(st.ir->readings[2].receiver.id, "B");
    for (int i : {1, 2}) {
        EXPECT_TRUE(st.ir->readings[i].codes.empty());
        EXPECT_EQ(st.ir->readings[i].volts, 0);
        EXPECT_FALSE(st.ir->readings[i].hasRaw());
    }
    ASSERT_TRUE(r.next(st) && st.ir);
    ASSERT_EQ(st.ir->readings.size(), 3u);
    EXPECT_EQ(st.ir->readings[2].receiver.id, "C");
    EXPECT_TRUE(st.ir->readings[2].codes.empty());
    convertRawlogToTextLog(d / "a.rawlog", d / "b.txt");
    EXPECT_EQ(rfir_test::slurp(d / "b.txt"),
              "format textlog 1\nreceiver A 0 0 0.3\nreceiver B 0 0.1 0.3\n"
              "receiver C 0 0.2 0.3\nodom 1 0 0 0\nir 1 C 4 1.5\nodom 2 0 0 0\n"
              "ir 2 B 1,2 1.25\nir 2 A 3 1\n");
}

TEST(RoundTrip, IRObservationWithNothingInViewIsRefused) {
    TmpDir d;
    rfir::obs::CObservationLogHeader h;
    h.receivers = {{"L", 0, 0, 1}, {"M", 0, 0, 1}};
    {
        CRawlogWriter w(d / "x.rawlog", h);
        auto ir = rfir::obs::CObservationIRSignals::Create();
        ir->sensorLabel = "IR";
        ir->readings.push_back({h.receivers[0], {}, 0, 0, {}});
        ir->readings.push_back({h.receivers[1], {}, 0, 0, {}});
        w.writeStep(1, exactPose(0, 0, 0), {ir});
        w.close();
    }
    try {
        convertRawlogToTextLog(d / "x.rawlog", d / "x.txt");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(
            std::string(e.what()).find(
                "instant 1 (t 1): IR observation in which no receiver sees anything"),
            std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(d / "x.txt"));
}
