/* rfir: the IR sensor model of thesis chapter 5 as small functors: the
 * voltage-vs-distance curve (eq. 5.3), the voltage likelihood (eq. 5.2) and the
 * belief that picks one of the emitters sharing a repeated ID (eq. 5.1).
 * Units: metres and volts (the thesis' curve takes millimetres). */
#pragma once

#include <rfir/obs/CObservationIRSignals.h>
#include <rfir/obs/ir_lattice.h>
#include <rfir/obs/ir_voltage_curve.h>  // TVoltageCurve, eq. 5.3

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <cstddef>
#include <vector>

namespace rfir::ir {
/** Eq. 5.2 in log form with alpha = 1: -(V - Vbar)^2 / (2 sigma^2). */
double voltageLogLikelihood(double v, double vExpected, double sigma);

/** Index (into `emitters`) of the candidate with the largest belief of eq. 5.1,
 * exp(-|x_p - x_r|^2 / (2 sigma^2)), which falls with the distance whatever
 * sigma: the candidate nearest to `receiver`. Candidates must be non-empty. */
size_t mostLikelyEmitter(const std::vector<size_t>& candidates,
                         const std::vector<TEmitter>& emitters,
                         const mrpt::math::TPoint2D& receiver);

/** World position of a receiver mounted on a robot at `robot`. */
mrpt::math::TPoint2D receiverInWorld(const mrpt::math::TPose2D& robot,
                                     const rfir::obs::TIRReceiver& r);

/** Parameters of the per-reading likelihood beyond eq. 5.2. */
struct TIRLikelihoodParams {
    TVoltageCurve curve;
    /** sigma of eq. 5.2 (the thesis does not give it). Wider than the voltage
     * noise: readings at 10 Hz of one emitter are strongly correlated, and a
     * narrow sigma depletes the particles while the heading is still ambiguous
     * (docs/results_ir.md). */
    double sigmaVolts = 0.2;
    double sigmaBelief = 0.03;  //!< sigma of eq. 5.1 (the thesis: 30 mm)
    /** Log-likelihood added when the receiver would be beyond the detected
     * emitter's visible radius (it could not have seen it); 0 disables it
     * (the thesis' eq. 5.2 alone). */
    double outOfRangeLogLik = -8.0;
    /** The out-of-range term ramps in linearly over this distance (m) past the
     * visible radius, so that a track a centimetre off at the edge of view is
     * not thrown away. */
    double outOfRangeRamp = 0.05;
    /** Negative information (not in the thesis): log-likelihood added when a
     * receiver that saw nothing would be within missRadiusFraction of the
     * visible radius of some emitter of the map; 0 disables it. Failed
     * emitters stay in the map, so it is kept mild. */
    double missLogLik = 0.0;
    double missRadiusFraction = 0.8;
    /** The robot stays under the emitters: a pose farther than areaMargin
     * outside their bounding box gets outOfAreaLogLik per observation (not in
     * the thesis; 0 disables it). */
    double areaMargin = 0.5;
    double outOfAreaLogLik = 0.0;
    /** Voltage outliers (not in the thesis): eq. 5.2 becomes the mixture
     * (1 - w) N(V; Vbar, sigma) + w U(0, voltOutlierRange), so that one wild
     * voltage (a reflection, a glitch) bounds the loss of a good pose;
     * 0 keeps eq. 5.2 exactly. */
    double voltOutlierWeight = 0.0;
    double voltOutlierRange = 4.0;  //!< V: width of the uniform component
};

/** Log-likelihood of one reading (voltage v) from an emitter at `emitter`, for
 * a receiver at `receiver`, `h` metres below it: eq. 5.2 with eq. 5.3, plus the
 * out-of-range term. */
double readingLogLikelihood(double v, const mrpt::math::TPoint2D& receiver,
                            const TEmitter& emitter, double h,
                            const TIRLikelihoodParams& p);

/** Horizontal distances at which the curve gives voltage v (0, 1 or 2 roots in
 * [0, visibleRadius]; above the curve's maximum, the distance of the maximum);
 * used to draw poses from a reading (sensor resetting). */
std::vector<double> distancesForVoltage(const TVoltageCurve& c, double v, double h);

}  // namespace rfir::ir
