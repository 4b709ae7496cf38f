/* rfir: the robust smoother's factors as Ceres auto-differentiated cost
 * functors (graph_smoother_ceres.cpp). Poses are (x, y, phi) with phi
 * unwrapped along the path; tags (x, y). The read model and the odometry
 * model are the models layer's templates, evaluated here over Jets. */
#pragma once

#include <rfir/models/miss_model.h>
#include <rfir/models/odometry_noise.h>
#include <rfir/models/read_model.h>

#include <ceres/ceres.h>

#include <cmath>

namespace rfir::slam::detail {
using rfir::models::smoothAbs;

/** The step model's shape along one axis: zero inside the half-size h,
 * growing linearly outside it, the corner rounded over tau (a softplus). */
template <class T>
T hinge(const T& e, double h, double tau) {
    using std::exp;
    using std::log;
    const T z = (smoothAbs(e, tau) - h) / tau;
    if (z > T(30)) return z * tau;  // log(1 + e^z) = z to double precision
    return T(tau) * log(T(1) + exp(z));
}

/** Odometry increment u between poses p and c; bias b = (translation scale,
 * heading drift per metre): the robot moved (1 + b0) u_xy and turned
 * u_phi + b1 d (d = |u_xy|). Whitened by the [motion] model's stds. */
struct COdometryCost {
    double ux, uy, uphi, d, wxy, wphi;
    template <class T>
    bool operator()(const T* p, const T* c, const T* b, T* r) const {
        using std::cos;
        using std::sin;
        T h[3];
        rfir::models::odometryModel(p, c, T(cos(p[2])), T(sin(p[2])), h);
        const T s = T(1) + b[0];
        r[0] = wxy * (h[0] - s * ux);
        r[1] = wxy * (h[1] - s * uy);
        r[2] = wphi * (h[2] - uphi - b[1] * d);
        return true;
    }
};

/** A read: the tag inside the reader's square (zero residual), else the
 * distance from the square's edge over the tail std. */
struct CReadCost {
    double cx, cy, hx, hy, tauX, tauY, sx, sy;
    template <class T>
    bool operator()(const T* p, const T* m, T* r) const {
        T ex, ey;
        rfir::models::readModel(p, m, cx, cy, ex, ey);
        // The rounded corner lies outside the square: a tag on its edge costs
        // nothing (the band between this and CMissCost's favours neither).
        r[0] = hinge(ex, hx + tauX, tauX) / sx;
        r[1] = hinge(ey, hy + tauY, tauY) / sy;
        return true;
    }
};

/** A read as a Gaussian about the reader's centre (the `lm` solver's
 * model, std = factor x half-size): the first, convex-like solve, from which
 * the flat-inside model starts. */
struct CGaussianReadCost {
    double cx, cy, wx, wy;
    template <class T>
    bool operator()(const T* p, const T* m, T* r) const {
        T ex, ey;
        rfir::models::readModel(p, m, cx, cy, ex, ey);
        r[0] = ex * wx;
        r[1] = ey * wy;
        return true;
    }
};

/** A polled reader that did not read the tag: -log(1 - pd P(inside)), as a
 * residual r with r^2 / 2 that cost. */
struct CMissCost {
    double cx, cy, hx, hy, tauX, tauY, pd;
    template <class T>
    bool operator()(const T* p, const T* m, T* r) const {
        using std::log;
        using std::sqrt;
        T ex, ey;
        rfir::models::readModel(p, m, cx, cy, ex, ey);
        // The logistic's slope lies inside the square: a tag just outside
        // it, as every unread tag near a reader is, costs nothing (a soft
        // edge on the square itself pushed the whole map outwards).
        const T pin = rfir::models::readProbability(ex, ey, hx, hy, tauX, tauY);
        // The tiny constant keeps sqrt differentiable where pin is 0.
        r[0] = sqrt(T(-2) * log(T(1) - pd * pin) + T(1e-12));
        return true;
    }
};

/** Gaussian prior of the odometry bias about zero. */
struct CBiasPrior {
    double wScale, wDrift;
    template <class T>
    bool operator()(const T* b, T* r) const {
        r[0] = wScale * b[0];
        r[1] = wDrift * b[1];
        return true;
    }
};
}  // namespace rfir::slam::detail
