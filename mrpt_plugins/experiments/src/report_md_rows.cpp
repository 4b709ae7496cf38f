/* rfir-experiments: results.md sections of the sweeps and the kidnapping. */
#include <rfir/experiments/report.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rfir::experiments {
std::string fmt(double v, int digits);  // report_md.cpp
std::string fmtPM(const TStat& s, double scale, int digits);

std::string sweepSection(const TRowResults& r) {
    std::ostringstream o;
    o << "Robot dr / tags dt [mm], mean ± std over seeds"
      << (r.row.plotTime ? "; then the mean time per update [ms]" : "") << ".\n\n| "
      << r.row.xLabel << " |";
    for (const auto& m : r.row.methods) o << " " << m.label << " |";
    if (r.row.plotTime)
        for (const auto& m : r.row.methods) o << " " << m.label << " ms |";
    o << "\n| ---: |";
    const size_t cols = r.row.methods.size() * (r.row.plotTime ? 2 : 1);
    for (size_t i = 0; i < cols; i++) o << " ---: |";
    o << "\n";
    for (size_t p = 0; p < r.row.points.size(); p++) {
        char x[32];
        std::snprintf(x, sizeof(x), "%g", r.row.points[p].x);
        o << "| " << x << " |";
        for (const auto& m : r.row.methods)
            o << " " << fmtPM(statOf(perSeed(r, p, m.label, robotMeanDist)), 1e3, 1)
              << " / " << fmtPM(statOf(perSeed(r, p, m.label, tagMeanDist)), 1e3, 1)
              << " |";
        if (r.row.plotTime)
            for (const auto& m : r.row.methods)
                o << " "
                  << fmt(statOf(
                             perSeed(r, p, m.label, [](auto& x) { return x.msPerStep; }))
                             .mean,
                         3)
                  << " |";
        o << "\n";
    }
    return o.str();
}

std::string kidnapSection(const TRowResults& r) {
    std::ostringstream o;
    o << "Robot error [mm] before the kidnapping and from 15 s after the robot is put "
         "down to the end. A run has *recovered* when its error after is at most twice "
         "its error before; recovery time: seconds from the put-down to the first error "
         "below twice the error before (mean over the recovered seeds).\n\n"
         "| method | before | after | recovered (seeds) | recovery time [s] | sensor "
         "resettings | tags dt |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto& m : r.row.methods) {
        const auto& L = m.label;
        const auto rec = perSeed(r, 0, L, [](auto& x) { return x.recoveryTime; });
        size_t ok = 0;
        for (double v : rec) ok += std::isfinite(v);
        o << "| " << L << " | "
          << fmtPM(statOf(perSeed(r, 0, L, [](auto& x) { return x.beforeKidnap; })), 1e3,
                   1)
          << " | "
          << fmtPM(statOf(perSeed(r, 0, L, [](auto& x) { return x.afterKidnap; })), 1e3,
                   1)
          << " | " << ok << " / " << perSeed(r, 0, L, robotMeanDist).size() << " | "
          << fmtPM(statOf(rec), 1, 1) << " | "
          << fmt(statOf(perSeed(r, 0, L, [](auto& x) { return double(x.resets); })).mean,
                 1)
          << " | " << fmtPM(statOf(perSeed(r, 0, L, tagMeanDist)), 1e3, 1) << " |\n";
    }
    return o.str();
}

}  // namespace rfir::experiments
