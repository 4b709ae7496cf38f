/* rfir: IR sensor model functors (thesis eqs. 5.1-5.2; eq. 5.3 is in
 * observations, ir_voltage_curve.cpp). */
#include <rfir/ir/sensor_model.h>
#include <rfir/models/read_model.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rfir::ir {
double voltageLogLikelihood(double v, double vExpected, double sigma) {
    const double e = v - vExpected;
    return -e * e / (2 * sigma * sigma);
}

namespace {
/** Eq. 5.2 mixed with a uniform outlier component of weight w over [0, range]
 * V, in the units of voltageLogLikelihood (0 at V = Vbar when w = 0):
 * log((1 - w) exp(-e^2 / 2 sigma^2) + w sqrt(2 pi) sigma / range); w = 0 gives
 * voltageLogLikelihood exactly. */
double voltageMixtureLogLikelihood(double v, double vExpected, double sigma, double w,
                                   double range) {
    const double g = voltageLogLikelihood(v, vExpected, sigma);
    if (w <= 0) return g;
    // Both densities relative to the Gaussian's peak 1 / (sqrt(2 pi) sigma).
    const double u = w * std::sqrt(2 * M_PI) * sigma / range;
    return std::log((1 - w) * std::exp(g) + u);
}
}  // namespace

size_t mostLikelyEmitter(const std::vector<size_t>& candidates,
                         const std::vector<TEmitter>& emitters,
                         const mrpt::math::TPoint2D& r) {
    if (candidates.empty())
        throw std::invalid_argument("mostLikelyEmitter: no candidate");
    // argmax of eq. 5.1 = argmin of the squared distance (no underflow at
    // distances where exp() is 0 for every candidate).
    size_t best = candidates[0];
    double bestD2 = 1e300;
    for (size_t i : candidates) {
        const double dx = emitters[i].x - r.x, dy = emitters[i].y - r.y;
        const double d2 = dx * dx + dy * dy;
        if (d2 < bestD2) {
            bestD2 = d2;
            best = i;
        }
    }
    return best;
}

mrpt::math::TPoint2D receiverInWorld(const mrpt::math::TPose2D& p,
                                     const rfir::obs::TIRReceiver& r) {
    return rfir::models::robotFrameToWorld(p, std::cos(p.phi), std::sin(p.phi), r.x, r.y);
}

double readingLogLikelihood(double v, const mrpt::math::TPoint2D& rcv, const TEmitter& e,
                            double h, const TIRLikelihoodParams& p) {
    const double d = std::hypot(e.x - rcv.x, e.y - rcv.y);
    double ll = voltageMixtureLogLikelihood(v, p.curve.expected(d, h), p.sigmaVolts,
                                            p.voltOutlierWeight, p.voltOutlierRange);
    const double beyond = d - p.curve.visibleRadius(h);
    if (beyond > 0)
        ll += p.outOfRangeLogLik *
              (p.outOfRangeRamp > 0 ? std::min(1.0, beyond / p.outOfRangeRamp) : 1.0);
    return ll;
}

std::vector<double> distancesForVoltage(const TVoltageCurve& c, double v, double h) {
    // Solve in the fitted frame: (h0/h)^2 curve(d0) = v, d = d0 h / h0.
    double scale = 1.0, back = 1.0;
    if (c.heightModel != TVoltageCurve::HeightModel::Fixed && h > 0)
        scale = (c.fitHeight / h) * (c.fitHeight / h);
    if (c.heightModel == TVoltageCurve::HeightModel::Angular && h > 0)
        back = h / c.fitHeight;
    const double a = c.c2, b = c.c1, k = c.c0 - v / scale;
    std::vector<double> out;
    auto keep = [&](double d0) {
        if (d0 >= 0 && d0 <= c.maxDistance) out.push_back(d0 * back);
    };
    if (std::abs(a) < 1e-15) {
        if (std::abs(b) > 1e-15) keep(-k / b);
        return out;
    }
    const double disc = b * b - 4 * a * k;
    if (disc < 0) {
        // Above the curve's maximum (noise): the distance of the maximum.
        if (a < 0) keep(-b / (2 * a));
        return out;
    }
    const double r1 = (-b - std::sqrt(disc)) / (2 * a),
                 r2 = (-b + std::sqrt(disc)) / (2 * a);
    keep(std::min(r1, r2));
    if (r2 != r1) keep(std::max(r1, r2));
    return out;
}

}  // namespace rfir::ir
