/* rfir-eval: errors of an estimated path and map against the ground truth, in
 * the seeds' table layout (mm, rad) and as one JSON line; optional PNG figure
 * (the run is rfir_evalapp). */
#include <rfir/common/cli.h>
#include <rfir/evalapp/eval_app.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

namespace {
using rfir::evalapp::TEvalArgs;

/** Thrown to end the program with a given code, output already printed. */
struct TExit {
    int code;
};

/** Ends the program after --help / --version (0) or a parse error. */
void parseOrExit(TCLAP::CmdLine& cmd, int argc, char** argv) {
    if (const auto code = rfir::common::parseCommandLine(cmd, argc, argv))
        throw TExit{*code};
}

TEvalArgs parse(int argc, char** argv) {
    TCLAP::CmdLine cmd(
        "Compares an estimated robot path (TUM) and landmark map with the ground truth: "
        "mean and max of |dx|, |dy|, |dtheta| and distance (the seeds' tables), mapped "
        "vs passed-over tags. Prints a table (mm, rad) and one JSON line (m, rad).",
        ' ', RFIR_VERSION);
    TCLAP::ValueArg<std::string> path("", "path", "estimated robot path (TUM)", false, "",
                                      "EST.tum", cmd);
    TCLAP::ValueArg<std::string> gtPath("", "gt-path", "ground-truth path (TUM)", false,
                                        "", "GT.tum", cmd);
    TCLAP::ValueArg<std::string> map("", "map", "estimated map (tag/landmark records)",
                                     false, "", "EST_MAP", cmd);
    TCLAP::ValueArg<std::string> gtMap("", "gt-map", "ground-truth map", false, "",
                                       "GT_MAP", cmd);
    std::vector<std::string> kinds = {"tag", "landmark"};
    TCLAP::ValuesConstraint<std::string> kindNames(kinds);
    TCLAP::ValueArg<std::string> kind("", "kind",
                                      "map records to evaluate (default: those of the "
                                      "estimated map)",
                                      false, "", &kindNames, cmd);
    TCLAP::ValueArg<std::string> rawlog(
        "", "rawlog",
        std::string("the rawlog of the run: reader / sensor geometry for the "
                    "passed-over count, odometry for the dead-reckoning row") +
            rfir::common::kRawlogClassesHelp,
        false, "", "FILE", cmd);
    TCLAP::SwitchArg atGt("", "at-gt-times",
                          "pair each ground-truth pose with the estimate interpolated "
                          "at its time (sparse truth, e.g. the IR spots), instead of "
                          "each estimated pose with the interpolated truth",
                          cmd);
    TCLAP::SwitchArg noOdom("", "no-odometry", "no dead-reckoning row", cmd);
    TCLAP::ValueArg<std::string> label("", "label", "method name in the table and JSON",
                                       false, "estimate", "NAME", cmd);
    TCLAP::ValueArg<std::string> plot("", "plot", "write the path-and-map figure (PNG)",
                                      false, "", "OUT.png", cmd);
    TCLAP::ValueArg<std::string> errorPlot(
        "", "error-plot", "write the robot's position error vs time (PNG)", false, "",
        "OUT.png", cmd);
    TCLAP::ValueArg<std::string> title("", "title", "figure title (default: the label)",
                                       false, "", "TEXT", cmd);
    rfir::common::CNumberArg<int> segments(
        "", "segments",
        "also give the robot's mean error in N equal windows of the ground truth's "
        "time span (e.g. the laps of a loop)",
        false, 0, "N", cmd, 0, 1000000);
    TCLAP::SwitchArg ids("", "ids", "write landmark IDs on the figure", cmd);
    TCLAP::ValueArg<std::string> jsonFile("", "json-file",
                                          "also write the JSON line to "
                                          "FILE (atomically)",
                                          false, "", "FILE", cmd);
    TCLAP::SwitchArg jsonOnly("", "json-only", "print only the JSON line", cmd);
    TCLAP::SwitchArg quiet("q", "quiet", rfir::common::kQuietHelp, cmd);
    TCLAP::MultiArg<std::string> runs(
        "", "run",
        "a run to compare with the others (repeat it): its label, path and "
        "optional map; one table, one JSON line {\"runs\": [...]}, and --plot "
        "draws every path",
        false, "LABEL=EST.tum[,MAP]", cmd);
    parseOrExit(cmd, argc, argv);
    TEvalArgs a;
    a.path = path.getValue(), a.gtPath = gtPath.getValue(), a.map = map.getValue();
    a.gtMap = gtMap.getValue(), a.rawlog = rawlog.getValue(), a.label = label.getValue();
    a.plot = plot.getValue(), a.title = title.getValue(),
    a.jsonFile = jsonFile.getValue();
    a.kind = kind.getValue(), a.jsonOnly = jsonOnly.getValue();
    a.noOdometry = noOdom.getValue(), a.ids = ids.getValue();
    a.atGtTimes = atGt.getValue();
    a.errorPlot = errorPlot.getValue();
    a.segments = segments.getValue();
    a.quiet = quiet.getValue();
    for (const auto& r : runs.getValue()) a.runs.push_back(rfir::eval::parseRunSpec(r));
    rfir::evalapp::validateEvalArgs(a);
    return a;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return rfir::evalapp::runEvalApp(parse(argc, argv));
    } catch (const TExit& e) {
        return e.code;
    } catch (const rfir::common::CUsageError& e) {  // thrown before any work
        std::cerr << "rfir-eval: error: " << e.what() << "\n";
        return rfir::common::kUsageExitCode;
    } catch (const std::exception& e) {
        std::cerr << "rfir-eval: error: " << e.what() << "\n";
        return 1;
    }
}
