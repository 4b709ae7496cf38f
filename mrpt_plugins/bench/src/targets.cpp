/* rfir-bench: ratios and the pass/fail targets of docs/benchmark.md. */
#include <rfir/bench/bench.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace rfir::bench {
namespace {
std::string fmt(const char* f, double a, double b = 0, double c = 0, double d = 0) {
    char buf[256];
    std::snprintf(buf, sizeof(buf), f, a, b, c, d);
    return buf;
}

const TCaseResult* find(const std::vector<TCaseResult>& v, const std::string& m, size_t M,
                        size_t N) {
    for (const auto& c : v)
        if (c.method == m && c.M == M && c.N == N && !c.skipped) return &c;
    return nullptr;
}

void fillRatios(TBenchReport& r, std::vector<TCaseResult>& v) {
    for (auto& c : v) {
        if (c.skipped) continue;
        for (const auto& f : r.floor)
            if (f.M == c.M && f.medianUs > 0) c.floorRatio = c.medianUs / f.medianUs;
        const auto* ps = find(v, "ps", c.M, c.N);
        if (ps && ps->medianUs > 0) c.vsPsRatio = c.medianUs / ps->medianUs;
    }
}

TTarget flatInN(const TBenchReport& r, const std::string& method,
                const std::string& label) {
    TTarget t;
    // Up to the largest N swept (1,000,000 by default), at least 100,000.
    size_t maxN = 0;
    for (const auto& c : r.sweepN)
        if (c.method == method && !c.skipped) maxN = std::max(maxN, c.N);
    t.name = label + " update time flat in N (within 20 % of N = 10, up to N = " +
             fmt("%.0f", double(std::max<size_t>(maxN, 100000))) + ")";
    const auto* lo = find(r.sweepN, method, r.options.fixedM, 10);
    const auto* hi = find(r.sweepN, method, r.options.fixedM, maxN);
    if (!lo || !hi || maxN < 100000) {
        t.measured = false;
        t.detail = "needs N = 10 and N >= 100000 in the sweep";
        return t;
    }
    double worst = 0;
    for (const auto& c : r.sweepN)
        if (c.method == method && !c.skipped) {
            worst = std::max(worst, std::fabs(c.medianUs / lo->medianUs - 1));
            if (c.tagsMapped != c.N) {
                t.measured = false;
                t.detail = fmt("the state at N = %.0f has only %.0f tags", double(c.N),
                               double(c.tagsMapped));
                return t;
            }
        }
    t.pass = worst <= 0.20;
    t.detail = fmt("M = %.0f: %.1f us at N = 10, %.1f us at N = %.0f; ",
                   double(r.options.fixedM), lo->medianUs, hi->medianUs, double(maxN)) +
               fmt("largest deviation over the sweep %.0f %%", 100 * worst);
    return t;
}

/** Bytes per added particle between the smallest and largest M of the sweep. */
double slopeM(const TBenchReport& r, const std::string& m, double& lo, double& hi,
              bool peak = false) {
    const TCaseResult *a = nullptr, *b = nullptr;
    for (const auto& c : r.sweepM)
        if (c.method == m && !c.skipped) {
            if (!a || c.M < a->M) a = &c;
            if (!b || c.M > b->M) b = &c;
        }
    if (!a || !b || a->M == b->M) return NAN;
    lo = double(a->M);
    hi = double(b->M);
    if (peak) return (double(b->peakBytes) - double(a->peakBytes)) / (hi - lo);
    return (double(b->stateBytes) - double(a->stateBytes)) / (hi - lo);
}

/** Bytes per added tag between the two largest N of the sweep. */
double slopeN(const TBenchReport& r, const std::string& m, bool peak = false) {
    const TCaseResult *a = nullptr, *b = nullptr;
    for (const auto& c : r.sweepN)
        if (c.method == m && !c.skipped) {
            if (!b || c.N > b->N)
                a = b, b = &c;
            else if (!a || c.N > a->N)
                a = &c;
        }
    if (!a || !b) return NAN;
    if (peak) return (double(b->peakBytes) - double(a->peakBytes)) / double(b->N - a->N);
    return (double(b->stateBytes) - double(a->stateBytes)) / double(b->N - a->N);
}

TTarget memoryShape(const TBenchReport& r) {
    TTarget t;
    t.name = "memory O(M + L N) for PS/PF-SLAM against O(M N) for FastSLAM";
    double lo = 0, hi = 0;
    const double N = double(r.options.fixedN);
    const double psM = slopeM(r, "ps", lo, hi), pfM = slopeM(r, "pf", lo, hi);
    const double fsM = slopeM(r, "fastslam", lo, hi);
    const double psN = slopeN(r, "ps"), pfN = slopeN(r, "pf"),
                 fsN = slopeN(r, "fastslam");
    if (std::isnan(psM) || std::isnan(pfM) || std::isnan(psN)) {
        t.measured = false;
        t.detail = "needs two M and two N values";
        return t;
    }
    // O(M + L N): a robot particle costs a pose and a weight (well under 1 KB)
    // whatever N is; a FastSLAM particle costs its share of N EKFs.
    t.pass = psM < 1024 && pfM < 1024;
    const double fsMp = slopeM(r, "fastslam", lo, hi, true);
    const double fsNp = slopeN(r, "fastslam", true);
    const double M = double(r.options.fixedM);
    // Without FastSLAM in the run (--methods), its half is said, not "nan".
    const bool fs = !std::isnan(fsM) && !std::isnan(fsN);
    t.detail =
        fmt("bytes per extra robot particle at N = %.0f: PS %.0f, PF %.0f", N, psM, pfM) +
        (fs ? fmt(", FastSLAM %.0f at its peak (%.1f per particle per tag) and %.0f "
                  "after the timed updates; ",
                  fsMp, fsMp / N, fsM)
            : std::string("; ")) +
        fmt("bytes per extra tag at M = %.0f: PS %.0f, PF %.0f", M, psN, pfN) +
        (fs ? fmt(", FastSLAM %.0f at its peak (%.1f per tag per particle) and %.0f "
                  "after the timed updates",
                  fsNp, fsNp / M, fsN)
            : std::string(" (FastSLAM not in this run)"));
    return t;
}

/** Heap per mapped tag (the whole state over N at the largest N, and per
 * extra tag between the two largest N) against a bound (8 KB for PS-SLAM,
 * 2 KB for PF-SLAM, at L = 100 and lag 25: a million tags fit in memory). */
TTarget tagBytes(const TBenchReport& r, const std::string& method,
                 const std::string& label, double limit) {
    TTarget t;
    t.name = label + fmt(" state bytes per mapped tag at most %.0f", limit);
    const TCaseResult* b = nullptr;
    for (const auto& c : r.sweepN)
        if (c.method == method && !c.skipped && (!b || c.N > b->N)) b = &c;
    const double slope = slopeN(r, method);
    // Below 100,000 tags the robot particles' share of the state would count.
    if (!b || std::isnan(slope) || b->N < 100000) {
        t.measured = false;
        t.detail = "needs two N values, the largest at least 100000";
        return t;
    }
    const double whole = double(b->stateBytes) / double(b->N);
    t.pass = whole <= limit && slope <= limit;
    t.detail =
        fmt("at N = %.0f: %.0f bytes per tag (whole state / N), ", double(b->N), whole) +
        fmt("%.0f per extra tag; peak %.2f GB", slope, b->peakBytes / 1e9);
    return t;
}

TTarget psAbsolute(const TBenchReport& r) {
    TTarget t;
    t.name = "PS-SLAM single-thread update, M = 500, 2 tags read: under 100 us";
    const TCaseResult* c = find(r.sweepM, "ps", 500, r.options.fixedN);
    if (!c) c = find(r.sweepN, "ps", 500, r.options.fixedN);
    if (!c) {
        t.measured = false;
        t.detail = "needs M = 500";
        return t;
    }
    t.pass = c->medianUs < 100;
    t.detail = fmt("median %.1f us (p90 %.1f us) at N = %.0f", c->medianUs, c->p90Us,
                   double(c->N));
    return t;
}

TTarget psFloor(const TBenchReport& r) {
    TTarget t;
    t.name = "PS-SLAM update within 3x the floor at M = 5000";
    const TCaseResult* c = find(r.sweepM, "ps", 5000, r.options.fixedN);
    if (!c) {
        t.measured = false;
        t.detail = "needs M = 5000";
        return t;
    }
    t.pass = c->floorRatio > 0 && c->floorRatio <= 3;
    t.detail = fmt("median %.1f us = %.2f x the floor (%.1f us)", c->medianUs,
                   c->floorRatio, c->floorRatio > 0 ? c->medianUs / c->floorRatio : 0);
    return t;
}

TTarget vsPlain(const TBenchReport& r) {
    TTarget t;
    t.name = "PS-SLAM and PF-SLAM per step within 1.5 x the plain reference (issue 11)";
    std::string d;
    bool any = false, pass = true;
    for (const auto& p : r.plain)
        for (size_t k = 0; k < p.methods.size(); k++) {
            if (p.methods[k] == "fastslam" || !(p.plainUs > 0)) continue;
            const double x = p.engineUs[k] / p.plainUs;
            any = true;
            pass = pass && x <= 1.5;
            d += std::string(d.empty() ? "" : "; ") + methodLabel(p.methods[k]) +
                 fmt(" M = %.0f: %.1f us = %.2f x plain (%.1f us)", double(p.M),
                     p.engineUs[k], x, p.plainUs);
        }
    t.measured = any;
    t.pass = any && pass;
    t.detail = any ? d : "no side-by-side run";
    return t;
}

TTarget realtime(const TBenchReport& r) {
    TTarget t;
    t.name = "20-minute 30 x 20 m run processed at least 500x faster than real time";
    const TRealtimeResult* x = nullptr;
    // Judged at the stock M = 500 when that run exists, else at the largest M:
    // a smaller M would make the target easier than what users run.
    for (const auto& rt : r.realtime)
        if (rt.method == "ps" && (!x || (x->M != 500 && (rt.M == 500 || rt.M > x->M))))
            x = &rt;
    if (!x) {
        t.measured = false;
        t.detail = "no real-time run";
        return t;
    }
    t.pass = x->speedup >= 500 && x->simSeconds >= 1199;
    t.detail =
        fmt("PS-SLAM, M = %.0f: %.0f s of robot time in %.2f s of CPU time = %.0fx "
            "real time",
            double(x->M), x->simSeconds, x->slamSeconds, x->speedup) +
        fmt(" (%.2f s wall clock on the shared machine)", x->slamWallSeconds);
    if (x->simSeconds < 1199) t.detail += " (shortened run: not the target's 20 minutes)";
    return t;
}
TTarget wholeProcess(const TBenchReport& r) {
    TTarget t;
    t.name = "20-minute 30 x 20 m floor, whole rfir-slam process under 0.5 s (issue 11)";
    const TProcessRun* x = nullptr;
    for (const auto& p : r.process)
        if (p.log.rfind("bench_floor_30x20", 0) == 0) x = &p;
    if (!x || x->robotSeconds < 1199) {
        t.measured = false;
        t.detail = x ? "shortened run: not the target's 20 minutes" : "no process run";
        return t;
    }
    t.pass = x->cpuSeconds < 0.5;
    t.detail =
        fmt("PS-SLAM, M = %.0f: %.2f s of CPU (user + sys), %.2f s wall; of it "
            "%.2f s loading the program and its shared libraries",
            double(x->M), x->cpuSeconds, x->wallSeconds, x->startupCpuSeconds);
    if (x->mrptStartupCpuSeconds > 0)
        t.detail +=
            fmt(" (MRPT's rawlog-edit --version: %.2f s)", x->mrptStartupCpuSeconds);
    // The bar's own figures: 0.5 s against its plain program's 0.19 s.
    if (x->plainCpuSeconds > 0)
        t.detail +=
            fmt("; side by side, rfir-plain-ps (the plain reference as a program, "
                "no MRPT) %.2f s: %.2f x plain, where the issue's 0.5 s against "
                "its plain 0.19 s allows 2.63 x",
                x->plainCpuSeconds, x->cpuSeconds / x->plainCpuSeconds);
    return t;
}
}  // namespace

void evaluate(TBenchReport& r) {
    fillRatios(r, r.sweepM);
    fillRatios(r, r.sweepN);
    r.targets = {flatInN(r, "ps", "PS-SLAM"),
                 flatInN(r, "pf", "PF-SLAM"),
                 memoryShape(r),
                 tagBytes(r, "ps", "PS-SLAM", 8192),
                 tagBytes(r, "pf", "PF-SLAM", 2048),
                 psAbsolute(r),
                 psFloor(r),
                 vsPlain(r),
                 realtime(r),
                 wholeProcess(r)};
}

}  // namespace rfir::bench
