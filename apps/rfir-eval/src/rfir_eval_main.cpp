/* rfir-eval: errors of an estimated path and map against the ground truth, in
 * the papers' table layout (mm, rad) and as one JSON line; optional PNG figure
 * (the run is rfir_evalapp). Reads rfir's files and what MRPT's rbpf-slam and
 * pf-localization write. */
#include <rfir/common/cli.h>
#include <rfir/evalapp/eval_app.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

namespace {
using rfir::evalapp::TEvalArgs;
using TCLAP::SwitchArg;
using TCLAP::ValueArg;
using TStrArg = TCLAP::ValueArg<std::string>;

/** Thrown to end the program with a given code, output already printed. */
struct TExit {
    int code;
};

const char* kDescription =
    "Compares an estimated robot path and landmark map with the ground truth: mean "
    "and max of |dx|, |dy|, |dtheta| and distance (the papers' tables), mapped vs "
    "passed-over tags. Prints a table (mm, rad) and one JSON line (m, rad). Reads "
    "rfir's files (TUM paths, rfir's map records) and, with --path-format mrpt / "
    "--map-format mrpt, what MRPT's rbpf-slam and pf-localization write "
    "(docs/mrpt-apps.md).";

/** The command line; its fields are the options. */
struct TOptions {
    TCLAP::CmdLine cmd{kDescription, ' ', RFIR_VERSION};
    TStrArg path{"",
                 "path",
                 "estimated robot path: TUM (a file that is not is refused, saying what "
                 "it looks like), or with --path-format mrpt rbpf-slam's "
                 "log_estimated_path.txt or pf-localization's output folder",
                 false,
                 "",
                 "EST",
                 cmd};
    std::vector<std::string> pathFormats{"tum", "mrpt"};
    TCLAP::ValuesConstraint<std::string> pathFormatNames{pathFormats};
    TStrArg pathFormat{"",
                       "path-format",
                       "how --path (and --run paths without their own) is written: tum, "
                       "or mrpt (rbpf-slam's path composed with the log's start pose: "
                       "needs --rawlog or --start; pf-localization's folder: needs "
                       "--rawlog)",
                       false,
                       "tum",
                       &pathFormatNames,
                       cmd};
    TStrArg gtPath{"", "gt-path", "ground-truth path (TUM)", false, "", "GT.tum", cmd};
    TStrArg map{"",        "map", "estimated map (tag/landmark records)", false, "",
                "EST_MAP", cmd};
    std::vector<std::string> mapFormats{"rfir", "mrpt"};
    TCLAP::ValuesConstraint<std::string> mapFormatNames{mapFormats};
    TStrArg mapFormat{
        "",
        "map-format",
        "how --map (and --run maps without their own) is written: rfir, or "
        "mrpt (a map rbpf-slam saved: CBeaconMap's or CLandmarksMap's text, "
        "or rfir's tag map's, composed with the log's start pose)",
        false,
        "rfir",
        &mapFormatNames,
        cmd};
    TStrArg gtMap{"", "gt-map", "ground-truth map", false, "", "GT_MAP", cmd};
    std::vector<std::string> kinds{"tag", "landmark"};
    TCLAP::ValuesConstraint<std::string> kindNames{kinds};
    TStrArg kind{
        "",    "kind", "map records to evaluate (default: those of the estimated map)",
        false, "",     &kindNames,
        cmd};
    TStrArg rawlog{"",
                   "rawlog",
                   std::string("the rawlog of the run: reader / sensor geometry for the "
                               "passed-over count, odometry for the dead-reckoning row, "
                               "the start pose and instants for MRPT's outputs") +
                       rfir::common::kRawlogClassesHelp,
                   false,
                   "",
                   "FILE",
                   cmd};
    rfir::common::CNumberListArg<double> start{
        "",    "start",   "the robot's start pose X Y PHI (default: the rawlog header's)",
        false, "X Y PHI", cmd,
        ' ',   3};
    SwitchArg atGt{"", "at-gt-times",
                   "pair each ground-truth pose with the estimate interpolated at its "
                   "time (sparse truth, e.g. the IR spots), instead of each estimated "
                   "pose with the interpolated truth",
                   cmd};
    SwitchArg noOdom{"", "no-odometry", "no dead-reckoning row", cmd};
    TStrArg label{"",     "label", "method name in the table and JSON", false, "estimate",
                  "NAME", cmd};
    TStrArg plot{"",        "plot", "write the path-and-map figure (PNG)", false, "",
                 "OUT.png", cmd};
    TStrArg errorPlot{
        "",    "error-plot", "write the robot's position error vs time (PNG)",
        false, "",           "OUT.png",
        cmd};
    TStrArg title{"",     "title", "figure title (default: the label)", false, "",
                  "TEXT", cmd};
    rfir::common::CNumberArg<int> segments{
        "",
        "segments",
        "also give the robot's mean error in N equal windows of the ground truth's time "
        "span (e.g. the laps of a loop)",
        false,
        0,
        "N",
        cmd,
        0,
        1000000};
    SwitchArg ids{"", "ids", "write landmark IDs on the figure", cmd};
    TStrArg jsonFile{"",    "json-file", "also write the JSON line to FILE (atomically)",
                     false, "",          "FILE",
                     cmd};
    SwitchArg jsonOnly{"", "json-only", "print only the JSON line", cmd};
    SwitchArg quiet{"q", "quiet", rfir::common::kQuietHelp, cmd};
    TCLAP::MultiArg<std::string> runs{
        "",
        "run",
        "a run to compare with the others (repeat it): its label, path and optional "
        "map; 'mrpt:' before the path: an MRPT app's path and map (as --path-format "
        "mrpt --map-format mrpt); one table, one JSON line {\"runs\": [...]}, and --plot "
        "draws every path",
        false,
        "LABEL=[mrpt:]EST[,MAP]",
        cmd};
};

TEvalArgs parse(int argc, char** argv) {
    TOptions o;
    std::vector<std::string> args(argv, argv + argc);
    rfir::common::foldOptionValues(args, "--start", 3);
    if (const auto code = rfir::common::parseCommandLine(o.cmd, args)) throw TExit{*code};
    TEvalArgs a;
    a.path = o.path.getValue(), a.gtPath = o.gtPath.getValue(), a.map = o.map.getValue();
    a.gtMap = o.gtMap.getValue(), a.rawlog = o.rawlog.getValue();
    a.label = o.label.getValue(), a.plot = o.plot.getValue(),
    a.title = o.title.getValue();
    a.jsonFile = o.jsonFile.getValue();
    a.kind = o.kind.getValue(), a.jsonOnly = o.jsonOnly.getValue();
    a.noOdometry = o.noOdom.getValue(), a.ids = o.ids.getValue();
    a.atGtTimes = o.atGt.getValue();
    a.errorPlot = o.errorPlot.getValue();
    a.segments = o.segments.getValue();
    a.quiet = o.quiet.getValue();
    using rfir::eval::parseInputFormat;
    a.pathFormat = parseInputFormat("--path-format", o.pathFormat.getValue());
    a.mapFormat = parseInputFormat("--map-format", o.mapFormat.getValue());
    if (o.start.isSet()) {
        const auto& v = o.start.values();
        a.start = mrpt::poses::CPose2D(v[0], v[1], v[2]);
    }
    for (const auto& r : o.runs.getValue()) a.runs.push_back(rfir::eval::parseRunSpec(r));
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
