#include "loop_closure.h"

#include "tagmap_settings.h"

#include <rfir/models/read_model.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace rfir::slam {
namespace {
/** Share of the window's reads the smoothed path must explain: the rest is
 * room for ghost reads (set before the first measurement). */
constexpr double kExplainedShare = 0.9;
}  // namespace

double explainedShare(const std::vector<TSlamInput>& inputs, const TSlamRun& smoothed,
                      double window, double margin, size_t& total) {
    total = 0;
    if (inputs.empty() || smoothed.path.size() != inputs.size()) return 0;
    std::unordered_map<std::string, mrpt::math::TPoint2D> tags;
    for (const auto& l : smoothed.map)
        if (l.isTag) tags[l.id] = {l.x, l.y};
    const double tEnd = inputs.back().t;
    size_t explained = 0;
    for (size_t k = inputs.size(); k-- > 0 && inputs[k].t > tEnd - window;) {
        if (!inputs[k].rfid) continue;
        const auto robot = smoothed.path[k].second.asTPose();
        const double c = std::cos(robot.phi), s = std::sin(robot.phi);
        for (const auto& rd : inputs[k].rfid->readings)
            for (const auto& id : rd.tags) {
                const auto it = tags.find(id);
                if (it == tags.end()) continue;
                const auto& r = rd.reader;
                const auto e = rfir::models::readModel(robot, c, s, r.x, r.y, it->second);
                total++;
                if (std::abs(e.x) <= r.halfX + margin &&
                    std::abs(e.y) <= r.halfY + margin)
                    explained++;
            }
    }
    return total ? double(explained) / double(total) : 0;
}

std::optional<TGraphSmootherResult> smoothedLoopClosure(
    const std::vector<TSlamInput>& inputs, const mrpt::poses::CPose2D& start,
    const TSlamRun& soFar, const TSlamConfig& cfg) {
    // The question at a trigger is whether a drift explains it: estimate the
    // drift even from the few closures before the first return.
    auto params = smootherParams(cfg);
    params.options.bias_min_closures = 0;
    auto res = smoothRun(inputs, start, soFar, params);
    // A read contradicts a tag beyond contradict_margin outside its square
    // (as the map's own test); the share leaves room for ghost reads.
    const double margin = std::max(0.0, cfg.tagmap->insertion.contradictMargin);
    size_t total = 0;
    const double share =
        explainedShare(inputs, res.run, cfg.kidnap.max_gap, margin, total);
    if (total == 0 || share < kExplainedShare) return std::nullopt;
    return res;
}

std::optional<TSlamRun> CRunHistory::closeLoop(double t, const mrpt::poses::CPose2D& now,
                                               std::vector<TLandmarkOut> map,
                                               const std::vector<double>& resetTimes,
                                               const TSlamConfig& cfg) {
    TSlamRun soFar;
    soFar.path = path_;
    soFar.path.emplace_back(t, now);
    soFar.map = std::move(map);
    soFar.resetTimes = resetTimes;
    std::optional<TGraphSmootherResult> res;
    try {
        res = smoothedLoopClosure(inputs_, start_, soFar, cfg);
    } catch (const std::exception&) {
        return std::nullopt;  // the solver failed: the resetting, as without the option
    }
    if (!res) return std::nullopt;
    path_.assign(res->run.path.begin(), res->run.path.end() - 1);
    return std::move(res->run);
}

}  // namespace rfir::slam
