/* rfir-bench: one method at one (M, N): build the state, time the updates. */
#include <rfir/bench/bench.h>
#include <rfir/bench/synthetic_drive.h>
#include <rfir/common/install_paths.h>

#include <rfir/common/ini_file.h>
#include <rfir/common/ini_override.h>
#include <rfir/slam/slam_config.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <stdexcept>

namespace rfir::bench {
using Clock = std::chrono::steady_clock;

rfir::slam::TSlamConfig benchConfig(const TBenchOptions& o, const std::string& method,
                                    size_t M) {
    const std::string path = rfir::common::slamIniPath(o.configDir, method);
    // Edits go to the memory copy, never to the stock INI.
    auto f = rfir::common::readIniFile(path);
    f.write("slam", "robot_particles", std::to_string(M));
    rfir::common::applyIniOverrides(f, o.slamSets);
    auto cfg = rfir::slam::loadSlamConfig(f, method);
    cfg.seed = o.seed;
    return cfg;
}

namespace {
double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t i = std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5));
    return v[i];
}

/** Runs one step; samples the heap only when asked, because mallinfo2 walks
 * the allocator's free lists: that costs milliseconds on a large heap and
 * evicts the caches a following timed step would find warm. */
struct TStepper {
    rfir::slam::CSlamEngine& engine;
    size_t base;
    size_t peak = 0;
    double lastWall = 0;
    /** Heap in use above `base` now. */
    size_t above() const {
        const size_t h = heapInUse();
        return h - std::min(base, h);
    }
    void samplePeak() { peak = std::max(peak, above()); }
    /** Returns the step's thread CPU time; lastWall gets its wall time. */
    double step(const rfir::slam::TSlamInput& in) {
        const double w0 = wallSeconds(), c0 = threadCpuSeconds();
        engine.step(in);
        const double dt = threadCpuSeconds() - c0;
        lastWall = wallSeconds() - w0;
        return dt;
    }
};
}  // namespace

TCaseResult runCase(const TBenchOptions& o, const std::string& method, size_t M,
                    size_t N) {
    TCaseResult r;
    r.method = method;
    r.M = M;
    r.N = N;
    if (method == "fastslam" && double(M) * double(N) > o.maxFastSlamMN) {
        r.skipped = true;
        r.skipReason = "M*N above --max-fastslam-mn";
        return r;
    }
    const auto cfg = benchConfig(o, method, M);
    const CSyntheticDrive drive(N);
    const size_t base = heapInUse();
    {
        auto engine = rfir::slam::makeEngine(cfg, rfir::obs::CObservationLogHeader());
        engine->reset(mrpt::poses::CPose2D(0, 0, 0));
        TStepper st{*engine, base};
        const auto t0 = Clock::now();
        for (size_t i = 0; i < drive.populationSteps(); i++) {
            st.step(drive.populationStep(i));
            if (i % 16 == 15) st.samplePeak();
        }
        st.samplePeak();
        r.buildSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
        for (size_t k = 0; k < o.warmupUpdates; k++) st.step(drive.timedStep(k));
        std::vector<double> us, wall;
        const bool trace = std::getenv("RFIR_BENCH_TRACE") != nullptr;
        for (size_t k = 0; k < o.timedUpdates; k++) {
            // Inputs are built outside the timed call.
            const auto in = drive.timedStep(o.warmupUpdates + k);
            us.push_back(1e6 * st.step(in));
            wall.push_back(1e6 * st.lastWall);
            if (trace) std::fprintf(stderr, "%zu %.1f\n", k, us.back());
        }
        r.updates = us.size();
        r.medianUs = percentile(us, 0.5);
        r.p90Us = percentile(us, 0.9);
        r.wallMedianUs = percentile(wall, 0.5);
        r.meanUs = us.empty()
                       ? 0
                       : std::accumulate(us.begin(), us.end(), 0.0) / double(us.size());
        r.stateBytes = st.above();
        r.peakBytes = std::max(st.peak, r.stateBytes);
        r.tagsMapped = engine->landmarks().size();
    }
    return r;
}

}  // namespace rfir::bench
