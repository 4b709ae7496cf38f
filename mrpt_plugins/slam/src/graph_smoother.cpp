/* rfir: Gauss-Newton (Levenberg-Marquardt damped) smoothing of a SLAM run over
 * odometry and Gaussian RFID read factors ([smoother] solver = lm), the tags'
 * marginal stds of both solvers, and smoothRun's dispatch; see graph_smoother.h. */
#include "graph_smoother_internal.h"

#include <rfir/models/detection_likelihood.h>
#include <rfir/models/odometry_noise.h>
#include <rfir/slam/detections.h>
#include <rfir/slam/graph_smoother.h>

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace rfir::slam {
namespace {
/** x_{k-1}^-1 (+) x_k = u, noise of MRPT's Gaussian odometry model (k = 0:
 * from the fixed start pose). */
struct TOdoFactor {
    double ux, uy, uphi;  //!< the increment
    double wxy, wphi;     //!< 1 / std
};
/** readModel(p_k, reader centre, tag) = 0 (eq. 6 of 003, inverted). */
struct TReadFactor {
    size_t k, tag;
    double cx, cy;  //!< reader centre, robot frame
    double wx, wy;  //!< 1 / std
};

struct TState {
    Eigen::VectorXd x;  //!< 3 per pose (x, y, phi), then 2 per tag
};

class CProblem {
  public:
    CProblem(const std::vector<TSlamInput>& in, const mrpt::poses::CPose2D& start,
             const TGraphSmootherParams& p)
        : K_(in.size()), start_(start) {
        odo_.reserve(K_);
        for (const auto& s : in) {
            const auto u = s.odometryIncrement.value_or(mrpt::poses::CPose2D());
            // The filters' odometry noise model (models/odometry_noise.h).
            double wxy, wphi;
            detail::stepOdometryInformationSqrt(s, p.motion.noise(), wxy, wphi);
            odo_.push_back({u.x(), u.y(), u.phi(), wxy, wphi});
        }
        for (size_t k = 0; k < K_; k++) {
            if (!in[k].rfid) continue;
            std::vector<TDetection> dets;
            appendDetections(*in[k].rfid, dets);
            for (const auto& d : dets) {
                auto [it, isNew] = tagIndex_.try_emplace(d.id, tagIds_.size());
                if (isNew) tagIds_.push_back(d.id), firstRead_.push_back(reads_.size());
                reads_.push_back({k, it->second, d.a, d.b,
                                  1.0 / (p.readStdFactor * d.halfX),
                                  1.0 / (p.readStdFactor * d.halfY)});
            }
        }
    }
    size_t dim() const { return 3 * K_ + 2 * tagIds_.size(); }
    size_t tagVar(size_t j) const { return 3 * K_ + 2 * j; }
    const std::vector<std::string>& tagIds() const { return tagIds_; }
    size_t reads() const { return reads_.size(); }

    TState initial(const std::vector<std::pair<double, mrpt::poses::CPose2D>>& path,
                   const std::vector<TLandmarkOut>& map) const {
        TState s;
        s.x.resize(dim());
        for (size_t k = 0; k < K_; k++) {
            const auto& q = path[k].second;
            s.x.segment<3>(3 * k) << q.x(), q.y(), q.phi();
        }
        std::unordered_map<std::string, const TLandmarkOut*> known;
        for (const auto& l : map)
            if (l.isTag) known[l.id] = &l;
        for (size_t j = 0; j < tagIds_.size(); j++) {
            const auto it = known.find(tagIds_[j]);
            if (it != known.end()) {
                s.x.segment<2>(tagVar(j)) << it->second->x, it->second->y;
                continue;
            }
            const auto& r = reads_[firstRead_[j]];  // the first reader's centre
            const auto p = s.x.segment<3>(3 * r.k);
            const auto c =
                rfir::models::readerCentreInWorld({p[0], p[1], p[2]}, {r.cx, r.cy, 0, 0});
            s.x.segment<2>(tagVar(j)) << c.x, c.y;
        }
        return s;
    }

    /** Sum of squared whitened residuals; with H and g, the normal equations. */
    double linearize(const TState& s, std::vector<Eigen::Triplet<double>>* H,
                     Eigen::VectorXd* g) const {
        double cost = 0;
        if (g) g->setZero(dim());
        for (size_t k = 0; k < K_; k++) cost += odoTerm(s, k, H, g);
        for (const auto& r : reads_) cost += readTerm(s, r, H, g);
        return cost;
    }

  private:
    /** Adds J_a^T J_b blocks and J^T r for whitened rows. */
    template <int R>
    static void accumulate(
        const std::vector<std::pair<size_t, Eigen::Matrix<double, R, -1>>>& J,
        const Eigen::Matrix<double, R, 1>& r, std::vector<Eigen::Triplet<double>>* H,
        Eigen::VectorXd* g) {
        for (const auto& [ia, Ja] : J) {
            if (g) g->segment(ia, Ja.cols()) += Ja.transpose() * r;
            if (!H) continue;
            for (const auto& [ib, Jb] : J) {
                const Eigen::MatrixXd blk = Ja.transpose() * Jb;
                for (int a = 0; a < blk.rows(); a++)
                    for (int b = 0; b < blk.cols(); b++)
                        H->emplace_back(int(ia + a), int(ib + b), blk(a, b));
            }
        }
    }

    double odoTerm(const TState& s, size_t k, std::vector<Eigen::Triplet<double>>* H,
                   Eigen::VectorXd* g) const {
        const auto& f = odo_[k];
        const Eigen::Vector3d prev =
            k ? Eigen::Vector3d(s.x.segment<3>(3 * (k - 1)))
              : Eigen::Vector3d(start_.x(), start_.y(), start_.phi());
        const Eigen::Vector3d cur = s.x.segment<3>(3 * k);
        const double c = std::cos(prev[2]), sn = std::sin(prev[2]);
        double h[3];  // the increment the two poses imply
        rfir::models::odometryModel(prev.data(), cur.data(), c, sn, h);
        const double lx = h[0], ly = h[1];
        const Eigen::Vector3d w(f.wxy, f.wxy, f.wphi);
        Eigen::Vector3d r(lx - f.ux, ly - f.uy, mrpt::math::wrapToPi(h[2] - f.uphi));
        r = r.cwiseProduct(w);
        if (H || g) {
            using J3 = Eigen::Matrix<double, 3, -1>;
            J3 Jc(3, 3), Jp(3, 3);
            Jc << c, sn, 0, -sn, c, 0, 0, 0, 1;
            Jp << -c, -sn, ly, sn, -c, -lx, 0, 0, -1;
            std::vector<std::pair<size_t, J3>> J{{3 * k, w.asDiagonal() * Jc}};
            if (k) J.push_back({3 * (k - 1), w.asDiagonal() * Jp});
            accumulate<3>(J, r, H, g);
        }
        return r.squaredNorm();
    }

    double readTerm(const TState& s, const TReadFactor& f,
                    std::vector<Eigen::Triplet<double>>* H, Eigen::VectorXd* g) const {
        const Eigen::Vector3d p = s.x.segment<3>(3 * f.k);
        const Eigen::Vector2d m = s.x.segment<2>(tagVar(f.tag));
        rfir::models::TReadJacobians Jr;
        const auto e =
            rfir::models::readModel({p[0], p[1], p[2]}, f.cx, f.cy, {m[0], m[1]}, &Jr);
        const Eigen::Vector2d w(f.wx, f.wy);
        const Eigen::Vector2d r = Eigen::Vector2d(e.x, e.y).cwiseProduct(w);
        if (H || g) {
            using J2 = Eigen::Matrix<double, 2, -1>;
            J2 Jp(2, 3), Jm(2, 2);
            Jp << Jr.pose[0][0], Jr.pose[0][1], Jr.pose[0][2], Jr.pose[1][0],
                Jr.pose[1][1], Jr.pose[1][2];
            Jm << Jr.tag[0][0], Jr.tag[0][1], Jr.tag[1][0], Jr.tag[1][1];
            accumulate<2>(
                {{3 * f.k, w.asDiagonal() * Jp}, {tagVar(f.tag), w.asDiagonal() * Jm}}, r,
                H, g);
        }
        return r.squaredNorm();
    }

    size_t K_;
    mrpt::poses::CPose2D start_;
    std::vector<TOdoFactor> odo_;
    std::vector<TReadFactor> reads_;
    std::vector<std::string> tagIds_;
    std::vector<size_t> firstRead_;
    std::unordered_map<std::string, size_t> tagIndex_;
};

/** The tag diagonal of H^-1, one solve per column. */
void marginals(const CProblem& pb, const TState& s, std::vector<TLandmarkOut>& map) {
    const int n = int(pb.dim());
    std::vector<Eigen::Triplet<double>> trip;
    Eigen::VectorXd g;
    pb.linearize(s, &trip, &g);
    Eigen::SparseMatrix<double> H(n, n);
    H.setFromTriplets(trip.begin(), trip.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    solver.compute(H);
    std::unordered_map<std::string, TLandmarkOut*> out;
    for (auto& l : map) out[l.id] = &l;
    for (size_t j = 0; j < pb.tagIds().size(); j++) {
        const auto it = out.find(pb.tagIds()[j]);
        if (it == out.end()) continue;
        const size_t v = pb.tagVar(j);
        for (int a = 0; a < 2; a++) {
            Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
            e[v + a] = 1;
            const double var =
                solver.info() == Eigen::Success ? solver.solve(e)[v + a] : 0;
            (a ? it->second->sy : it->second->sx) = std::sqrt(std::max(0.0, var));
        }
    }
}
}  // namespace

namespace detail {
void stepOdometryInformationSqrt(const TSlamInput& s,
                                 const rfir::models::OdometryNoiseParams& n, double& wxy,
                                 double& wphi) {
    const auto u = s.odometryIncrement.value_or(mrpt::poses::CPose2D());
    if (s.odometryParts.empty()) {
        rfir::models::odometryInformationSqrt(n, u.x(), u.y(), u.phi(), wxy, wphi);
        return;
    }
    double vxy = 0, vphi = 0;
    for (const auto& q : s.odometryParts) {
        double sxy, sphi;
        n.stds(q.interval.x(), q.interval.y(), q.interval.phi(), sxy, sphi);
        vxy += q.fraction * sxy * sxy;
        vphi += q.fraction * sphi * sphi;
    }
    // A poll exactly at a record (a zero share): as the noise floor of its
    // increment, not an infinite weight.
    double fxy, fphi;
    rfir::models::odometryInformationSqrt(n, u.x(), u.y(), u.phi(), fxy, fphi);
    wxy = vxy > 0 ? 1 / std::sqrt(vxy) : fxy;
    wphi = vphi > 0 ? 1 / std::sqrt(vphi) : fphi;
}

void gaussianMarginalStds(const std::vector<TSlamInput>& inputs,
                          const mrpt::poses::CPose2D& start,
                          const TGraphSmootherParams& params, TSlamRun& run) {
    const CProblem pb(inputs, start, params);
    marginals(pb, pb.initial(run.path, run.map), run.map);
}

TGraphSmootherResult smoothRunLM(const std::vector<TSlamInput>& inputs,
                                 const mrpt::poses::CPose2D& start,
                                 const TSlamRun& filtered,
                                 const TGraphSmootherParams& params) {
    const CProblem pb(inputs, start, params);
    TState s = pb.initial(filtered.path, filtered.map);
    TGraphSmootherResult res;
    res.run = filtered;
    res.reads = pb.reads();
    const int n = int(pb.dim());
    double cost = pb.linearize(s, nullptr, nullptr), lambda = 1e-6;
    res.initialCost = cost;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    Eigen::SparseMatrix<double> H(n, n);
    for (int it = 0; it < params.maxIterations; it++) {
        std::vector<Eigen::Triplet<double>> trip;
        Eigen::VectorXd g;
        pb.linearize(s, &trip, &g);
        H.setFromTriplets(trip.begin(), trip.end());
        double step = 0;
        for (int tries = 0; tries < 10; tries++) {  // Levenberg-Marquardt damping
            Eigen::SparseMatrix<double> A = H;
            for (int i = 0; i < n; i++)
                A.coeffRef(i, i) += lambda * (1.0 + H.coeff(i, i));
            solver.compute(A);
            if (solver.info() != Eigen::Success)
                throw std::runtime_error("smoothRun: the normal equations are singular");
            const Eigen::VectorXd dx = -solver.solve(g);
            TState t{s.x + dx};
            const double c = pb.linearize(t, nullptr, nullptr);
            if (c < cost) {
                s = std::move(t), cost = c, step = dx.cwiseAbs().maxCoeff();
                lambda = std::max(1e-9, lambda / 10);
                break;
            }
            lambda *= 10;
        }
        res.iterations = it + 1;
        if (step < params.tolerance) break;
    }
    res.finalCost = cost;
    for (size_t k = 0; k < inputs.size(); k++)
        res.run.path[k].second = mrpt::poses::CPose2D(
            s.x[3 * k], s.x[3 * k + 1], mrpt::math::wrapToPi(s.x[3 * k + 2]));
    res.run.map.clear();
    for (size_t j = 0; j < pb.tagIds().size(); j++) {
        TLandmarkOut l;
        l.id = pb.tagIds()[j];
        l.x = s.x[pb.tagVar(j)];
        l.y = s.x[pb.tagVar(j) + 1];
        res.run.map.push_back(l);
    }
    // Marginal stds at the final state (H above was linearised before the
    // last accepted step).
    marginals(pb, s, res.run.map);
    return res;
}
}  // namespace detail

TGraphSmootherParams smootherParams(const TSlamConfig& cfg) {
    TGraphSmootherParams p;
    p.motion = cfg.motion;
    if (cfg.smoother.odometry_a3 >= 0) p.motion.a3 = cfg.smoother.odometry_a3;
    p.options = cfg.smoother;
    p.maxIterations = cfg.smoother.max_iterations;
    return p;
}

TGraphSmootherResult smoothRun(const std::vector<TSlamInput>& inputs,
                               const mrpt::poses::CPose2D& start,
                               const TSlamRun& filtered,
                               const TGraphSmootherParams& params) {
    if (filtered.path.size() != inputs.size())
        throw std::invalid_argument("smoothRun: the path needs one pose per input");
    const auto t0 = std::chrono::steady_clock::now();
    auto res = params.options.solver == "lm"
                   ? detail::smoothRunLM(inputs, start, filtered, params)
                   : detail::smoothRunCeres(inputs, start, filtered, params);
    res.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
}

}  // namespace rfir::slam
