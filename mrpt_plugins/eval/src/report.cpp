#include <rfir/eval/report.h>

#include "report_json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace rfir::eval {
using rfir::common::TMapEntry;

namespace {
const char* pluralKey(TMapEntry::Kind k) {
    switch (k) {
        case TMapEntry::Kind::Tag:
            return "tags";
        case TMapEntry::Kind::Emitter:
            return "emitters";
        default:
            return "landmarks";
    }
}
}  // namespace

namespace {
std::string fmt(double v, int decimals) {
    char b[64];
    std::snprintf(b, sizeof(b), "%.*f", decimals, v);
    return b;
}

/** Display width of a UTF-8 string (code points; the table uses no wide glyphs). */
size_t displayWidth(const std::string& s) {
    size_t n = 0;
    for (unsigned char c : s)
        if ((c & 0xC0) != 0x80) n++;
    return n;
}

/** Left-aligned first column, right-aligned others, two spaces between. */
std::string renderTable(const std::vector<std::vector<std::string>>& rows) {
    std::vector<size_t> w;
    for (const auto& r : rows)
        for (size_t i = 0; i < r.size(); i++) {
            if (w.size() <= i) w.push_back(0);
            w[i] = std::max(w[i], displayWidth(r[i]));
        }
    std::ostringstream o;
    for (const auto& r : rows) {
        std::string line;
        for (size_t i = 0; i < r.size(); i++) {
            const std::string pad(w[i] - displayWidth(r[i]), ' ');
            line += i == 0 ? r[i] + pad : "  " + pad + r[i];
        }
        while (!line.empty() && line.back() == ' ') line.pop_back();
        o << line << "\n";
    }
    return o.str();
}

std::vector<std::string> robotCells(const std::string& label, const TRobotErrors& e,
                                    bool showMax) {
    const auto& s = e.stats;
    std::vector<std::string> c{label, fmt(1e3 * s.mean_dx, 1), fmt(1e3 * s.mean_dy, 1),
                               fmt(s.mean_dtheta, 3), fmt(1e3 * s.mean_dist, 1)};
    if (showMax)
        for (auto v : {fmt(1e3 * s.max_dx, 1), fmt(1e3 * s.max_dy, 1),
                       fmt(s.max_dtheta, 3), fmt(1e3 * s.max_dist, 1)})
            c.push_back(v);
    c.push_back(std::to_string(s.count));
    return c;
}

std::string robotTable(const std::vector<TEvalResult>& rows, bool showMax) {
    std::vector<std::vector<std::string>> t;
    std::vector<std::string> h2{"method", "x [mm]", "y [mm]", "θ [rad]", "dr [mm]"};
    if (showMax) {
        h2.insert(h2.end(), {"x [mm]", "y [mm]", "θ [rad]", "dr [mm]"});
    }
    h2.push_back("poses");
    t.push_back(h2);
    for (const auto& r : rows) {
        if (r.robot) t.push_back(robotCells(r.label, *r.robot, showMax));
        if (r.odometry)
            t.push_back(robotCells(r.label + " odometry", *r.odometry, showMax));
    }
    std::string out = "Robot localization (mean";
    out += showMax ? ", then max)\n" : ")\n";
    return out + renderTable(t);
}

/** evo's figures: RMSE, SE(2)-aligned absolute errors, relative errors. */
std::string evoTable(const std::vector<TEvalResult>& rows) {
    std::vector<std::vector<std::string>> t;
    t.push_back({"method", "rmse dr", "rmse θ", "al. mean dr", "al. rmse dr",
                 "al. max dr", "al. rmse θ", "RPE/m t", "RPE/m θ", "RPE/s t", "RPE/s θ"});
    auto row = [&](const std::string& label, const TRobotErrors& e) {
        t.push_back(
            {label, fmt(1e3 * e.stats.rmse_dist, 1), fmt(e.stats.rmse_dtheta, 3),
             fmt(1e3 * e.aligned.mean_dist, 1), fmt(1e3 * e.aligned.rmse_dist, 1),
             fmt(1e3 * e.aligned.max_dist, 1), fmt(e.aligned.rmse_dtheta, 3),
             fmt(1e3 * e.rpePerMetre.rmse_trans, 1), fmt(e.rpePerMetre.rmse_rot, 3),
             fmt(1e3 * e.rpePerSecond.rmse_trans, 1), fmt(e.rpePerSecond.rmse_rot, 3)});
    };
    for (const auto& r : rows) {
        if (r.robot) row(r.label, *r.robot);
        if (r.odometry) row(r.label + " odometry", *r.odometry);
    }
    return "Robot, as evo reports it: RMSE; after SE(2) alignment (al.); relative "
           "pose error RMSE over 1 m and 1 s (mm, rad)\n" +
           renderTable(t);
}

/** Mean distance error per time window; rows as in robotTable, the header
 * from the first result with windows. */
std::string segmentTable(const std::vector<TEvalResult>& rows) {
    const TEvalResult* first = nullptr;
    for (const auto& r : rows)
        if (!r.segmentBounds.empty() && !first) first = &r;
    if (!first) return {};
    std::vector<std::vector<std::string>> t;
    std::vector<std::string> h{"method"};
    for (size_t k = 0; k + 1 < first->segmentBounds.size(); k++)
        h.push_back(fmt(first->segmentBounds[k], 0) + "-" +
                    fmt(first->segmentBounds[k + 1], 0) + " s");
    t.push_back(h);
    auto row = [&](const std::string& label, const std::vector<TErrorStats>& v) {
        if (v.empty()) return;
        std::vector<std::string> c{label};
        for (const auto& s : v) c.push_back(s.count ? fmt(1e3 * s.mean_dist, 1) : "-");
        t.push_back(c);
    };
    for (const auto& r : rows) {
        row(r.label, r.robotSegments);
        row(r.label + " odometry", r.odometrySegments);
    }
    return "Robot position error per time window (mean dr [mm])\n" + renderTable(t);
}

std::string mapTable(const std::vector<TEvalResult>& rows, bool showMax) {
    TMapEntry::Kind kind = TMapEntry::Kind::Tag;
    for (const auto& r : rows)
        if (r.map) kind = r.map->kind;
    const bool tags = kind == TMapEntry::Kind::Tag;
    std::vector<std::vector<std::string>> t;
    std::vector<std::string> h{"method", "x [mm]", "y [mm]", "dt [mm]"};
    if (showMax) h.insert(h.end(), {"x [mm]", "y [mm]", "dt [mm]"});
    h.insert(h.end(), {"mapped", tags ? "passed over" : "in view", "total"});
    t.push_back(h);
    for (const auto& r : rows) {
        if (!r.map) continue;
        const auto& s = r.map->stats;
        std::vector<std::string> c{r.label, fmt(1e3 * s.mean_dx, 1),
                                   fmt(1e3 * s.mean_dy, 1), fmt(1e3 * s.mean_dist, 1)};
        if (showMax)
            c.insert(c.end(), {fmt(1e3 * s.max_dx, 1), fmt(1e3 * s.max_dy, 1),
                               fmt(1e3 * s.max_dist, 1)});
        c.push_back(std::to_string(r.map->mapped));
        c.push_back(r.map->passedOver ? std::to_string(*r.map->passedOver) : "-");
        c.push_back(std::to_string(r.map->total));
        t.push_back(c);
    }
    std::string out = tags ? "Tag localization" : "Landmark localization";
    out += showMax ? " (mean, then max)\n" : " (mean)\n";
    return out + renderTable(t);
}
}  // namespace

