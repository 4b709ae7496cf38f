/* rfir-bench: the measurements (docs/benchmark.md) and their report. */
#pragma once

#include <rfir/slam/slam_engine.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rfir::bench {
/** What one run measures (the command line). */
struct TBenchOptions {
    std::vector<size_t> sweepM{100, 200, 500, 1000, 2000, 5000};
    std::vector<size_t> sweepN{10, 100, 1000, 10000, 100000, 1000000};
    size_t fixedN = 1000;  //!< tags mapped in the sweep over M
    size_t fixedM = 500;   //!< robot particles in the sweep over N
    std::vector<std::string> methods{"ps", "pf", "fastslam"};
    size_t timedUpdates = 200;  //!< timed updates per case
    size_t warmupUpdates = 10;  //!< untimed updates before them
    size_t rounds = 3;          //!< rounds over every case (each keeps its fastest)
    /** FastSLAM cases with M * N above this are skipped (O(M N) memory). */
    double maxFastSlamMN = 5e7;
    double realtimeSeconds = 1200;  //!< simulated length of the real-time run
    std::string configDir;          //!< stock INIs (slam_*.ini, bench_*.ini)
    uint64_t seed = 1;
    /** The user's --set edits, applied last: into every SLAM INI (after
     * [slam] robot_particles = M) and into the simulated floor's INI. */
    std::vector<std::string> slamSets, simSets, sets;
    bool quick = false;
    bool realtime = true;  //!< run the whole offline runs
    /** Side by side with the plain reference: a simulated 300 mm random-path
     * log of this length, at these M. */
    double compareSeconds = 300;
    std::vector<size_t> compareM{500, 5000};
};

/** Heap bytes in use (glibc mallinfo2: uordblks + hblkhd, all arenas). */
size_t heapInUse();

/** CPU time of the calling thread (s): unlike the wall clock, it does not
 * count the time other processes on a shared machine take the core. */
double threadCpuSeconds();
/** Wall-clock seconds (steady). */
double wallSeconds();

/** One method at one (M, N). */
struct TCaseResult {
    std::string method;
    size_t M = 0, N = 0;
    bool skipped = false;
    std::string skipReason;
    size_t updates = 0;
    double medianUs = 0, meanUs = 0, p90Us = 0;  //!< thread CPU time per timed update
    double wallMedianUs = 0;  //!< wall-clock median (includes preemption)
    double floorRatio = 0;    //!< median / floor median at the same M
    double vsPsRatio = 0;     //!< median / PS-SLAM median at the same (M, N)
    size_t stateBytes = 0;    //!< heap in use by the state after the timed updates
    size_t peakBytes = 0;     //!< largest heap in use during the build and timing
    double buildSeconds = 0;  //!< building the N-tag state
    size_t tagsMapped = 0;    //!< landmarks the engine reports
};

/** The floor at one M: one fast Gaussian motion draw, one pose composition
 * and one detection likelihood per particle, plain loops (floor_loop.cpp). */
struct TFloorResult {
    size_t M = 0;
    double medianUs = 0, meanUs = 0;  //!< thread CPU time
    double wallMedianUs = 0;
};

/** The whole offline PS-SLAM run over a simulated floor. */
struct TRealtimeResult {
    std::string config;  //!< INI of the simulated run
    std::string method;
    size_t M = 0;
    double simSeconds = 0;  //!< robot time covered
    size_t steps = 0, tagsInWorld = 0, tagsMapped = 0, detections = 0;
    double simulateSeconds = 0;  //!< simulator (not counted in the speed)
    double slamSeconds = 0;      //!< every engine step, end to end (thread CPU time)
    double slamWallSeconds = 0;  //!< the same on the wall clock
    double speedup = 0;          //!< simSeconds / slamSeconds
    double plainSeconds = 0;     //!< the plain reference on the same run (ps rows)
};

/** Per step (thread CPU time of the whole run / steps), engines and the
 * plain reference (plain_reference.cpp) on the same simulated log. */
struct TPlainCompare {
    std::string log;
    size_t M = 0, steps = 0;
    double plainUs = 0;
    size_t plainTags = 0;
    std::vector<std::string> methods;
    std::vector<double> engineUs;
    std::vector<size_t> engineTags;
};

/** A whole rfir-slam process (PS-SLAM, stock INI, default outputs) on a
 * simulated rawlog, timed from outside (process_run.cpp). */
struct TProcessRun {
    std::string log;
    double robotSeconds = 0;
    size_t M = 0;
    double cpuSeconds = 0;         //!< user + system, fastest round
    double wallSeconds = 0;        //!< wall clock, fastest round
    double startupCpuSeconds = 0;  //!< `rfir-slam --version`: loading alone
    /** rfir-plain-ps on the same log exported as text, side by side in the
     * same rounds (0: not run): user + system CPU, wall, fastest round. */
    double plainCpuSeconds = 0, plainWallSeconds = 0;
    /** MRPT's own rawlog-edit --version (0: not on PATH): what loading
     * MRPT's shared libraries costs any MRPT program. */
    double mrptStartupCpuSeconds = 0;
};

/** A pass/fail target with the numbers that decide it. */
struct TTarget {
    std::string name;
    bool pass = false;
    bool measured = true;  //!< false: the cases it needs were not run
    std::string detail;
};

struct TBenchReport {
    TBenchOptions options;
    std::string host;                      //!< CPU model and core count
    double loadBefore = 0, loadAfter = 0;  //!< 1-minute load average
    std::vector<TFloorResult> floor;
    std::vector<TCaseResult> sweepM, sweepN;
    std::vector<TRealtimeResult> realtime;
    std::vector<TPlainCompare> plain;
    std::vector<TProcessRun> process;
    std::vector<TTarget> targets;
};

/** The stock INI of a method with [slam] robot_particles = M. */
rfir::slam::TSlamConfig benchConfig(const TBenchOptions& o, const std::string& method,
                                    size_t M);

/** Builds an N-tag state with the method itself, then times updates. */
TCaseResult runCase(const TBenchOptions& o, const std::string& method, size_t M,
                    size_t N);

TFloorResult runFloor(const TBenchOptions& o, size_t M);

/** Simulates the run once, then times each (method, M) on it. */
std::vector<TRealtimeResult> runRealtime(
    const TBenchOptions& o, const std::vector<std::pair<std::string, size_t>>& runs);

/** The engines and the plain reference side by side (runPlainCompare). */
std::vector<TPlainCompare> runPlainCompare(const TBenchOptions& o);
/** Thread CPU seconds of the plain reference over a run (ps settings at M). */
double plainSeconds(const TBenchOptions& o, const std::vector<rfir::slam::TSlamInput>& in,
                    const mrpt::poses::CPose2D& start, size_t M, size_t& mapped);

/** Whole rfir-slam processes on the floor and the 300 s log (none if the
 * programs are not beside rfir-bench). */
std::vector<TProcessRun> runProcesses(const TBenchOptions& o);

/** Fills the ratios (to the floor, to PS-SLAM) and the targets. */
void evaluate(TBenchReport& r);

/** "PS-SLAM", "PF-SLAM", "FastSLAM" for ps, pf, fastslam. */
const char* methodLabel(const std::string& method);
void printTable(const TBenchReport& r, std::ostream& out);
std::string toJson(const TBenchReport& r);
/** The results as Markdown tables (for docs/benchmark.md). */
std::string toMarkdown(const TBenchReport& r);
/** bench_time_vs_M.png, bench_time_vs_N.png, bench_memory_vs_N.png in dir. */
void writePlots(const TBenchReport& r, const std::string& dir);

}  // namespace rfir::bench
