/* rfir-experiments: results.md: our numbers (mean +- std over seeds) beside
 * the papers' numbers, row by row, with the figures. */
#include <rfir/experiments/report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

namespace rfir::experiments {
std::string sweepSection(const TRowResults& r);   // report_md_rows.cpp
std::string kidnapSection(const TRowResults& r);  // report_md_rows.cpp

std::string fmt(double v, int digits) {
    if (!std::isfinite(v)) return "-";
    char b[64];
    std::snprintf(b, sizeof(b), "%.*f", digits, v);
    return b;
}
std::string fmtPM(const TStat& s, double scale, int digits) {
    if (!std::isfinite(s.mean)) return "-";
    if (s.n < 2) return fmt(scale * s.mean, digits);
    return fmt(scale * s.mean, digits) + " ± " + fmt(scale * s.sd, digits);
}

namespace {
const TPaperNumbers* paperFor(const TRow& row, const std::string& method) {
    for (const auto& s : row.paperNumbers)
        if (s.label == method) return &s;
    return nullptr;
}

std::string paperCell(const TPaperNumbers* s, double v) {
    if (!s || !std::isfinite(v)) return "-";
    return (s->note.empty() ? "" : s->note + " ") + fmt(v, 1);
}

double robotStat(const TRunResult& r, double rfir::eval::TErrorStats::*f) {
    return r.eval.robot ? r.eval.robot->stats.*f : kNaN;
}
double mapStat(const TRunResult& r, double rfir::eval::TErrorStats::*f) {
    return r.eval.map && r.eval.map->stats.count ? r.eval.map->stats.*f : kNaN;
}

TStat seedStat(const TRowResults& r, const std::string& m, const TGetter& g) {
    return statOf(perSeed(r, 0, m, g));
}

/** Paired over seeds (every method runs on the same data): true when the
 * mean of the per-seed differences a - b is within two standard errors of 0,
 * i.e. our seeds do not resolve the order of a and b. */
bool pairedTie(const TRowResults& r, const std::string& a, const std::string& b,
               const TGetter& get) {
    const auto va = perSeed(r, 0, a, get), vb = perSeed(r, 0, b, get);
    std::vector<double> d;
    for (size_t i = 0; i < std::min(va.size(), vb.size()); i++)
        d.push_back(va[i] - vb[i]);
    const TStat s = statOf(d);
    if (s.n < 2) return false;
    return std::abs(s.mean) < 2 * s.sd / std::sqrt(double(s.n));
}

/** The ordering of methods by `get` (ours) against the papers' ordering;
 * "≈" joins neighbours whose order our seeds do not resolve (pairedTie). */
std::string orderingCheck(const TRowResults& r, const char* what,
                          double TPaperNumbers::*paperField, const TGetter& get) {
    std::vector<std::pair<double, std::string>> paper, ours;
    for (const auto& s : r.row.paperNumbers)
        if (std::isfinite(s.*paperField)) {
            paper.push_back({s.*paperField, s.label});
            ours.push_back({seedStat(r, s.label, get).mean, s.label});
        }
    if (paper.size() < 2) return "";
    std::sort(paper.begin(), paper.end());
    std::sort(ours.begin(), ours.end());
    std::string cs, co;
    for (size_t i = 0; i < paper.size(); i++) cs += (i ? " < " : "") + paper[i].second;
    for (size_t i = 0; i < ours.size(); i++)
        co += (i ? (pairedTie(r, ours[i - 1].second, ours[i].second, get) ? " ≈ " : " < ")
                 : "") +
              ours[i].second;
    bool reversed = false, tied = false;
    for (size_t i = 0; i < paper.size(); i++)
        for (size_t j = i + 1; j < paper.size(); j++) {
            const auto& a = paper[i].second;
            const auto& b = paper[j].second;
            if (pairedTie(r, a, b, get))
                tied = true;
            else if (seedStat(r, a, get).mean > seedStat(r, b, get).mean)
                reversed = true;
        }
    const char* verdict =
        reversed ? " (**different ordering**)"
        : tied   ? " (not contradicted, but not resolved by our random seeds)"
                 : " (same ordering)";
    return std::string(what) + ": papers " + cs + "; ours " + co + verdict;
}

std::string tableSection(const TRowResults& r) {
    using S = rfir::eval::TErrorStats;
    std::ostringstream o;
    o << "| method | x | y | θ [rad] | dr | dr max | tag x | tag y | dt | dt max "
         "| mapped / passed over | ms per step | papers' dr / dt |\n"
         "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | "
         "---: | ---: |\n";
    for (const auto& m : r.row.methods) {
        const auto& L = m.label;
        auto rs = [&](double S::*f) {
            return seedStat(r, L, [f](auto& x) { return robotStat(x, f); });
        };
        auto ms = [&](double S::*f) {
            return seedStat(r, L, [f](auto& x) { return mapStat(x, f); });
        };
        const double rMax =
            maxOver(r, 0, L, [](auto& x) { return robotStat(x, &S::max_dist); });
        const double tMax =
            maxOver(r, 0, L, [](auto& x) { return mapStat(x, &S::max_dist); });
        const TStat mapped =
            seedStat(r, L, [](auto& x) { return double(x.eval.map->mapped); });
        const TStat passed = seedStat(r, L, [](auto& x) {
            return x.eval.map->passedOver ? double(*x.eval.map->passedOver) : kNaN;
        });
        const TStat ms_ = seedStat(r, L, [](auto& x) { return x.msPerStep; });
        const auto* s = paperFor(r.row, L);
        o << "| " << L << " | " << fmtPM(rs(&S::mean_dx), 1e3, 1) << " | "
          << fmtPM(rs(&S::mean_dy), 1e3, 1) << " | " << fmtPM(rs(&S::mean_dtheta), 1, 3)
          << " | **" << fmtPM(rs(&S::mean_dist), 1e3, 1) << "** | " << fmt(1e3 * rMax, 0)
          << " | " << fmtPM(ms(&S::mean_dx), 1e3, 1) << " | "
          << fmtPM(ms(&S::mean_dy), 1e3, 1) << " | **" << fmtPM(ms(&S::mean_dist), 1e3, 1)
          << "** | " << fmt(1e3 * tMax, 0) << " | " << fmt(mapped.mean, 0) << " / "
          << fmt(passed.mean, 0) << " | " << fmt(ms_.mean, 3) << " | "
          << paperCell(s, s ? s->dr : kNaN) << " / " << paperCell(s, s ? s->dt : kNaN)
          << " |\n";
    }
    for (const auto& c : {orderingCheck(r, "Robot", &TPaperNumbers::dr, robotMeanDist),
                          orderingCheck(r, "Tags", &TPaperNumbers::dt, tagMeanDist)})
        if (!c.empty()) o << "\n" << c << ".\n";
    return o.str();
}

std::string seedList(const TRowResults& r) {
    std::set<uint64_t> s;
    for (const auto& x : r.runs) s.insert(x.seed);
    std::string o;
    for (auto v : s) o += (o.empty() ? "" : ", ") + std::to_string(v);
    return o;
}

/** One line per table row: ours (mean over seeds) with the papers' numbers below. */
std::string summary(const std::vector<TRowResults>& rows) {
    const std::vector<std::string> methods{"PS-SLAM", "PF-SLAM", "FastSLAM",
                                           "Dead reckoning"};
    std::ostringstream o;
    o << "Robot dr / tags dt [mm]: ours (mean ± std over seeds), the papers' numbers "
         "below.\n\n| row | source in the papers |";
    for (const auto& m : methods) o << " " << m << " |";
    o << "\n| --- | --- | ---: | ---: | ---: | ---: |\n";
    for (const auto& r : rows) {
        if (r.row.kind != TRowKind::Table || r.row.id.rfind("policy", 0) == 0) continue;
        o << "| [" << r.row.id << "](#" << r.row.id << ") " << r.row.title << " | "
          << r.row.source << " |";
        for (const auto& m : methods) {
            const auto* s = paperFor(r.row, m);
            o << " " << fmtPM(seedStat(r, m, robotMeanDist), 1e3, 0) << " / "
              << fmtPM(seedStat(r, m, tagMeanDist), 1e3, 0);
            if (s)
                o << "<br>papers: " << paperCell(s, s->dr) << " / "
                  << paperCell(s, s->dt);
            o << " |";
        }
        o << "\n";
    }
    return o.str();
}

/** The only sentence of the header that changes from run to run. */
std::string timeSentence(const std::vector<TRowResults>& rows, const TMeta& meta) {
    double runs = 0;
    for (const auto& r : rows) runs += r.runSeconds;
    if (meta.jobs == 0)
        return "Run time: " + fmt(runs / 60, 1) +
               " min, summed over the runs (merged from their folders).";
    return "Wall time: " + fmt(meta.wallSeconds / 60, 1) + " min on " +
           std::to_string(meta.jobs) + (meta.jobs == 1 ? " process." : " processes.");
}

std::string header(const std::vector<TRowResults>& rows, const TMeta& meta) {
    std::ostringstream o;
    o << "# Experiments: our numbers beside the papers'\n\n"
      << "Generated by `rfir-experiments` (run `bash scripts/experiments.sh`; this file "
         "is "
         "overwritten by each run). Command: `"
      << meta.commandLine << "`"
      << (meta.revision.empty() ? "" : ", source revision " + meta.revision)
      << (meta.quick ? " (**quick mode: tiny runs**)" : "") << ". Seeds: ";
    for (size_t i = 0; i < meta.seeds.size(); i++) o << (i ? ", " : "") << meta.seeds[i];
    o << " (each seed drives both the simulation and the SLAM run; the same seed gives "
         "the same numbers).";
    if (!meta.sets.empty()) {
        o << " INI edits (`--set`, applied after the rows' own edits):";
        for (const auto& e : meta.sets) o << " `" << e << "`";
        o << ".";
    }
    o << " " << timeSentence(rows, meta) << " Every raw number is in "
      << "[results.json](results.json), the timings in [timings.json](timings.json).\n\n"
      << "All methods run on the same simulated data of each seed, with the stock INIs "
         "(`config_ini/slam_ps.ini`, `slam_pf.ini`, `slam_fastslam.ini`); dead reckoning "
         "is the odometry alone (tags placed from the odometry pose). Errors are in mm "
         "(θ in rad): the mean over the run (robot) or over the mapped tags (tags) of "
         "|dx|, |dy|, |dθ| and the distance, averaged over a row's sub-runs (e.g. the "
         "five "
         "predefined paths), then **mean ± standard deviation over the random seeds**; "
         "*max* is "
         "the largest error over all seeds and sub-runs. Orderings are judged paired "
         "over seeds (the methods share each seed's data): `a < b` when the mean "
         "per-seed difference is more than two standard errors from zero, else `a ≈ b`. "
         "*Mapped / passed over*: tags "
         "estimated / tags that came inside a reader's area (landmarks in the sensor's "
         "view).\n\n";
    return o.str();
}
}  // namespace

std::string markdownReport(const std::vector<TRowResults>& rows, const TMeta& meta,
                           const std::string& notes) {
    std::ostringstream o;
    o << header(rows, meta) << "## Summary\n\n" << summary(rows) << "\n";
    if (!notes.empty()) o << notes << "\n";
    o << "## Rows\n\n";
    for (const auto& r : rows) {
        o << "<a id=\"" << r.row.id << "\"></a>\n### " << r.row.id << ": " << r.row.title
          << " (" << r.row.source << ")\n\nThe papers report: " << r.row.paperClaim
          << ". Our random seeds: " << seedList(r) << "; simulated setup: ";
        std::set<std::string> inis;
        for (const auto& k : r.row.runs) inis.insert("`config_ini/" + k.simIni + "`");
        for (auto it = inis.begin(); it != inis.end(); ++it)
            o << (it == inis.begin() ? "" : ", ") << *it;
        o << ".\n\n";
        if (r.row.kind == TRowKind::Table)
            o << tableSection(r);
        else if (r.row.kind == TRowKind::Sweep)
            o << sweepSection(r);
        else
            o << kidnapSection(r);
        for (const auto& f : figureNames(r.row))
            o << "\n![" << r.row.id << "](" << f << ")\n";
        o << "\n";
    }
    o << "## Other results\n\n- IR positioning (thesis chapter 5): [results_ir.md]"
         "(results_ir.md).\n- Timing benchmark (time per update against particles and "
         "tags): [benchmark.md](benchmark.md).\n";
    return o.str();
}

}  // namespace rfir::experiments
