/* rfir-ir-experiments: thesis 5.4.1-5.4.5 (tables 5.2, 5.3) in simulation. */
#include <rfir/irexp/tables.h>

#include <rfir/eval/plot.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace rfir::irexp {
namespace fs = std::filesystem;

std::string fmt(double v, int decimals) {
    std::ostringstream o;
    o.setf(std::ios::fixed);
    o.precision(decimals);
    o << v;
    return o.str();
}

std::string tableHeader(const std::string& first) {
    return "| " + first +
           " | mean x [mm] | mean y [mm] | mean θ [rad] | mean dr [mm] | max x [mm] | "
           "max y [mm] | max θ [rad] | max dr [mm] "
           "|\n|---|---|---|---|---|---|---|---|---|\n";
}

std::string statsRow(const std::string& label, const rfir::eval::TErrorStats& s) {
    return "| " + label + " | " + fmt(1000 * s.mean_dx, 0) + " | " +
           fmt(1000 * s.mean_dy, 0) + " | " + fmt(s.mean_dtheta, 2) + " | " +
           fmt(1000 * s.mean_dist, 0) + " | " + fmt(1000 * s.max_dx, 0) + " | " +
           fmt(1000 * s.max_dy, 0) + " | " + fmt(s.max_dtheta, 2) + " | " +
           fmt(1000 * s.max_dist, 0) + " |\n";
}

namespace {
std::string thesisRow(const std::string& label, const double v[8]) {
    std::ostringstream o;
    o << "| " << label;
    for (int i = 0; i < 8; i++) o << " | " << (i % 4 == 2 ? fmt(v[i], 2) : fmt(v[i], 0));
    o << " |\n";
    return o.str();
}

std::string startNote(const TAggregate& a) {
    return a.started == a.runs
               ? ""
               : " (" + std::to_string(a.runs - a.started) + " of " +
                     std::to_string(a.runs) + " runs never saw a unique ID)";
}
}  // namespace

namespace {
std::string figure(const TExperimentRun& s, const TOptions& opt, const TRunSpec& spec,
                   const std::string& name, const std::string& caption) {
    const std::string dir = s.workDir + "/fig_" + name;
    runOne(s, spec, s.firstSeed, dir);
    fs::create_directories(opt.imgDir);
    fs::copy_file(dir + "/path_map.png", opt.imgDir + "/" + name,
                  fs::copy_options::overwrite_existing);
    return "![" + caption + "](" + opt.imgRel + "/" + name + ")\n\n*" + caption + "*\n\n";
}
}  // namespace

namespace {
struct TRoom {
    std::string name, mixed, unique;
    std::vector<std::string> uniqueSets;
};

/** Table 5.2 in one room: the three configurations (and the per-particle
 * association) at the spots, all of them and from 10 s after the start. */
std::string roomSection(const TExperimentRun& s, const TOptions& opt, const TRoom& room) {
    const double tProp[8] = {22, 29, 0.06, 36, 69, 79, 0.23, 105};
    const double tUniq[8] = {30, 25, 0.04, 39, 87, 91, 0.10, 126};
    const double tOdo[8] = {94, 55, 0.03, 108, 161, 99, 0.08, 189};
    TRunSpec mixed{room.mixed}, particle{room.mixed}, uniq{room.unique}, odo{room.mixed};
    particle.locSets = {"MetricMap_irEmitterMap_00_likelihoodOpts.association=particle"};
    uniq.simSets = room.uniqueSets;
    odo.odometryOnly = true;
    const auto aM = aggregate(runSeeds(s, mixed, opt.seeds));
    const auto aP = aggregate(runSeeds(s, particle, opt.seeds));
    const auto aU = aggregate(runSeeds(s, uniq, opt.seeds));
    const auto aO = aggregate(runSeeds(s, odo, opt.seeds));
    std::ostringstream md;
    md << "### " << room.name << "\n\n"
       << tableHeader("configuration")
       << statsRow("unique + repeated IDs (thesis association)", aM.spots)
       << statsRow("unique + repeated IDs (per-particle association)", aP.spots)
       << statsRow("unique IDs only (same positions)", aU.spots)
       << statsRow("odometry only", aO.spots)
       << thesisRow("*thesis: proposed system*", tProp)
       << thesisRow("*thesis: 11 unique IDs*", tUniq)
       << thesisRow("*thesis: odometry*", tOdo)
       << "\nOnly the spots from 10 s after the first unique ID (the start transient "
          "left "
          "out):\n\n"
       << tableHeader("configuration")
       << statsRow("unique + repeated IDs (thesis association)", aM.spotsSettled)
       << statsRow("unique + repeated IDs (per-particle association)", aP.spotsSettled)
       << statsRow("unique IDs only (same positions)", aU.spotsSettled)
       << statsRow("odometry only", aO.spotsSettled) << "\n"
       << "Whole path from the first unique ID (mean dr): unique + repeated "
       << fmt(1000 * aM.path.mean_dist, 1) << " mm, unique only "
       << fmt(1000 * aU.path.mean_dist, 1) << " mm, odometry "
       << fmt(1000 * aO.path.mean_dist, 1) << " mm; first unique ID after "
       << fmt(aM.meanStart, 1) << " s on average" << startNote(aM) << ".\n\n";
    return md.str();
}
}  // namespace

