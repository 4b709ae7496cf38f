/* rfir-experiments: the sweeps (detection range, robot particles), the
 * kidnapping and the robot-update policy rows. */
#include <rfir/experiments/experiment.h>

#include <cstdio>
#include <string>

namespace rfir::experiments {
namespace {
std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof(b), "%g", v);
    return b;
}

std::vector<TMethodSpec> filterMethods() {
    return {{"PS-SLAM", "ps", {}}, {"PF-SLAM", "pf", {}}, {"FastSLAM", "fastslam", {}}};
}

/** Thesis fig. 4.4: 100-500 mm squares, five predefined paths x3, 4 tags/m^2.
 * The paths are moved inwards (margin 0.65 m) to run 0.1 m from a row of
 * tags: with the stock 0.5 m margin they run midway between the rows (0.25 m
 * away), out of reach of readers under about 250 mm on three of the paths. */
TRow rangeSweep() {
    TRow r;
    r.id = "range_sweep";
    r.title = "detection range 100-500 mm (4 tags/m^2, 5 predefined paths x3)";
    r.source = "thesis fig. 4.4";
    r.kind = TRowKind::Sweep;
    for (int k = 1; k <= 5; k++)
        r.runs.push_back(
            {"trajectory " + std::to_string(k),
             "sim_rfid_300mm_4tags_predef1.ini",
             {"trajectory.predefined=" + std::to_string(k), "trajectory.margin=0.65"}});
    for (double mm : {100, 150, 200, 250, 300, 400, 500})
        r.points.push_back(
            {num(mm) + " mm", mm, {"robot.reader_half_size=" + num(mm / 2000.0)}, {}});
    r.methods = filterMethods();
    r.paperClaim =
        "PS-SLAM and PF-SLAM equal below about 180 mm, PS-SLAM better above; "
        "FastSLAM worst, growing with the range";
    r.xLabel = "detection square side [mm]";
    r.maxSeeds = 3;
    return r;
}

/** Thesis fig. 3.6 / 4.1(a): accuracy and time per update against M. */
TRow particleSweep() {
    TRow r;
    r.id = "particles_sweep";
    r.title = "robot particles M = 100-5000 (60 mm, 16 tags/m^2, rectangle x3)";
    r.source = "thesis fig. 3.6, 4.1(a)";
    r.kind = TRowKind::Sweep;
    r.runs = {{"", "sim_rfid_60mm_16tags_loop.ini", {}}};
    for (double m : {100, 200, 500, 1000, 2000, 5000})
        r.points.push_back({"M = " + num(m), m, {}, {"slam.robot_particles=" + num(m)}});
    r.methods = filterMethods();
    r.paperClaim =
        "time per update grows linearly with M for every method; PF/PS-SLAM "
        "cost does not grow with the number of tags, FastSLAM's does";
    r.xLabel = "robot particles M";
    r.logX = true;
    r.plotTime = true;
    r.maxSeeds = 3;
    return r;
}

/** The papers do not give their odometry noise: a setup with the stock INI's
 * odometry noise (every [odometry] parameter) scaled. Run on the 60 mm and
 * the 300 mm setups, it shows whether any one level suits both. */
TRow odometrySweep(const std::string& id, const std::string& ini,
                   const std::string& setup) {
    TRow r;
    r.id = id;
    r.title = "odometry noise x0.25-x2 of the stock INI (" + setup + ")";
    r.source = "ours (the papers' odometry noise is unknown)";
    r.kind = TRowKind::Sweep;
    r.runs = {{"", ini, {}}};
    for (double f : {0.25, 0.5, 1.0, 2.0}) {
        TPoint p{"x" + num(f), f, {}, {}};
        p.odometryScale = f;
        r.points.push_back(p);
    }
    r.methods = {{"PS-SLAM", "ps", {}},
                 {"PF-SLAM", "pf", {}},
                 {"FastSLAM", "fastslam", {}},
                 {"Dead reckoning", "odometry", {}}};
    r.paperClaim =
        "(not in the papers; their tables come from one unstated odometry noise)";
    r.xLabel = "odometry noise factor";
    r.logX = true;
    return r;
}

