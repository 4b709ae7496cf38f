/* rfir-bench: the results as Markdown tables (docs/benchmark.md). */
#include <rfir/bench/bench.h>

#include <cstdio>
#include <sstream>

namespace rfir::bench {
namespace {
std::string num(double v, int prec) {
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.*f", prec, v);
    return buf;
}

void cases(std::ostringstream& o, const std::vector<TCaseResult>& v) {
    o << "| method | M | N | median us | p90 us | wall us | x floor | x PS-SLAM | state "
         "MB "
         "| peak MB | build s |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: "
         "| ---: "
         "| ---: | ---: |\n";
    for (const auto& c : v) {
        o << "| " << methodLabel(c.method) << " | " << c.M << " | " << c.N << " | ";
        if (c.skipped) {
            o << "skipped: " << c.skipReason << " | | | | | | | |\n";
            continue;
        }
        o << num(c.medianUs, 1) << " | " << num(c.p90Us, 1) << " | "
          << num(c.wallMedianUs, 1) << " | " << num(c.floorRatio, 2) << " | "
          << num(c.vsPsRatio, 2) << " | " << num(c.stateBytes / 1e6, 2) << " | "
          << num(c.peakBytes / 1e6, 2) << " | " << num(c.buildSeconds, 2) << " |\n";
    }
    o << "\n";
}
}  // namespace

namespace {
void processRows(std::ostream& o, const TBenchReport& r) {
    if (r.process.empty()) return;
    o << "\n**Whole rfir-slam processes** (`rfir-slam` on the simulated rawlog, "
         "stock `slam_ps.ini`, every default output; the child's user + system CPU "
         "and wall clock, fastest round; loading: `rfir-slam --version`; side by side "
         "in the same rounds, `rfir-plain-ps`, the plain reference as a whole program "
         "without MRPT, on the same log exported as text; MRPT's own `rawlog-edit "
         "--version`)\n\n| log | M | CPU s | wall s | loading CPU s | plain CPU s | "
         "x plain | rawlog-edit --version CPU s |\n| --- | ---: | ---: | ---: | ---: | "
         "---: | ---: | ---: |\n";
    const auto opt = [](double v) { return v > 0 ? num(v, 2) : std::string("-"); };
    for (const auto& p : r.process)
        o << "| " << p.log << " | " << p.M << " | " << num(p.cpuSeconds, 2) << " | "
          << num(p.wallSeconds, 2) << " | " << num(p.startupCpuSeconds, 2) << " | "
          << opt(p.plainCpuSeconds) << " | "
          << opt(p.plainCpuSeconds > 0 ? p.cpuSeconds / p.plainCpuSeconds : 0) << " | "
          << opt(p.mrptStartupCpuSeconds) << " |\n";
}

void plainRows(std::ostream& o, const TBenchReport& r) {
    if (r.plain.empty()) return;
    o << "\n**Per step against the plain reference** (`plain_reference.cpp`; thread CPU "
         "of the whole run / steps, same inputs)\n\n| log | M | steps | plain us | "
         "method "
         "| us | x plain |\n| --- | ---: | ---: | ---: | --- | ---: | ---: |\n";
    for (const auto& p : r.plain)
        for (size_t k = 0; k < p.methods.size(); k++)
            o << "| " << p.log << " | " << p.M << " | " << p.steps << " | "
              << num(p.plainUs, 1) << " | " << methodLabel(p.methods[k]) << " | "
              << num(p.engineUs[k], 1) << " | "
              << num(p.plainUs > 0 ? p.engineUs[k] / p.plainUs : 0, 2) << " |\n";
}
}  // namespace

std::string toMarkdown(const TBenchReport& r) {
    std::ostringstream o;
    o << "Measured on " << r.host
      << ", shared with other jobs while it ran (1-minute load "
      << "average " << num(r.loadBefore, 1) << " at the start, " << num(r.loadAfter, 1)
      << " at the end); one thread; seed " << r.options.seed << "; times are thread CPU "
      << "time, median of " << r.options.timedUpdates << " timed updates per case, the "
      << "fastest of " << r.options.rounds << " rounds (wall: the wall-clock median of "
      << "that round).";
    if (!r.options.sets.empty()) {
        o << " INI edits (`--set`):";
        for (const auto& e : r.options.sets) o << " `" << e << "`";
        o << ".";
    }
    o << "\n\n";
    o << "**Floor** (one fast Gaussian motion draw, one pose composition and one "
         "detection likelihood per particle, plain loops)\n\n"
      << "| M | median us | mean us | wall us |\n| ---: | ---: | ---: | ---: |\n";
    for (const auto& f : r.floor)
        o << "| " << f.M << " | " << num(f.medianUs, 1) << " | " << num(f.meanUs, 1)
          << " | " << num(f.wallMedianUs, 1) << " |\n";
    o << "\n**Against the robot particles M** (N = " << r.options.fixedN
      << " tags mapped)\n\n";
    cases(o, r.sweepM);
    o << "**Against the mapped tags N** (M = " << r.options.fixedM
      << " robot particles)\n\n";
    cases(o, r.sweepN);
    o << "**Whole offline runs** (`config_ini/bench_floor_30x20.ini`)\n\n"
      << "| method | M | robot time s | steps | tags in world | tags mapped | reads | "
         "SLAM CPU s | SLAM wall s | x real time | plain reference CPU s |\n| --- | "
         "---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto& x : r.realtime)
        o << "| " << methodLabel(x.method) << " | " << x.M << " | "
          << num(x.simSeconds, 0) << " | " << x.steps << " | " << x.tagsInWorld << " | "
          << x.tagsMapped << " | " << x.detections << " | " << num(x.slamSeconds, 2)
          << " | " << num(x.slamWallSeconds, 2) << " | " << num(x.speedup, 0) << " | "
          << (x.plainSeconds > 0 ? num(x.plainSeconds, 2) : std::string("-")) << " |\n";
    plainRows(o, r);
    processRows(o, r);
    o << "\n**Targets**\n\n| target | result | numbers |\n| --- | --- | --- |\n";
    for (const auto& t : r.targets)
        o << "| " << t.name << " | "
          << (t.measured ? (t.pass ? "PASS" : "**FAIL**") : "not measured") << " | "
          << t.detail << " |\n";
    return o.str();
}

}  // namespace rfir::bench