std::string expConfigurations(const TExperimentRun& s, const TOptions& opt) {
    progress(s, "configurations (table 5.2)");
    std::ostringstream md;
    md << "## Emitter configurations at 70 marked spots (thesis 5.4.1-5.4.2, table "
          "5.2)\n\n"
       << "Loop x3 at 200 mm/s, 70 spots (1 s stop each), unknown start; errors at the "
          "spots (spots before the first unique ID are not scored), "
       << opt.seeds << " seeds (mean of the per-run means, max of the maxima).\n\n";
    const TRoom rooms[] = {
        {"Lattice room 3.2 x 2.4 m (20 repeated + 12 unique emitters, 16 IDs)",
         "sim_ir_loop.ini",
         "sim_ir_unique_only.ini",
         {}},
        {"Strip room 2.4 x 0.8 m (8 repeated + 3 unique emitters, 7 IDs: the thesis' "
         "counts)",
         "sim_ir_exp_strip.ini",
         "sim_ir_exp_strip.ini",
         {"ir.all_unique=true"}}};
    for (const auto& room : rooms) md << roomSection(s, opt, room);
    TRunSpec mixed{"sim_ir_loop.ini"}, odo{"sim_ir_loop.ini"},
        strip{"sim_ir_exp_strip.ini"};
    odo.odometryOnly = true;
    const std::string seed = "seed " + std::to_string(s.firstSeed);
    md << figure(s, opt, mixed, "ir_loop_mixed.png",
                 "Lattice room, unique + repeated IDs, " + seed +
                     ": estimate (red) against the ground truth (blue), odometry "
                     "(grey), emitters (orange)")
       << figure(s, opt, strip, "ir_strip_mixed.png",
                 "Strip room (the thesis' 3 unique + 8 repeated emitters), " + seed)
       << figure(s, opt, odo, "ir_loop_odometry.png",
                 "Lattice room, odometry only, " + seed);
    return md.str();
}

std::string expRotation(const TExperimentRun& s, const TOptions& opt) {
    progress(s, "rotation (5.4.3)");
    TRunSpec rot{"sim_ir_rotation.ini"}, odo{"sim_ir_rotation.ini"};
    odo.odometryOnly = true;
    const auto aR = aggregate(runSeeds(s, rot, opt.seeds));
    const auto aO = aggregate(runSeeds(s, odo, opt.seeds));
    std::ostringstream md;
    md << "## Trajectory with rotations (thesis 5.4.3)\n\nOne loop turning in place at "
          "each "
          "corner (the robot faces its direction of travel), unknown start; every pose "
          "from "
          "the first unique ID, "
       << opt.seeds << " seeds. The thesis shows this only as a figure (5.14).\n\n"
       << tableHeader("configuration") << statsRow("unique + repeated IDs", aR.path)
       << statsRow("unique + repeated IDs, from 10 s after the start", aR.settled)
       << statsRow("odometry only", aO.path) << "\n"
       << figure(s, opt, rot, "ir_rotation.png",
                 "Loop with rotations, seed " + std::to_string(s.firstSeed));
    return md.str();
}

std::string expSpeeds(const TExperimentRun& s, const TOptions& opt) {
    progress(s, "speeds (5.4.4)");
    std::ostringstream md;
    md << "## Robot speeds (thesis 5.4.4)\n\nThe loop x3 with 70 spots at 100-300 mm/s, "
       << opt.seeds
       << " seeds; errors at the spots. The thesis reports, from figure 5.15, "
          "that speed does not change the accuracy.\n\n"
       << tableHeader("speed [mm/s]");
    for (const char* v : {"0.10", "0.15", "0.20", "0.25", "0.30"}) {
        TRunSpec sp{"sim_ir_loop.ini"};
        sp.simSets = {std::string("trajectory.speed=") + v};
        const auto a = aggregate(runSeeds(s, sp, opt.seeds));
        md << statsRow(fmt(1000 * std::stod(v), 0), a.spots)
           << statsRow(fmt(1000 * std::stod(v), 0) + ", from 10 s after the start",
                       a.spotsSettled);
    }
    TRunSpec fast{"sim_ir_loop.ini"};
    fast.simSets = {"trajectory.speed=0.30"};
    md << "\n"
       << figure(s, opt, fast, "ir_speed_300.png",
                 "Loop x3 at 300 mm/s, seed " + std::to_string(s.firstSeed));
    return md.str();
}

std::string expFailures(const TExperimentRun& s, const TOptions& opt) {
    progress(s, "failed emitters (5.4.5)");
    TRunSpec ok{"sim_ir_loop.ini"}, failed{"sim_ir_failed.ini"};
    const auto aK = aggregate(runSeeds(s, ok, opt.seeds));
    const auto aF = aggregate(runSeeds(s, failed, opt.seeds));
    std::ostringstream md;
    md << "## Two failed emitters (thesis 5.4.5)\n\nThe two repeated-ID emitters with "
          "code 4 "
          "at (0.8, 0.8) and (2.4, 0.8) send nothing but stay in the map; loop x3, 70 "
          "spots, "
       << opt.seeds
       << " seeds. The thesis (figure 5.16): \"the instability increases, the "
          "accuracy is acceptable\".\n\n"
       << tableHeader("emitters") << statsRow("all working", aK.spots)
       << statsRow("two failed", aF.spots)
       << statsRow("all working, from 10 s after the start", aK.spotsSettled)
       << statsRow("two failed, from 10 s after the start", aF.spotsSettled) << "\n"
       << figure(s, opt, failed, "ir_failed.png",
                 "Two failed emitters, seed " + std::to_string(s.firstSeed));
    return md.str();
}

}  // namespace rfir::irexp
