/* rfir: the robust offline smoother on Ceres ([smoother] solver = ceres; see
 * graph_smoother.h and docs/slam.md "Offline smoothing"). */
#include "graph_smoother_factors.h"
#include "graph_smoother_internal.h"

#include <rfir/models/odometry_noise.h>
#include <rfir/models/read_model.h>
#include <rfir/slam/detections.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <unordered_map>

namespace rfir::slam::detail {
namespace {
using TPose = std::array<double, 3>;
using TTag = std::array<double, 2>;

/** One reader's poll at step k and the tags it read. */
struct TPoll {
    size_t k;
    double cx, cy, hx, hy;
    std::vector<size_t> tags;
};

struct TGraph {
    size_t K = 0;
    std::vector<mrpt::poses::CPose2D> u;  //!< odometry increment per step
    std::vector<double> t;
    std::vector<TPoll> polls;
    std::vector<std::string> tagIds;
    std::unordered_map<std::string, size_t> tagIndex;
    std::vector<TPose> x;     //!< poses (heading unwrapped)
    std::vector<TTag> m;      //!< tags
    std::vector<bool> cut;    //!< cut[k]: no odometry factor into pose k
    std::vector<bool> moved;  //!< moved[k]: an odometry record ends at step k
    const std::vector<TSlamInput>* in = nullptr;  //!< the steps (odometry parts)
};

/** Distinct tags read again after `minTravel` m of odometry path since
 * their previous read. */
size_t closures(const TGraph& g, double minTravel) {
    std::vector<double> travel(g.K + 1, 0.0);
    for (size_t k = 0; k < g.K; k++)
        travel[k + 1] = travel[k] + std::hypot(g.u[k].x(), g.u[k].y());
    std::vector<double> last(g.tagIds.size(), -1);
    std::vector<bool> closed(g.tagIds.size(), false);
    for (const auto& p : g.polls)  // in step order
        for (size_t j : p.tags) {
            const double d = travel[p.k + 1];
            if (last[j] >= 0 && d - last[j] >= minTravel) closed[j] = true;
            last[j] = d;
        }
    return size_t(std::count(closed.begin(), closed.end(), true));
}

/** 1 / std (m, rad) of the tie between a step without odometry and the one before. */
constexpr double kSameRecordTie = 1e4;

TGraph collect(const std::vector<TSlamInput>& in, const TSlamRun& filtered) {
    TGraph g;
    g.K = in.size();
    g.in = &in;
    g.cut.assign(g.K, false);
    for (size_t k = 0; k < g.K; k++) {
        g.u.push_back(in[k].odometryIncrement.value_or(mrpt::poses::CPose2D()));
        g.moved.push_back(in[k].odometryIncrement.has_value());
        g.t.push_back(in[k].t);
        const auto& q = filtered.path[k].second;
        g.x.push_back({q.x(), q.y(), q.phi()});
        if (!in[k].rfid) continue;
        for (const auto& r : in[k].rfid->readings) {
            TPoll p{k, r.reader.x, r.reader.y, r.reader.halfX, r.reader.halfY, {}};
            for (const auto& id : r.tags) {
                auto [it, isNew] = g.tagIndex.try_emplace(id, g.tagIds.size());
                if (isNew) {
                    g.tagIds.push_back(id);
                    // Not in the filter's map: the first reader's centre.
                    const auto c = mrpt::poses::CPose2D(q.x(), q.y(), q.phi()) +
                                   mrpt::poses::CPose2D(p.cx, p.cy, 0);
                    g.m.push_back({c.x(), c.y()});
                }
                p.tags.push_back(it->second);
            }
            g.polls.push_back(std::move(p));
        }
    }
    for (const auto& l : filtered.map) {
        const auto it = g.tagIndex.find(l.id);
        if (l.isTag && it != g.tagIndex.end()) g.m[it->second] = {l.x, l.y};
    }
    return g;
}

/** Squared hinge cost of the reads of steps [a, b] with poses `x`. */
double readCost(const TGraph& g, const std::vector<TPose>& x, size_t a, size_t b,
                const std::vector<size_t>& pollIdx) {
    double c = 0;
    for (size_t i : pollIdx) {
        const auto& p = g.polls[i];
        if (p.k < a || p.k > b) continue;
        for (size_t j : p.tags) {
            double ex, ey;
            rfir::models::readModel(x[p.k].data(), g.m[j].data(), p.cx, p.cy, ex, ey);
            const double dx = std::max(0.0, std::abs(ex) - p.hx) / p.hx;
            const double dy = std::max(0.0, std::abs(ey) - p.hy) / p.hy;
            c += std::min(25.0, dx * dx + dy * dy);  // capped: ghost reads
        }
    }
    return c;
}

/** For each kidnap reset of the filter: the odometry increment across which
 * the robot was carried. Poses before it are chained forward from the
 * window's start, poses after it backward from the filter's pose `settle`
 * seconds after the reset; the split whose path fits the reads best is cut
 * and its chains become the initial path. */
void cutKidnappings(TGraph& g, const TSlamRun& filtered, double window,
                    std::vector<double>& cutTimes) {
    const double settle = 3.0;  // s for the reset filter to converge
    std::vector<size_t> pollIdx(g.polls.size());
    for (size_t i = 0; i < pollIdx.size(); i++) pollIdx[i] = i;
    for (double tr : filtered.resetTimes) {
        const auto at = [&](double t) {
            return size_t(std::lower_bound(g.t.begin(), g.t.end(), t) - g.t.begin());
        };
        const size_t ks = std::max<size_t>(1, at(tr - window));
        const size_t ka = std::min(g.K - 1, at(tr + settle));
        if (ks >= ka) continue;
        double best = std::numeric_limits<double>::infinity();
        size_t bestS = ks;
        std::vector<TPose> bestX;
        for (size_t s = ks; s <= ka; s++) {
            std::vector<TPose> x = g.x;
            mrpt::poses::CPose2D q(x[ks - 1][0], x[ks - 1][1], x[ks - 1][2]);
            for (size_t k = ks; k < s; k++) {
                q = q + g.u[k];
                x[k] = {q.x(), q.y(), q.phi()};
            }
            q = mrpt::poses::CPose2D(x[ka][0], x[ka][1], x[ka][2]);
            for (size_t k = ka; k > s; k--) {
                q = q + (-g.u[k]);
                x[k - 1] = {q.x(), q.y(), q.phi()};
            }
            const double c = readCost(g, x, ks, ka, pollIdx);
            if (c < best) best = c, bestS = s, bestX = std::move(x);
        }
        g.x = std::move(bestX);
        g.cut[bestS] = true;
        cutTimes.push_back(g.t[bestS]);
    }
}

/** Headings continuous along the path, so that the odometry residual needs
 * no wrapping. */
void unwrapHeadings(TGraph& g, const mrpt::poses::CPose2D& start) {
    double prev = start.phi();
    for (size_t k = 0; k < g.K; k++) {
        const double pred = prev + g.u[k].phi();
        g.x[k][2] = pred + mrpt::math::wrapToPi(g.x[k][2] - pred);
        prev = g.x[k][2];
    }
}

ceres::LossFunction* makeLoss(const std::string& kind, double scale) {
    if (kind == "huber") return new ceres::HuberLoss(scale);
    if (kind == "cauchy") return new ceres::CauchyLoss(scale);
    return nullptr;
}
}  // namespace

namespace {
/** The factors of `g` into `pb`; returns the read and miss factor counts. */
std::pair<size_t, size_t> addFactors(ceres::Problem& pb, TGraph& g, TPose& start,
                                     std::array<double, 2>& bias,
                                     const TGraphSmootherParams& p, int stage) {
    const bool withBias = stage == 2;
    const auto& o = p.options;
    for (size_t k = 0; k < g.K; k++) {
        if (g.cut[k]) continue;
        const auto& u = g.u[k];
        double wxy, wphi;
        detail::stepOdometryInformationSqrt((*g.in)[k], p.motion.noise(), wxy, wphi);
        // A poll between two odometry records sits at the earlier one, as in
        // the filters: tied to it, not given the noise floor of an increment
        // of its own (9 polls per record loosened the chain 3 x per metre).
        if (!g.moved[k]) wxy = wphi = kSameRecordTie;
        auto* f =
            new ceres::AutoDiffCostFunction<COdometryCost, 3, 3, 3, 2>(new COdometryCost{
                u.x(), u.y(), u.phi(), std::hypot(u.x(), u.y()), wxy, wphi});
        pb.AddResidualBlock(f, makeLoss(o.odometry_loss, o.odometry_loss_scale),
                            k ? g.x[k - 1].data() : start.data(), g.x[k].data(),
                            bias.data());
    }
    size_t reads = 0, misses = 0;
    for (const auto& q : g.polls) {
        const double tx = o.read_edge_smoothing * q.hx, ty = o.read_edge_smoothing * q.hy;
        const bool gaussian = stage == 0 || std::min(q.hx, q.hy) < o.flat_min_half_size;
        for (size_t j : q.tags) {
            if (gaussian) {
                pb.AddResidualBlock(
                    new ceres::AutoDiffCostFunction<CGaussianReadCost, 2, 3, 2>(
                        new CGaussianReadCost{q.cx, q.cy, 1 / (p.readStdFactor * q.hx),
                                              1 / (p.readStdFactor * q.hy)}),
                    makeLoss(o.read_loss, o.read_loss_scale), g.x[q.k].data(),
                    g.m[j].data());
                reads++;
                continue;
            }
            auto* f = new ceres::AutoDiffCostFunction<CReadCost, 2, 3, 2>(new CReadCost{
                q.cx, q.cy, q.hx, q.hy, tx, ty, o.read_tail_std_factor * q.hx,
                o.read_tail_std_factor * q.hy});
            pb.AddResidualBlock(f, makeLoss(o.read_loss, o.read_loss_scale),
                                g.x[q.k].data(), g.m[j].data());
            reads++;
        }
        if (gaussian || o.detection_probability <= 0) continue;
        // Negative information for the tags near the square (at the initial
        // estimate) that this poll did not read.
        const auto& x = g.x[q.k];
        const double mx = q.hx + 0.5 * q.hx + 0.05, my = q.hy + 0.5 * q.hy + 0.05;
        for (size_t j = 0; j < g.m.size(); j++) {
            double ex, ey;
            rfir::models::readModel(x.data(), g.m[j].data(), q.cx, q.cy, ex, ey);
            if (std::abs(ex) > mx || std::abs(ey) > my) continue;
            if (std::find(q.tags.begin(), q.tags.end(), j) != q.tags.end()) continue;
            auto* f = new ceres::AutoDiffCostFunction<CMissCost, 1, 3, 2>(
                new CMissCost{q.cx, q.cy, q.hx, q.hy, tx, ty, o.detection_probability});
            pb.AddResidualBlock(f, nullptr, g.x[q.k].data(), g.m[j].data());
            misses++;
        }
    }
    pb.SetParameterBlockConstant(start.data());
    // Each bias term is estimated (prior std > 0, last solve) or held at 0.
    const bool scale = withBias && o.scale_prior_std > 0;
    const bool drift = withBias && o.drift_prior_std > 0;
    if (scale || drift) {
        pb.AddResidualBlock(
            new ceres::AutoDiffCostFunction<CBiasPrior, 2, 2>(new CBiasPrior{
                scale ? 1 / o.scale_prior_std : 0, drift ? 1 / o.drift_prior_std : 0}),
            nullptr, bias.data());
        if (!scale || !drift)
            pb.SetManifold(bias.data(), new ceres::SubsetManifold(2, {scale ? 1 : 0}));
    } else
        pb.SetParameterBlockConstant(bias.data());
    return {reads, misses};
}
}  // namespace

TGraphSmootherResult smoothRunCeres(const std::vector<TSlamInput>& inputs,
                                    const mrpt::poses::CPose2D& start,
                                    const TSlamRun& filtered,
                                    const TGraphSmootherParams& params) {
    TGraphSmootherResult res;
    res.run = filtered;
    TGraph g = collect(inputs, filtered);
    if (g.K == 0) return res;
    cutKidnappings(g, filtered, params.options.kidnap_window, res.cutTimes);
    unwrapHeadings(g, start);
    TPose s0 = {start.x(), start.y(), start.phi()};
    std::array<double, 2> bias = {0, 0};
    // Three solves. Gaussian reads first: the flat-inside model has no
    // gradient inside the squares and, from a filter's path 160 mm off,
    // stopped in a worse optimum on the 60 mm loop (measured). Then the flat
    // model with negative information, the odometry bias held: freed from
    // the filter's path it ran off to a wrong scale (+0.1 on the 300 mm
    // loop). Last the bias too; each solve picks the unread tags anew.
    res.closures = closures(g, params.options.closure_min_travel);
    const bool wanted =
        params.options.drift_prior_std > 0 || params.options.scale_prior_std > 0;
    res.biasEstimated =
        wanted && res.closures >= size_t(params.options.bias_min_closures);
    res.biasHeld = wanted && !res.biasEstimated;
    TGraphSmootherParams solveParams = params;  // the bias held if not estimated
    if (!res.biasEstimated)
        solveParams.options.drift_prior_std = solveParams.options.scale_prior_std = 0;
    for (int stage = 0; stage < 3; stage++) {
        ceres::Problem pb;
        std::tie(res.reads, res.negatives) =
            addFactors(pb, g, s0, bias, solveParams, stage);
        ceres::Solver::Options so;
        so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
        so.max_num_iterations = params.options.max_iterations;
        so.num_threads = 1;  // same seed, same bytes
        so.logging_type = ceres::SILENT;
        ceres::Solver::Summary sum;
        ceres::Solve(so, &pb, &sum);
        if (!sum.IsSolutionUsable())
            throw std::runtime_error("smoothRun: the solver failed: " + sum.message);
        // Ceres' cost is half the sum of squared (robustified) residuals.
        if (stage == 0) res.initialCost = 2 * sum.initial_cost;
        res.finalCost = 2 * sum.final_cost;
        res.iterations += int(sum.iterations.size());
    }
    res.odometryScale = bias[0];
    res.headingDriftPerMetre = bias[1];
    for (size_t k = 0; k < g.K; k++)
        res.run.path[k].second =
            mrpt::poses::CPose2D(g.x[k][0], g.x[k][1], mrpt::math::wrapToPi(g.x[k][2]));
    res.run.map.clear();
    for (size_t j = 0; j < g.tagIds.size(); j++) {
        TLandmarkOut l;
        l.id = g.tagIds[j];
        l.x = g.m[j][0];
        l.y = g.m[j][1];
        res.run.map.push_back(l);
    }
    gaussianMarginalStds(inputs, start, params, res.run);
    return res;
}
}  // namespace rfir::slam::detail
