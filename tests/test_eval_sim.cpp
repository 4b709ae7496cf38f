// Cross-check with the simulator: the landmarks the simulated sensors detected
// must be among those the evaluation counts as passed over / in view (same
// reader and sensor geometry conventions), and almost all of them.
#include <rfir/eval/metrics.h>
#include <rfir/obs/CObservationRFIDReaders.h>
#include <rfir/sim/simulator.h>

#include <gtest/gtest.h>
#include <mrpt/obs/CObservationBearingRange.h>

#include <iostream>
#include <set>

using namespace rfir::eval;

TEST(EvalSim, DetectedTagsArePassedOver) {
    rfir::sim::TSimConfig cfg;  // 60 mm readers, 16 tags/m^2, rectangle
    cfg.trajectory.laps = 1;
    const auto out = rfir::sim::simulate(cfg, 7);
    std::set<std::string> detected;
    for (const auto& s : out.steps)
        for (const auto& o : s.obs)
            if (auto r = std::dynamic_pointer_cast<rfir::obs::CObservationRFIDReaders>(o))
                for (const auto& rd : r->readings)
                    detected.insert(rd.tags.begin(), rd.tags.end());
    const auto passed = tagsPassedOver(out.gtMap, out.groundTruth, out.header.readers);
    std::cout << "tags read " << detected.size() << ", passed over " << passed.size()
              << ", in the carpet " << out.gtMap.size() << "\n";
    ASSERT_GT(detected.size(), 20u);
    for (const auto& id : detected) EXPECT_TRUE(passed.count(id)) << id;
    // Detection is sampled every dt; the densified path may graze a few more.
    EXPECT_LE(passed.size(), detected.size() + detected.size() / 20 + 2)
        << "passed " << passed.size() << ", detected " << detected.size();
}

TEST(EvalSim, DetectedLandmarksAreInView) {
    rfir::sim::TSimConfig cfg;
    cfg.rfid.enabled = false;
    cfg.rb.enabled = true;
    cfg.trajectory.laps = 1;
    cfg.trajectory.rotation = rfir::sim::TTrajectoryConfig::Rotation::Spin;
    const auto out = rfir::sim::simulate(cfg, 3);
    ASSERT_TRUE(out.header.rbSensor);
    std::set<std::string> detected;
    for (const auto& s : out.steps)
        for (const auto& o : s.obs)
            if (auto b =
                    std::dynamic_pointer_cast<mrpt::obs::CObservationBearingRange>(o))
                for (const auto& m : b->sensedData)
                    detected.insert(out.header.landmarkName(m.landmarkID));
    const auto inView = landmarksInView(out.gtMap, out.groundTruth, *out.header.rbSensor);
    std::cout << "landmarks measured " << detected.size() << ", in view " << inView.size()
              << "\n";
    ASSERT_GT(detected.size(), 5u);
    for (const auto& id : detected) EXPECT_TRUE(inView.count(id)) << id;
    EXPECT_LE(inView.size(), detected.size() + detected.size() / 10 + 2)
        << "in view " << inView.size() << ", detected " << detected.size();
}
