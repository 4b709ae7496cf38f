/* rfir-experiments: results.json, every raw number (SI units: m, rad, s). */
#include <rfir/experiments/report.h>

#include <rfir/common/atomic_file.h>

#include <cmath>
#include <ostream>
#include <sstream>

namespace rfir::experiments {
namespace {
std::string q(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') o += '\\';
        o += c;
    }
    return o + "\"";
}
std::string n(double v) {
    if (!std::isfinite(v)) return "null";
    std::ostringstream o;
    o.precision(9);
    o << v;
    return o.str();
}

void writeRun(std::ostream& o, const TRow& row, const TRunResult& r) {
    o << "{\"point\":" << q(row.points[r.point].label)
      << ",\"x\":" << n(row.points[r.point].x) << ",\"run\":" << q(row.runs[r.run].label)
      << ",\"method\":" << q(r.method) << ",\"seed\":" << r.seed
      << ",\"steps\":" << r.steps << ",\"ms_per_step\":" << n(r.msPerStep)
      << ",\"max_step_ms\":" << n(r.maxStepMs) << ",\"total_s\":" << n(r.totalSeconds)
      << ",\"resets\":" << r.resets;
    if (std::isfinite(r.beforeKidnap) || std::isfinite(r.afterKidnap))
        o << ",\"before_kidnap_mean_dist\":" << n(r.beforeKidnap)
          << ",\"after_kidnap_mean_dist\":" << n(r.afterKidnap)
          << ",\"recovery_time\":" << n(r.recoveryTime);
    o << ",\"errors\":" << rfir::eval::toJson(r.eval) << "}";
}

void writeRow(std::ostream& o, const TRowResults& rr) {
    const TRow& row = rr.row;
    o << "{\"id\":" << q(row.id) << ",\"title\":" << q(row.title)
      << ",\"source\":" << q(row.source) << ",\"seed_claim\":" << q(row.seedClaim)
      << ",\"seed_numbers_mm\":[";
    for (size_t i = 0; i < row.seedNumbers.size(); i++) {
        const auto& s = row.seedNumbers[i];
        o << (i ? "," : "") << "{\"method\":" << q(s.label) << ",\"x\":" << n(s.x)
          << ",\"y\":" << n(s.y) << ",\"theta_rad\":" << n(s.theta)
          << ",\"dr\":" << n(s.dr) << ",\"tx\":" << n(s.tx) << ",\"ty\":" << n(s.ty)
          << ",\"dt\":" << n(s.dt) << ",\"note\":" << q(s.note) << "}";
    }
    o << "],\"runs\":[\n";
    for (size_t i = 0; i < rr.runs.size(); i++) {
        o << (i ? ",\n" : "");
        writeRun(o, row, rr.runs[i]);
    }
    o << "\n]}";
}
}  // namespace

void writeJson(const std::string& path, const std::vector<TRowResults>& rows,
               const TMeta& meta) {
    rfir::common::writeFileAtomically(path, [&](std::ostream& o) {
        o << "{\"generator\":\"rfir-experiments\",\"command\":" << q(meta.commandLine)
          << ",\"quick\":" << (meta.quick ? "true" : "false") << ",\"seeds\":[";
        for (size_t i = 0; i < meta.seeds.size(); i++)
            o << (i ? "," : "") << meta.seeds[i];
        o << "],\"ini_edits\":[";
        for (size_t i = 0; i < meta.sets.size(); i++)
            o << (i ? "," : "") << q(meta.sets[i]);
        o << "],\"wall_seconds\":" << n(meta.wallSeconds) << ",\"rows\":[\n";
        for (size_t i = 0; i < rows.size(); i++) {
            o << (i ? ",\n" : "");
            writeRow(o, rows[i]);
        }
        o << "\n]}\n";
    });
}

}  // namespace rfir::experiments
