/* rfir-experiments: the rows of the papers' experiments with their numbers:
 * the thesis' tables 3.1, 3.2, 4.1, 4.2, figs. 4.4, 3.6, 4.1 and section
 * 3.4.3; the PS-SLAM paper's tables 4, 6, 7 (docs/bibliography.md [1] [3]). */
#include <rfir/experiments/experiment.h>

#include <string>

namespace rfir::experiments {
namespace {
const double N = kNaN;

std::vector<TMethodSpec> threeMethods() {
    return {{"PS-SLAM", "ps", {}},
            {"PF-SLAM", "pf", {}},
            {"FastSLAM", "fastslam", {}},
            {"Dead reckoning", "odometry", {}}};
}

TSubRun one(const std::string& ini) {
    return {"", ini, {}};
}

/** The five predefined trajectories (three laps each) from one sim INI. */
std::vector<TSubRun> fivePredefined(const std::string& ini) {
    std::vector<TSubRun> v;
    for (int k = 1; k <= 5; k++)
        v.push_back({"trajectory " + std::to_string(k),
                     ini,
                     {"trajectory.predefined=" + std::to_string(k)}});
    return v;
}

TRow tableRow(const std::string& id, const std::string& title, const std::string& source,
              std::vector<TSubRun> runs, std::vector<TPaperNumbers> seeds,
              const std::string& claim) {
    TRow r;
    r.id = id;
    r.title = title;
    r.source = source;
    r.kind = TRowKind::Table;
    r.runs = std::move(runs);
    r.points = {TPoint{}};
    r.methods = threeMethods();
    r.paperNumbers = std::move(seeds);
    r.paperClaim = claim;
    r.figure = true;
    return r;
}

void addThesisChapter3(std::vector<TRow>& rows) {
    rows.push_back(tableRow("t31_16", "60 mm readers, 16 tags/m^2, rectangle x3",
                            "thesis table 3.1", {one("sim_rfid_60mm_16tags_loop.ini")},
                            {{"FastSLAM", 27.6, 24.0, 0.022, 36.6, 19.0, 28.9, 34.6, ""},
                             {"PF-SLAM", 20.8, 25.8, 0.015, 33.1, 26.7, 23.1, 35.3, ""}},
                            "PF-SLAM and FastSLAM about equal (about 35 mm)"));
    rows.push_back(tableRow("t31_100", "60 mm readers, 100 tags/m^2, rectangle x3",
                            "thesis table 3.1", {one("sim_rfid_60mm_100tags_loop.ini")},
                            {{"FastSLAM", 44.4, 43.7, 0.031, 62.3, 44.7, 33.2, 55.7, ""},
                             {"PF-SLAM", 23.2, 23.9, 0.011, 33.3, 25.7, 24.1, 35.2, ""}},
                            "PF-SLAM better than FastSLAM (35 against 60 mm)"));
    rows.push_back(
        tableRow("t32_16", "60 mm readers, 16 tags/m^2, random path", "thesis table 3.2",
                 {one("sim_rfid_60mm_16tags_random.ini")},
                 {{"FastSLAM", 122.0, 72.6, 0.076, 142.0, 147.0, 71.3, 163.4, ""},
                  {"PF-SLAM", 10.8, 26.8, 0.006, 28.9, 9.3, 26.9, 28.5, ""}},
                 "PF-SLAM far better than FastSLAM (29 against 142 mm)"));
    rows.push_back(tableRow("t32_100", "60 mm readers, 100 tags/m^2, random path",
                            "thesis table 3.2", {one("sim_rfid_60mm_100tags_random.ini")},
                            {{"FastSLAM", 47.5, 57.9, 0.019, 74.9, 52.0, 45.6, 69.2, ""},
                             {"PF-SLAM", 20.3, 37.1, 0.003, 42.3, 13.6, 23.4, 27.1, ""}},
                            "PF-SLAM better than FastSLAM (42 against 75 mm)"));
}

void addLargeReaderRows(std::vector<TRow>& rows) {
    std::vector<TSubRun> predef;
    for (int k = 1; k <= 5; k++)
        predef.push_back({"trajectory " + std::to_string(k),
                          "sim_rfid_300mm_4tags_predef" + std::to_string(k) + ".ini",
                          {}});
    rows.push_back(
        tableRow("t41", "300 mm readers, 4 tags/m^2, 5 predefined paths x3",
                 "thesis table 4.1", predef,
                 {{"PS-SLAM", 25.4, 45.1, 0.006, 53.8, 50.3, 51.2, 79.0, ""},
                  {"PF-SLAM", 41.4, 66.6, 0.003, 82.1, 66.1, 80.1, 110.5, ""},
                  {"FastSLAM", 315.1, 204.5, 0.182, 420.8, 296.6, 210.1, 412.1, ""}},
                 "PS-SLAM < PF-SLAM < FastSLAM (54 < 82 < 421 mm)"));
    rows.push_back(tableRow("t42", "300 mm readers, 4 tags/m^2, random path",
                            "thesis table 4.2 (PS-SLAM paper table 5)",
                            {one("sim_rfid_300mm_4tags_random.ini")},
                            {{"PS-SLAM", N, N, 0.010, 29.1, N, N, 50.4, ""},
                             {"PF-SLAM", N, N, N, 66.7, N, N, 82.3, ""},
                             {"FastSLAM", N, N, N, 245.7, N, N, 280.0, ""}},
                            "PS-SLAM < PF-SLAM < FastSLAM (29 < 67 < 246 mm)"));
    rows.push_back(
        tableRow("p4_t4", "300 mm readers, 4 tags/m^2, 5 predefined paths with rotation",
                 "PS-SLAM paper table 4", fivePredefined("sim_rfid_300mm_rotation.ini"),
                 {{"PS-SLAM", N, N, 0.005, 36, N, N, 66, "about"},
                  {"FastSLAM", N, N, N, 300, N, N, 300, "over"}},
                 "PS-SLAM best (about 36 / 66 mm), FastSLAM over 300 mm"));
}

void addRangeBearingRows(std::vector<TRow>& rows) {
    rows.push_back(
        tableRow("p4_t6", "range-bearing sensor, 5 predefined paths without rotation",
                 "PS-SLAM paper table 6", fivePredefined("sim_rb_norotation.ini"),
                 {{"PS-SLAM", N, N, 0.016, 113, N, N, 112, "about"}},
                 "PS-SLAM about equal to PF-SLAM, both better than FastSLAM"));
    rows.push_back(
        tableRow("p4_t7", "range-bearing sensor, 5 predefined paths with rotation",
                 "PS-SLAM paper table 7", fivePredefined("sim_rb_rotation.ini"),
                 {{"PS-SLAM", N, N, 0.012, 97, N, N, 93, "about"},
                  {"FastSLAM", N, N, N, 270, N, N, N, "about"}},
                 "PS-SLAM better than PF-SLAM; FastSLAM about 270 mm"));
}
}  // namespace

void addSweepRows(std::vector<TRow>& rows);   // rows_sweeps.cpp
void addPolicyRows(std::vector<TRow>& rows);  // rows_sweeps.cpp
void trimForQuick(std::vector<TRow>& rows);   // rows_sweeps.cpp

std::vector<TRow> allRows(bool quick) {
    std::vector<TRow> rows;
    addThesisChapter3(rows);
    addLargeReaderRows(rows);
    addRangeBearingRows(rows);
    addSweepRows(rows);
    addPolicyRows(rows);
    if (quick) trimForQuick(rows);
    return rows;
}

}  // namespace rfir::experiments
