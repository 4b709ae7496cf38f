/* rfir-bench: the table (stdout), the JSON file and the PNG plots. */
#include <rfir/bench/bench.h>

#include <rfir/common/json.h>
#include <rfir/eval/plot.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace rfir::bench {
const char* methodLabel(const std::string& m) {
    return m == "ps"         ? "PS-SLAM"
           : m == "pf"       ? "PF-SLAM"
           : m == "fastslam" ? "FastSLAM"
                             : "?";
}

namespace {

std::string row(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string row(const char* f, ...) {
    char buf[512];
    va_list ap;
    va_start(ap, f);
    std::vsnprintf(buf, sizeof(buf), f, ap);
    va_end(ap);
    return buf;
}

void printCases(const char* title, const std::vector<TCaseResult>& v, std::ostream& out) {
    out << title << "\n"
        << row("%-9s %6s %7s %10s %10s %10s %10s %8s %8s %10s %10s %8s\n", "method", "M",
               "N", "median_us", "p90_us", "mean_us", "wall_us", "x_floor", "x_PS",
               "state_MB", "peak_MB", "build_s");
    for (const auto& c : v) {
        if (c.skipped) {
            out << row("%-9s %6zu %7zu   skipped: %s\n", methodLabel(c.method), c.M, c.N,
                       c.skipReason.c_str());
            continue;
        }
        out << row(
            "%-9s %6zu %7zu %10.1f %10.1f %10.1f %10.1f %8.2f %8.2f %10.2f %10.2f "
            "%8.2f\n",
            methodLabel(c.method), c.M, c.N, c.medianUs, c.p90Us, c.meanUs,
            c.wallMedianUs, c.floorRatio, c.vsPsRatio, c.stateBytes / 1e6,
            c.peakBytes / 1e6, c.buildSeconds);
        if (c.tagsMapped != c.N)
            out << row(
                "    ^ only %zu of the %zu tags were mapped: the state is not the one "
                "asked for\n",
                c.tagsMapped, c.N);
    }
    out << "\n";
}

using rfir::common::TJson;
// The benchmark's numbers are written with 6 significant digits.
TJson p6(double v) {
    return rfir::common::printed(v, "%.6g");
}

TJson caseJson(const TCaseResult& c) {
    TJson j;
    j["method"] = c.method;
    j["M"] = c.M;
    j["N"] = c.N;
    j["skipped"] = c.skipped;
    if (c.skipped) {
        j["reason"] = c.skipReason;
        return j;
    }
    j["updates"] = c.updates;
    j["median_us"] = p6(c.medianUs);
    j["p90_us"] = p6(c.p90Us);
    j["mean_us"] = p6(c.meanUs);
    j["wall_median_us"] = p6(c.wallMedianUs);
    j["x_floor"] = p6(c.floorRatio);
    j["x_ps"] = p6(c.vsPsRatio);
    j["state_bytes"] = c.stateBytes;
    j["peak_bytes"] = c.peakBytes;
    j["build_s"] = p6(c.buildSeconds);
    j["landmarks"] = c.tagsMapped;
    return j;
}

TJson realtimeJson(const TRealtimeResult& x) {
    TJson j;
    j["method"] = x.method;
    j["M"] = x.M;
    j["robot_seconds"] = p6(x.simSeconds);
    j["steps"] = x.steps;
    j["tags_in_world"] = x.tagsInWorld;
    j["tags_mapped"] = x.tagsMapped;
    j["reads"] = x.detections;
    j["slam_seconds"] = p6(x.slamSeconds);
    j["slam_wall_seconds"] = p6(x.slamWallSeconds);
    j["x_realtime"] = p6(x.speedup);
    j["plain_reference_s"] = p6(x.plainSeconds);
    return j;
}

TJson plainJson(const TPlainCompare& p) {
    TJson j;
    j["log"] = p.log;
    j["M"] = p.M;
    j["steps"] = p.steps;
    j["plain_us_per_step"] = p6(p.plainUs);
    j["plain_tags"] = p.plainTags;
    for (size_t k = 0; k < p.methods.size(); k++) {
        j[p.methods[k] + "_us_per_step"] = p6(p.engineUs[k]);
        j[p.methods[k] + "_tags"] = p.engineTags[k];
    }
    return j;
}

TJson processJson(const TProcessRun& p) {
    TJson j;
    j["log"] = p.log;
    j["M"] = p.M;
    j["robot_seconds"] = p6(p.robotSeconds);
    j["cpu_seconds"] = p6(p.cpuSeconds);
    j["wall_seconds"] = p6(p.wallSeconds);
    j["startup_cpu_seconds"] = p6(p.startupCpuSeconds);
    j["plain_cpu_seconds"] = p6(p.plainCpuSeconds);
    j["plain_wall_seconds"] = p6(p.plainWallSeconds);
    j["mrpt_startup_cpu_seconds"] = p6(p.mrptStartupCpuSeconds);
    return j;
}

template <class T, class F>
TJson arrayOf(const std::vector<T>& v, F f) {
    TJson a = TJson::array();
    for (const auto& x : v) a.push_back(f(x));
    return a;
}
}  // namespace

namespace {
/** The side-by-side rows of printTable. */
void printPlain(const TBenchReport& r, std::ostream& out) {
    if (r.plain.empty()) return;
    out << "\nper step against the plain reference (thread CPU of the whole run / "
           "steps)\n";
    for (const auto& p : r.plain) {
        out << row("  %s, M = %zu, %zu steps: plain %.1f us (%zu tags)", p.log.c_str(),
                   p.M, p.steps, p.plainUs, p.plainTags);
        for (size_t k = 0; k < p.methods.size(); k++)
            out << row("; %s %.1f us (x %.2f, %zu tags)", p.methods[k].c_str(),
                       p.engineUs[k], p.plainUs > 0 ? p.engineUs[k] / p.plainUs : 0,
                       p.engineTags[k]);
        out << "\n";
    }
}
}  // namespace

void printTable(const TBenchReport& r, std::ostream& out) {
    out << "rfir-bench on " << r.host << " (load average " << row("%.1f", r.loadBefore)
        << " before, " << row("%.1f", r.loadAfter)
        << " after); single thread; thread CPU "
        << "time per SLAM update, median of " << r.options.timedUpdates << " (fastest of "
        << r.options.rounds << " rounds)"
        << " (2 known tags read per update; wall_us = wall-clock median); memory = heap "
        << "bytes in use by the state (glibc mallinfo2)\n\n";
    out << "floor (1 fast Gaussian motion draw + 1 pose composition + 1 detection "
           "likelihood per particle, plain loops)\n"
        << row("%6s %10s %10s %10s\n", "M", "median_us", "mean_us", "wall_us");
    for (const auto& f : r.floor)
        out << row("%6zu %10.2f %10.2f %10.2f\n", f.M, f.medianUs, f.meanUs,
                   f.wallMedianUs);
    out << "\n";
    printCases(("time and memory against M (N = " + std::to_string(r.options.fixedN) +
                " tags mapped)")
                   .c_str(),
               r.sweepM, out);
    printCases(("time and memory against N (M = " + std::to_string(r.options.fixedM) +
                " robot particles)")
                   .c_str(),
               r.sweepN, out);
    out << "whole offline runs\n"
        << row("%-9s %6s %9s %7s %7s %7s %9s %10s %10s %10s\n", "method", "M", "robot_s",
               "steps", "tags", "mapped", "reads", "slam_s", "wall_s", "x_realtime");
    for (const auto& x : r.realtime) {
        out << row("%-9s %6zu %9.0f %7zu %7zu %7zu %9zu %10.3f %10.3f %10.0f",
                   methodLabel(x.method), x.M, x.simSeconds, x.steps, x.tagsInWorld,
                   x.tagsMapped, x.detections, x.slamSeconds, x.slamWallSeconds,
                   x.speedup);
        if (x.plainSeconds > 0)
            out << row("   plain reference %.3f s (x %.2f)", x.plainSeconds,
                       x.slamSeconds / x.plainSeconds);
        out << "\n";
    }
    printPlain(r, out);
    if (!r.process.empty()) out << "\nwhole rfir-slam processes (PS-SLAM, user + sys)\n";
    for (const auto& p : r.process)
        out << row(
            "  %s, M = %zu: %.3f s CPU, %.3f s wall (loading alone %.3f s); "
            "rfir-plain-ps %.3f s CPU; rawlog-edit --version %.3f s\n",
            p.log.c_str(), p.M, p.cpuSeconds, p.wallSeconds, p.startupCpuSeconds,
            p.plainCpuSeconds, p.mrptStartupCpuSeconds);
    out << "\ntargets\n";
    for (const auto& t : r.targets)
        out << (t.measured ? (t.pass ? "  PASS  " : "  FAIL  ") : "  n/a   ") << t.name
            << ": " << t.detail << "\n";
}

std::string toJson(const TBenchReport& r) {
    TJson j;
    j["host"] = r.host;
    j["seed"] = r.options.seed;
    j["quick"] = r.options.quick;
    j["timed_updates"] = r.options.timedUpdates;
    j["rounds"] = r.options.rounds;
    j["ini_edits"] = r.options.sets;
    j["time_measure"] = "thread CPU time per update";
    j["load_before"] = p6(r.loadBefore);
    j["load_after"] = p6(r.loadAfter);
    j["memory_measure"] = "glibc mallinfo2 heap in use";
    j["floor"] = arrayOf(r.floor, [](const TFloorResult& f) {
        TJson e;
        e["M"] = f.M;
        e["median_us"] = p6(f.medianUs);
        e["mean_us"] = p6(f.meanUs);
        e["wall_median_us"] = p6(f.wallMedianUs);
        return e;
    });
    j["sweep_M"] = arrayOf(r.sweepM, caseJson);
    j["sweep_N"] = arrayOf(r.sweepN, caseJson);
    j["realtime"] = arrayOf(r.realtime, realtimeJson);
    j["plain_reference"] = arrayOf(r.plain, plainJson);
    j["process"] = arrayOf(r.process, processJson);
    j["targets"] = arrayOf(r.targets, [](const TTarget& t) {
        TJson e;
        e["name"] = t.name;
        e["result"] = t.measured ? (t.pass ? "pass" : "fail") : "not measured";
        e["detail"] = t.detail;
        return e;
    });
    return rfir::common::dumpJson(j) + "\n";
}

/** One series per method: median time (or state memory) against M or N. */
std::vector<rfir::eval::TSeries> methodSeries(const std::vector<std::string>& methods,
                                              const std::vector<TCaseResult>& v, bool byM,
                                              bool memory) {
    std::vector<rfir::eval::TSeries> out;
    for (const auto& m : methods) {
        rfir::eval::TSeries s;
        s.label = methodLabel(m);
        for (const auto& c : v)
            if (c.method == m && !c.skipped) {
                s.x.push_back(double(byM ? c.M : c.N));
                s.y.push_back(memory ? c.stateBytes / 1e6 : c.medianUs);
            }
        out.push_back(s);
    }
    return out;
}

void writePlots(const TBenchReport& r, const std::string& dir) {
    using rfir::eval::TLinePlot;
    using rfir::eval::TSeries;
    const auto& series = [&](const std::vector<TCaseResult>& v, bool byM, bool mem) {
        return methodSeries(r.options.methods, v, byM, mem);
    };
    TLinePlot tm;
    tm.title = "Time per SLAM update vs robot particles (N = " +
               std::to_string(r.options.fixedN) + " tags)";
    tm.xLabel = "robot particles M";
    tm.yLabel = "median time per update (us)";
    tm.series = series(r.sweepM, true, false);
    TSeries fl;
    fl.label = "floor";
    for (const auto& f : r.floor) fl.x.push_back(double(f.M)), fl.y.push_back(f.medianUs);
    tm.series.push_back(fl);
    tm.logX = tm.logY = true;
    rfir::eval::plotLines(dir + "/bench_time_vs_M.png", tm);

    TLinePlot tn;
    tn.title =
        "Time per SLAM update vs mapped tags (M = " + std::to_string(r.options.fixedM) +
        ")";
    tn.xLabel = "mapped tags N";
    tn.yLabel = "median time per update (us)";
    tn.series = series(r.sweepN, false, false);
    TSeries fn;
    fn.label = "floor";
    for (const auto& f : r.floor)
        if (f.M == r.options.fixedM && !r.options.sweepN.empty())
            for (size_t N : {r.options.sweepN.front(), r.options.sweepN.back()})
                fn.x.push_back(double(N)), fn.y.push_back(f.medianUs);
    tn.series.push_back(fn);
    tn.logX = tn.logY = true;
    rfir::eval::plotLines(dir + "/bench_time_vs_N.png", tn);

    TLinePlot mn;
    mn.title =
        "State memory vs mapped tags (M = " + std::to_string(r.options.fixedM) + ")";
    mn.xLabel = "mapped tags N";
    mn.yLabel = "heap in use by the state (MB)";
    mn.series = series(r.sweepN, false, true);
    TSeries peak;
    peak.label = "FastSLAM peak";
    for (const auto& c : r.sweepN)
        if (c.method == "fastslam" && !c.skipped)
            peak.x.push_back(double(c.N)), peak.y.push_back(c.peakBytes / 1e6);
    if (!peak.x.empty()) mn.series.push_back(peak);
    mn.logX = mn.logY = true;
    rfir::eval::plotLines(dir + "/bench_memory_vs_N.png", mn);
}

}  // namespace rfir::bench
