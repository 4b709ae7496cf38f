/* rfir: the text rows of the files rfir-eval reads (internal). */
#pragma once

#include <string>
#include <vector>

namespace rfir::eval::detail {
/** One data row: its line number and tokens. */
struct TTextRow {
    size_t line = 0;
    std::vector<std::string> tokens;
};

/** The data rows of a text file: blank lines and comments (`#` as in TUM and
 * rfir's files, `%` as in MRPT's) left out; at most `maxRows` (0: all).
 * Throws std::runtime_error naming the file (`what` says what it should be). */
std::vector<TTextRow> readTextRows(const std::string& file, const std::string& what,
                                   size_t maxRows = 0);

/** The token as a finite number, or false. */
bool toNumber(const std::string& tok, double& v);

/** The tokens of a row as finite numbers; std::runtime_error "FILE:LINE:
 * expected <expected>" when one is not, or when there are not `n` (0: any). */
std::vector<double> numbersOf(const TTextRow& r, const std::string& file, size_t n,
                              const std::string& expected);
}  // namespace rfir::eval::detail
