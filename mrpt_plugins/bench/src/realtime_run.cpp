/* rfir-bench: a whole offline run, timed end to end against the robot time it
 * covers (config_ini/bench_floor_30x20.ini, simulated in-process). */
#include <rfir/bench/bench.h>

#include <rfir/sim/simulator.h>
#include <rfir/slam/slam_inputs.h>

#include <chrono>
#include <string>

namespace rfir::bench {
namespace {
size_t countDetections(const std::vector<rfir::slam::TSlamInput>& inputs) {
    size_t n = 0;
    for (const auto& in : inputs)
        if (in.rfid) n += in.rfid->detectionCount();
    return n;
}
}  // namespace

std::vector<TRealtimeResult> runRealtime(
    const TBenchOptions& o, const std::vector<std::pair<std::string, size_t>>& runs) {
    using Clock = std::chrono::steady_clock;
    const std::string config = o.configDir + "/bench_floor_30x20.ini";
    char dur[64];
    std::snprintf(dur, sizeof(dur), "simulation.max_duration=%g", o.realtimeSeconds);
    std::vector<std::string> sets = {dur};
    sets.insert(sets.end(), o.simSets.begin(), o.simSets.end());
    const auto simCfg = rfir::sim::loadSimConfig(config, sets);
    auto t0 = Clock::now();
    const auto sim = rfir::sim::simulate(simCfg, o.seed);
    const double simulateSeconds =
        std::chrono::duration<double>(Clock::now() - t0).count();
    const auto inputs = rfir::slam::inputsFromSteps(sim.steps);
    const size_t dets = countDetections(inputs);
    size_t tags = 0;
    for (const auto& e : sim.gtMap)
        if (e.kind == rfir::common::TMapEntry::Kind::Tag) tags++;
    const mrpt::poses::CPose2D start =
        sim.groundTruth.empty() ? mrpt::poses::CPose2D() : sim.groundTruth.front().pose;

    std::vector<TRealtimeResult> out;
    for (const auto& [method, M] : runs) {
        TRealtimeResult r;
        r.config = config;
        r.method = method;
        r.M = M;
        r.simulateSeconds = simulateSeconds;
        r.detections = dets;
        r.steps = inputs.size();
        r.simSeconds = inputs.empty() ? 0 : inputs.back().t - inputs.front().t;
        r.tagsInWorld = tags;
        const auto cfg = benchConfig(o, method, M);
        auto engine = rfir::slam::makeEngine(cfg, sim.header);
        const double w0 = wallSeconds(), c0 = threadCpuSeconds();
        const auto run = rfir::slam::runEngine(*engine, start, inputs);
        r.slamSeconds = threadCpuSeconds() - c0;
        r.slamWallSeconds = wallSeconds() - w0;
        r.tagsMapped = run.map.size();
        r.speedup = r.slamSeconds > 0 ? r.simSeconds / r.slamSeconds : 0;
        size_t plainTags = 0;
        if (method == "ps") r.plainSeconds = plainSeconds(o, inputs, start, M, plainTags);
        out.push_back(r);
    }
    return out;
}

}  // namespace rfir::bench