/** Thesis 3.4.3: carried to a visited place without odometry; PF-SLAM recovers. */
TRow kidnapRow() {
    TRow r;
    r.id = "kidnap";
    r.title =
        "kidnapping (60 mm, 16 tags/m^2, rectangle x3; carried back to a visited place)";
    r.source = "thesis section 3.4.3, fig. 3.12";
    r.kind = TRowKind::Kidnap;
    r.runs = {{"", "sim_kidnap.ini", {}}};
    r.points = {TPoint{"", 0, {}, {"kidnap.enabled=true"}}};
    r.methods = {{"PS-SLAM", "ps", {}},
                 {"PF-SLAM", "pf", {}},
                 {"FastSLAM", "fastslam", {}},
                 {"Dead reckoning", "odometry", {}}};
    r.paperClaim = "PF-SLAM notices the kidnapping and recovers an accurate estimate";
    r.figure = true;
    return r;
}

/** The robot-update policy (the map's robot_update): the PF-SLAM paper's
 * Algorithm 1 as written ("literal": update the tag with this detection, then weigh the
 * robot with it, so the detection counts twice) against weighing with the estimate from
 * before the visit ("revisit": first read of a visit; "revisit_all": every read of a
 * visit). */
TRow policyRow(const std::string& id, const std::string& title, const std::string& ini) {
    TRow r;
    r.id = id;
    r.title = title;
    r.source = "robot-update policy (ours)";
    r.kind = TRowKind::Table;
    r.runs = {{"", ini, {}}};
    r.points = {TPoint{}};
    for (const char* m : {"ps", "pf"})
        for (const char* pol : {"literal", "revisit", "revisit_all"})
            r.methods.push_back({std::string(m[1] == 's' ? "PS-SLAM " : "PF-SLAM ") + pol,
                                 m,
                                 {std::string("tagmap_likelihood.robot_update=") + pol}});
    r.paperClaim = "(not in the papers)";
    return r;
}
}  // namespace

void addSweepRows(std::vector<TRow>& rows) {
    rows.push_back(rangeSweep());
    rows.push_back(kidnapRow());
    rows.push_back(particleSweep());
    rows.push_back(odometrySweep("odometry_sweep", "sim_rfid_60mm_16tags_loop.ini",
                                 "60 mm, 16 tags/m^2, rectangle x3"));
    rows.push_back(odometrySweep("odometry_sweep_300mm",
                                 "sim_rfid_300mm_4tags_random.ini",
                                 "300 mm, 4 tags/m^2, random path"));
}

void addPolicyRows(std::vector<TRow>& rows) {
    rows.push_back(policyRow("policy_60mm", "policy: 60 mm, 16 tags/m^2, random path",
                             "sim_rfid_60mm_16tags_random.ini"));
    rows.push_back(policyRow("policy_300mm", "policy: 300 mm, 4 tags/m^2, random path",
                             "sim_rfid_300mm_4tags_random.ini"));
}

/** --quick: one sub-run, the end points of sweeps, 40 s of simulated time. */
void trimForQuick(std::vector<TRow>& rows) {
    for (auto& r : rows) {
        r.runs.resize(1);
        if (r.points.size() > 2) r.points = {r.points.front(), r.points.back()};
        auto& o = r.runs.front().simOverrides;
        o.push_back("simulation.max_duration=40");
        if (r.kind == TRowKind::Kidnap)
            for (const char* s : {"kidnap.time=25", "kidnap.to_time=5"}) o.push_back(s);
    }
    for (auto& r : rows)
        if (r.id == "particles_sweep")
            r.points = {{"M = 100", 100, {}, {"slam.robot_particles=100"}},
                        {"M = 300", 300, {}, {"slam.robot_particles=300"}}};
}

}  // namespace rfir::experiments
