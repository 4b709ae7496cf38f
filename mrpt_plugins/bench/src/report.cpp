/* rfir-bench: the table (stdout), the JSON file and the PNG plots. */
#include <rfir/bench/bench.h>

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

void jsonCase(std::ostringstream& o, const TCaseResult& c) {
    o << "{\"method\": \"" << c.method << "\", \"M\": " << c.M << ", \"N\": " << c.N;
    if (c.skipped) {
        o << ", \"skipped\": true, \"reason\": \"" << c.skipReason << "\"}";
        return;
    }
    o << ", \"skipped\": false, \"updates\": " << c.updates
      << ", \"median_us\": " << c.medianUs << ", \"p90_us\": " << c.p90Us
      << ", \"mean_us\": " << c.meanUs << ", \"wall_median_us\": " << c.wallMedianUs
      << ", \"x_floor\": " << c.floorRatio << ", \"x_ps\": " << c.vsPsRatio
      << ", \"state_bytes\": " << c.stateBytes << ", \"peak_bytes\": " << c.peakBytes
      << ", \"build_s\": " << c.buildSeconds << ", \"landmarks\": " << c.tagsMapped
      << "}";
}

std::string jsonEscape(const std::string& s) {
    std::string r;
    for (char ch : s) {
        if (ch == '"' || ch == '\\') r += '\\';
        r += ch;
    }
    return r;
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
        out << row("  %s, M = %zu: %.3f s CPU, %.3f s wall (loading alone %.3f s)\n",
                   p.log.c_str(), p.M, p.cpuSeconds, p.wallSeconds, p.startupCpuSeconds);
    out << "\ntargets\n";
    for (const auto& t : r.targets)
        out << (t.measured ? (t.pass ? "  PASS  " : "  FAIL  ") : "  n/a   ") << t.name
            << ": " << t.detail << "\n";
}

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

std::string toJson(const TBenchReport& r) {
    std::ostringstream o;
    o << std::setprecision(6) << "{\n  \"host\": \"" << jsonEscape(r.host)
      << "\",\n  \"seed\": " << r.options.seed
      << ",\n  \"quick\": " << (r.options.quick ? "true" : "false")
      << ",\n  \"timed_updates\": " << r.options.timedUpdates
      << ",\n  \"rounds\": " << r.options.rounds << ",\n  \"ini_edits\": [";
    for (size_t i = 0; i < r.options.sets.size(); i++)
        o << (i ? ", " : "") << "\"" << jsonEscape(r.options.sets[i]) << "\"";
    o << "]"
      << ",\n  \"time_measure\": \"thread CPU time per update\""
      << ",\n  \"load_before\": " << r.loadBefore
      << ",\n  \"load_after\": " << r.loadAfter
      << ",\n  \"memory_measure\": \"glibc mallinfo2 heap in use\""
      << ",\n  \"floor\": [";
    for (size_t i = 0; i < r.floor.size(); i++)
        o << (i ? ", " : "") << "{\"M\": " << r.floor[i].M
          << ", \"median_us\": " << r.floor[i].medianUs
          << ", \"mean_us\": " << r.floor[i].meanUs
          << ", \"wall_median_us\": " << r.floor[i].wallMedianUs << "}";
    const std::pair<const char*, const std::vector<TCaseResult>*> sweeps[] = {
        {"sweep_M", &r.sweepM}, {"sweep_N", &r.sweepN}};
    for (const auto& [name, v] : sweeps) {
        o << "],\n  \"" << name << "\": [";
        for (size_t i = 0; i < v->size(); i++) {
            o << (i ? ",\n    " : "\n    ");
            jsonCase(o, (*v)[i]);
        }
    }
    o << "],\n  \"realtime\": [";
    for (size_t i = 0; i < r.realtime.size(); i++) {
        const auto& x = r.realtime[i];
        o << (i ? ", " : "") << "{\"method\": \"" << x.method << "\", \"M\": " << x.M
          << ", \"robot_seconds\": " << x.simSeconds << ", \"steps\": " << x.steps
          << ", \"tags_in_world\": " << x.tagsInWorld
          << ", \"tags_mapped\": " << x.tagsMapped << ", \"reads\": " << x.detections
          << ", \"slam_seconds\": " << x.slamSeconds
          << ", \"slam_wall_seconds\": " << x.slamWallSeconds
          << ", \"x_realtime\": " << x.speedup
          << ", \"plain_reference_s\": " << x.plainSeconds << "}";
    }
    o << "],\n  \"plain_reference\": [";
    for (size_t i = 0; i < r.plain.size(); i++) {
        const auto& p = r.plain[i];
        o << (i ? ", " : "") << "{\"log\": \"" << jsonEscape(p.log)
          << "\", \"M\": " << p.M << ", \"steps\": " << p.steps
          << ", \"plain_us_per_step\": " << p.plainUs
          << ", \"plain_tags\": " << p.plainTags;
        for (size_t k = 0; k < p.methods.size(); k++)
            o << ", \"" << p.methods[k] << "_us_per_step\": " << p.engineUs[k] << ", \""
              << p.methods[k] << "_tags\": " << p.engineTags[k];
        o << "}";
    }
    o << "],\n  \"process\": [";
    for (size_t i = 0; i < r.process.size(); i++) {
        const auto& p = r.process[i];
        o << (i ? ", " : "") << "{\"log\": \"" << jsonEscape(p.log)
          << "\", \"M\": " << p.M << ", \"robot_seconds\": " << p.robotSeconds
          << ", \"cpu_seconds\": " << p.cpuSeconds
          << ", \"wall_seconds\": " << p.wallSeconds
          << ", \"startup_cpu_seconds\": " << p.startupCpuSeconds << "}";
    }
    o << "],\n  \"targets\": [";
    for (size_t i = 0; i < r.targets.size(); i++) {
        const auto& t = r.targets[i];
        o << (i ? "," : "") << "\n    {\"name\": \"" << jsonEscape(t.name)
          << "\", \"result\": \""
          << (t.measured ? (t.pass ? "pass" : "fail") : "not measured")
          << "\", \"detail\": \"" << jsonEscape(t.detail) << "\"}";
    }
    o << "]\n}\n";
    return o.str();
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
