/* rfir-eval: the steps of one scoring run, separate from the command line. */
#pragma once

#include <rfir/eval/compare.h>

#include <mrpt/poses/CPose2D.h>

#include <optional>

#include <string>
#include <vector>

namespace rfir::evalapp {
struct TEvalArgs {
    std::string path, gtPath, map, gtMap, rawlog, label, plot, errorPlot, title, jsonFile,
        kind;
    bool jsonOnly = false, noOdometry = false, ids = false, atGtTimes = false,
         quiet = false;
    int segments = 0;
    std::vector<rfir::eval::TRunSpec> runs;  //!< --run: several runs side by side
    /** --path-format, --map-format: rfir's or an MRPT app's (also the --run
     * runs' unless one says its own). */
    rfir::eval::InputFormat pathFormat = rfir::eval::InputFormat::Rfir,
                            mapFormat = rfir::eval::InputFormat::Rfir;
    /** --start: the robot's start pose (default: the rawlog header's). */
    std::optional<mrpt::poses::CPose2D> start;
};

/** Option combinations the command-line parser cannot express; throws
 * rfir::common::CUsageError naming the options. */
void validateEvalArgs(const TEvalArgs& a);

/** Scores the run(s), writes the figures and the JSON file, prints the table
 * and the JSON line; returns the process exit code. Throws std::exception with
 * a message for the user on bad input. */
int runEvalApp(const TEvalArgs& a);

}  // namespace rfir::evalapp
