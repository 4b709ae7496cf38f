/* rfir-experiments: outputs: JSON of every raw number, the markdown report,
 * the figures. */
#pragma once

#include <rfir/experiments/results.h>

#include <functional>
#include <string>
#include <vector>

namespace rfir::experiments {
/** One JSON document with every run of every row (SI units): the runs'
 * entries (TRunResult::entry), no timings, so that the same sweep gives the
 * same bytes however it ran. */
void writeJson(const std::string& path, const std::vector<TRowResults>& rows,
               const TMeta& meta);

/** The timings of the same runs (ms per step, seconds), the wall time, the
 * processes and the command line as given. */
void writeTimings(const std::string& path, const std::vector<TRowResults>& rows,
                  const TMeta& meta);

/** The markdown report; images are linked as "img/exp_<row>*.png";
 * `notes` (markdown) is inserted after the summary. */
std::string markdownReport(const std::vector<TRowResults>& rows, const TMeta& meta,
                           const std::string& notes);

/** Where to write a figure, given its file name (exp_<row id>*.png). */
using TFigurePath = std::function<std::string(const std::string& name)>;

/** The figures of a row drawn from its first seed alone (the path/map panels,
 * the kidnapping's error over time): their file names, and the drawing from
 * that seed's first data set and its runs (with paths and maps). */
std::vector<std::string> firstSeedFigureNames(const TRow& row);
void writeFirstSeedFigures(const TFigurePath& path, const TRow& row, const TDataSet& d,
                           const std::vector<TRunResult>& runs);

/** The figures of a row drawn from every seed (the sweeps' line plots). */
std::vector<std::string> sweepFigureNames(const TRow& row);
void writeSweepFigures(const TFigurePath& path, const TRowResults& r);

/** Every figure of a row as results.md links it: "img/exp_<row id>*.png". */
std::vector<std::string> figureNames(const TRow& row);

}  // namespace rfir::experiments