std::string formatErrorTable(const std::vector<TEvalResult>& rows,
                             const TTableOptions& opts) {
    bool anyRobot = false, anyMap = false;
    for (const auto& r : rows) {
        anyRobot |= r.robot.has_value() || r.odometry.has_value();
        anyMap |= r.map.has_value();
    }
    std::string out;
    if (anyRobot) out += robotTable(rows, opts.showMax);
    if (anyRobot && opts.showEvo) out += "\n" + evoTable(rows);
    const std::string segments = segmentTable(rows);
    if (!segments.empty()) out += "\n" + segments;
    if (anyRobot && anyMap) out += "\n";
    if (anyMap) out += mapTable(rows, opts.showMax);
    return out;
}

namespace {
using rfir::common::printed;
using rfir::common::TJson;

TJson alignedJson(const TAlignment& a, const TErrorStats& s) {
    TJson j;
    j["theta"] = printed(a.theta);
    j["tx"] = printed(a.tx);
    j["ty"] = printed(a.ty);
    j["mean_dist"] = printed(s.mean_dist);
    j["rmse_dist"] = printed(s.rmse_dist);
    j["max_dist"] = printed(s.max_dist);
    j["mean_dtheta"] = printed(s.mean_dtheta);
    j["rmse_dtheta"] = printed(s.rmse_dtheta);
    j["max_dtheta"] = printed(s.max_dtheta);
    return j;
}

TJson rpeJson(const TRpeStats& r) {
    TJson j;
    j["delta"] = printed(r.delta);
    j["pairs"] = r.pairs;
    j["mean_trans"] = printed(r.mean_trans);
    j["rmse_trans"] = printed(r.rmse_trans);
    j["max_trans"] = printed(r.max_trans);
    j["mean_rot"] = printed(r.mean_rot);
    j["rmse_rot"] = printed(r.rmse_rot);
    j["max_rot"] = printed(r.max_rot);
    return j;
}

TJson robotJson(const TRobotErrors& e) {
    const auto& s = e.stats;
    TJson j;
    j["poses"] = s.count;
    j["skipped"] = e.skipped;
    j["mean_dx"] = printed(s.mean_dx);
    j["mean_dy"] = printed(s.mean_dy);
    j["mean_dtheta"] = printed(s.mean_dtheta);
    j["mean_dist"] = printed(s.mean_dist);
    j["max_dx"] = printed(s.max_dx);
    j["max_dy"] = printed(s.max_dy);
    j["max_dtheta"] = printed(s.max_dtheta);
    j["max_dist"] = printed(s.max_dist);
    j["rmse_dist"] = printed(s.rmse_dist);
    j["rmse_dtheta"] = printed(s.rmse_dtheta);
    j["aligned"] = alignedJson(e.alignment, e.aligned);
    j["rpe_per_m"] = rpeJson(e.rpePerMetre);
    j["rpe_per_s"] = rpeJson(e.rpePerSecond);
    return j;
}

/** Window means, NaN (null) where a window has no pose. */
std::vector<double> meanDists(const std::vector<TErrorStats>& v) {
    std::vector<double> o;
    for (const auto& s : v) o.push_back(s.count ? s.mean_dist : std::nan(""));
    return o;
}

TJson segmentsJson(const TEvalResult& r) {
    TJson j;
    j["t"] = printed(r.segmentBounds);
    if (!r.robotSegments.empty())
        j["robot_mean_dist"] = printed(meanDists(r.robotSegments));
    if (!r.odometrySegments.empty())
        j["dead_reckoning_mean_dist"] = printed(meanDists(r.odometrySegments));
    return j;
}

void addMapJson(TJson& j, const TMapErrors& m) {
    const auto& s = m.stats;
    const std::string p = pluralKey(m.kind);
    auto opt = [](const std::optional<size_t>& v) { return v ? TJson(*v) : TJson(); };
    TJson st;
    st["count"] = s.count;
    st["mean_dx"] = printed(s.mean_dx);
    st["mean_dy"] = printed(s.mean_dy);
    st["mean_dist"] = printed(s.mean_dist);
    st["max_dx"] = printed(s.max_dx);
    st["max_dy"] = printed(s.max_dy);
    st["max_dist"] = printed(s.max_dist);
    st["rmse_dist"] = printed(s.rmse_dist);
    j[p] = st;
    j[p + "_mapped"] = m.mapped;
    j[p + "_total"] = m.total;
    j[p + "_unknown_ids"] = m.unknownIds.size();
    j[p + "_passed_over"] = opt(m.passedOver);
    j[p + "_mapped_of_passed_over"] = opt(m.mappedOfPassedOver);
}
}  // namespace

TJson toJsonValue(const TEvalResult& r) {
    TJson j;
    j["label"] = r.label;
    if (r.robot) j["robot"] = robotJson(*r.robot);
    if (r.odometry) j["dead_reckoning"] = robotJson(*r.odometry);
    if (r.map) addMapJson(j, *r.map);
    if (!r.segmentBounds.empty()) j["segments"] = segmentsJson(r);
    return j;
}

std::string toJson(const TEvalResult& r) {
    return rfir::common::dumpJson(toJsonValue(r));
}

}  // namespace rfir::eval
