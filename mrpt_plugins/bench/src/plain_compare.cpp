/* rfir-bench: the engines side by side with the plain reference on the same
 * inputs (a simulated log, converted once): thread CPU time of every step of
 * the whole run, divided by the steps. */
#include <rfir/bench/bench.h>
#include <rfir/bench/plain_reference.h>

#include <rfir/sim/simulator.h>
#include <rfir/slam/slam_inputs.h>

#include <algorithm>
#include <cstdio>

namespace rfir::bench {
namespace {
struct TLog {
    std::vector<rfir::slam::TSlamInput> inputs;
    rfir::obs::CObservationLogHeader header;
    mrpt::poses::CPose2D start;
};

TLog simulateLog(const std::string& ini, double seconds, uint64_t seed) {
    char dur[64];
    std::snprintf(dur, sizeof(dur), "simulation.max_duration=%g", seconds);
    const auto sim = rfir::sim::simulate(rfir::sim::loadSimConfig(ini, {dur}), seed);
    TLog l;
    l.inputs = rfir::slam::inputsFromSteps(sim.steps);
    l.header = sim.header;
    if (!sim.groundTruth.empty()) l.start = sim.groundTruth.front().pose;
    return l;
}

double engineSeconds(const TBenchOptions& o, const TLog& l, const std::string& method,
                     size_t M, size_t& mapped) {
    const auto cfg = benchConfig(o, method, M);
    auto engine = rfir::slam::makeEngine(cfg, l.header);
    const double c0 = threadCpuSeconds();
    const auto run = rfir::slam::runEngine(*engine, l.start, l.inputs);
    const double dt = threadCpuSeconds() - c0;
    mapped = run.map.size();
    return dt;
}
}  // namespace

double plainSeconds(const TBenchOptions& o, const std::vector<rfir::slam::TSlamInput>& in,
                    const mrpt::poses::CPose2D& start, size_t M, size_t& mapped) {
    CPlainPsSlam plain(plainOptionsFor(benchConfig(o, "ps", M)));
    const double c0 = threadCpuSeconds();
    plain.reset(start);
    for (const auto& s : in) plain.step(s);
    const double dt = threadCpuSeconds() - c0;
    mapped = plain.tagsMapped();
    return dt;
}

std::vector<TPlainCompare> runPlainCompare(const TBenchOptions& o) {
    const std::string ini = o.configDir + "/sim_rfid_300mm_4tags_random.ini";
    const TLog l = simulateLog(ini, o.compareSeconds, o.seed);
    std::vector<TPlainCompare> out;
    for (size_t M : o.compareM) {
        TPlainCompare p;
        p.log = "sim_rfid_300mm_4tags_random.ini, " +
                std::to_string(int(o.compareSeconds)) + " s";
        p.M = M;
        p.steps = l.inputs.size();
        double best = 1e300;
        for (size_t r = 0; r < o.rounds; r++)
            best = std::min(best, plainSeconds(o, l.inputs, l.start, M, p.plainTags));
        p.plainUs = 1e6 * best / double(std::max<size_t>(1, p.steps));
        for (const auto& m : o.methods) {
            if (m == "fastslam" && M > 1000) continue;  // O(M N) per step: not compared
            double e = 1e300;
            size_t mapped = 0;
            for (size_t r = 0; r < o.rounds; r++)
                e = std::min(e, engineSeconds(o, l, m, M, mapped));
            p.methods.push_back(m);
            p.engineUs.push_back(1e6 * e / double(std::max<size_t>(1, p.steps)));
            p.engineTags.push_back(mapped);
        }
        out.push_back(p);
    }
    return out;
}

}  // namespace rfir::bench
