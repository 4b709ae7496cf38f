#include "loop_closure.h"

#include "tagmap_settings.h"

#include <rfir/models/detection_likelihood.h>

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace rfir::slam {
namespace {
/** Share of the window's reads the smoothed path must explain: the rest is
 * room for ghost reads (set before the first measurement). */
constexpr double kExplainedShare = 0.9;

/** Share of the RFID reads of the inputs with t > tEnd - window that the
 * smoothed run does not contradict (the map's own test, `det.contradicts`
 * with [tagmap] contradict_margin: a tag at its smoothed place, the reader at
 * the smoothed pose); tags absent from the map are not counted. `total` gets
 * the number of reads counted. */
double explainedShare(const std::vector<TSlamInput>& inputs, const TSlamRun& smoothed,
                      double window, const rfir::models::DetectionLikelihood& det,
                      double margin, size_t& total) {
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
        for (const auto& rd : inputs[k].rfid->readings) {
            const auto& r = rd.reader;
            const rfir::models::ReaderArea area{r.x, r.y, r.halfX, r.halfY};
            for (const auto& id : rd.tags) {
                const auto it = tags.find(id);
                if (it == tags.end()) continue;
                total++;
                explained += !det.contradicts(robot, area, it->second, margin);
            }
        }
    }
    return total ? double(explained) / double(total) : 0;
}
}  // namespace

std::optional<TGraphSmootherResult> smoothedLoopClosure(
    const std::vector<TSlamInput>& inputs, const mrpt::poses::CPose2D& start,
    const TSlamRun& soFar, const TSlamConfig& cfg) {
    // The question at a trigger is whether a drift explains it: estimate the
    // drift even from the few closures before the first return.
    auto params = smootherParams(cfg);
    params.options.bias_min_closures = 0;
    auto res = smoothRun(inputs, start, soFar, params);
    const rfir::models::DetectionLikelihood det(cfg.tagmap->likelihood.detection);
    size_t total = 0;
    const double share = explainedShare(inputs, res.run, cfg.kidnap.max_gap, det,
                                        cfg.tagmap->insertion.contradictMargin, total);
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
    } catch (const std::runtime_error&) {
        return std::nullopt;  // the solver failed: the resetting, as without the option
    }
    if (!res) return std::nullopt;
    path_.assign(res->run.path.begin(), res->run.path.end() - 1);
    return std::move(res->run);
}

}  // namespace rfir::slam
