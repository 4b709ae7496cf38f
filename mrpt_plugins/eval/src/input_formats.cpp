/* rfir: the TUM shape check and the dispatch on --path-format / --map-format. */
#include <rfir/eval/input_formats.h>

#include "input_rows.h"

#include <rfir/common/text_input.h>
#include <rfir/common/usage_error.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace rfir::eval {
namespace detail {
std::vector<TTextRow> readTextRows(const std::string& file, const std::string& what,
                                   size_t maxRows) {
    std::ifstream f;
    rfir::common::openTextInput(f, file, what);
    std::vector<TTextRow> rows;
    std::string line;
    for (size_t ln = 1; rfir::common::getBoundedLine(f, line, file, ln); ln++) {
        std::istringstream s(line);
        TTextRow r{ln, {}};
        for (std::string t; s >> t;) r.tokens.push_back(t);
        if (r.tokens.empty() || r.tokens[0][0] == '#' || r.tokens[0][0] == '%') continue;
        rows.push_back(std::move(r));
        if (maxRows && rows.size() >= maxRows) break;
    }
    if (f.bad()) throw std::runtime_error(file + ": read error");
    return rows;
}

bool toNumber(const std::string& tok, double& v) {
    char* end = nullptr;
    v = std::strtod(tok.c_str(), &end);
    return !tok.empty() && *end == '\0' && std::isfinite(v);
}

std::vector<double> numbersOf(const TTextRow& r, const std::string& file, size_t n,
                              const std::string& expected) {
    std::vector<double> v(r.tokens.size());
    bool ok = !n || r.tokens.size() == n;
    for (size_t i = 0; ok && i < r.tokens.size(); i++) ok = toNumber(r.tokens[i], v[i]);
    if (!ok)
        throw std::runtime_error(file + ":" + std::to_string(r.line) + ": expected " +
                                 expected);
    return v;
}
}  // namespace detail

using detail::TTextRow;

InputFormat parseInputFormat(const std::string& option, const std::string& s) {
    if (s == "tum" || s == "rfir") return InputFormat::Rfir;
    if (s == "mrpt") return InputFormat::Mrpt;
    throw rfir::common::CUsageError(option + ": '" + s + "' is not tum, rfir or mrpt");
}

namespace {
/** Column 0 counts 0 or 1, 2, 3, ... over two rows or more: MRPT's step
 * numbers. */
bool stepColumn(const std::vector<std::vector<double>>& rows) {
    if (rows.size() < 2) return false;
    for (size_t i = 0; i < rows.size(); i++)
        if (rows[i][0] != rows[0][0] + double(i) || rows[0][0] > 1) return false;
    return true;
}

/** What rows of `n` numbers each (not TUM's unit quaternions) look like. */
std::string lookalike(const std::vector<std::vector<double>>& rows, size_t n) {
    const bool steps = stepColumn(rows);
    if (n == 8 && steps)
        return "it looks like MRPT rbpf-slam's log_estimated_path.txt (step x y z yaw "
               "pitch roll t): use --path-format mrpt";
    if (n == 7 && steps)
        return "it looks like MRPT rbpf-slam's log_odometry_path.txt (step x y z yaw "
               "pitch roll): the odometry, not an estimate";
    if (n == 4)
        return "it has 4 numbers a row, as pf-localization's particles_NNNNN.txt (x y "
               "phi log_weight): give pf-localization's output folder with "
               "--path-format mrpt";
    if (n == 3)
        return "it has 3 numbers a row (x y phi, as MRPT rbpf-slam's "
               "most_likely_path.txt or pf-localization's odo_est.txt): poses without "
               "times, no path to score";
    return "it has " + std::to_string(n) + " numbers a row; TUM has 8";
}
}  // namespace

std::string tumShapeProblem(const std::string& file) {
    if (std::filesystem::is_directory(file))
        return "it is a folder (pf-localization's output folder? use --path-format mrpt)";
    // The first rows tell the layout; the TUM reader checks every row after.
    const auto rows = detail::readTextRows(file, "path file", 5000);
    std::vector<std::vector<double>> nums;
    for (const TTextRow& r : rows) {
        std::vector<double> v(r.tokens.size());
        for (size_t i = 0; i < v.size(); i++)
            if (!detail::toNumber(r.tokens[i], v[i])) {
                const std::string& t = r.tokens[0];
                if (t == "tag" || t == "landmark" || t == "emitter")
                    return "it looks like a map (tag / landmark / emitter records): "
                           "give it with --map";
                return {};  // the TUM reader names the line
            }
        if (!nums.empty() && v.size() != nums[0].size()) return {};
        nums.push_back(std::move(v));
    }
    if (nums.empty()) return {};
    const size_t n = nums[0].size();
    if (n != 8) return lookalike(nums, n);
    for (size_t i = 0; i < nums.size(); i++) {
        const auto& v = nums[i];
        const double norm =
            std::sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
        if (std::abs(norm - 1) > 1e-3) {
            const std::string l = lookalike(nums, n);
            if (l.rfind("it looks like", 0) == 0) return l;
            std::ostringstream o;
            o << "columns 5 to 8 of line " << rows[i].line << " are no unit quaternion "
              << "(norm " << norm << ")";
            return o.str();
        }
    }
    return {};
}

rfir::common::TPath2D loadTumChecked(const std::string& file) {
    const std::string problem = tumShapeProblem(file);
    if (!problem.empty())
        throw std::runtime_error(file +
                                 ": not a TUM path (t x y z qx qy qz qw, a unit "
                                 "quaternion): " +
                                 problem);
    return rfir::common::loadTUM(file);
}

rfir::common::TPath2D loadPath(const std::string& file, InputFormat f,
                               const TMrptFrame& frame) {
    if (f == InputFormat::Rfir) return loadTumChecked(file);
    if (std::filesystem::is_directory(file)) return loadPfLocalizationPath(file, frame);
    if (!frame.start)
        throw std::runtime_error(
            file +
            ": rbpf-slam's path starts at the origin: give the log's start pose "
            "(--start X Y PHI, or --rawlog with a header start pose)");
    return loadRbpfSlamPath(file, *frame.start);
}

}  // namespace rfir::eval
