/* rfir-experiments: outputs: JSON of every raw number, the markdown report,
 * the figures. */
#pragma once

#include <rfir/experiments/results.h>

#include <string>
#include <vector>

namespace rfir::experiments {
/** One JSON document with every run of every row (SI units). */
void writeJson(const std::string& path, const std::vector<TRowResults>& rows,
               const TMeta& meta);

/** The markdown report; images are linked as "img/exp_<row>*.png";
 * `notes` (markdown) is inserted after the summary. */
std::string markdownReport(const std::vector<TRowResults>& rows, const TMeta& meta,
                           const std::string& notes);

/** The figures of a row into DIR/img/exp_<row id>*.png; returns their file
 * names relative to DIR. */
std::vector<std::string> writeFigures(const std::string& outDir, const TRowResults& r);

/** The file names writeFigures produces for a row (for the markdown). */
std::vector<std::string> figureNames(const TRowResults& r);

}  // namespace rfir::experiments
