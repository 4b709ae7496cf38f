/* rfir: the IR receiver's voltage-vs-distance curve, thesis eq. 5.3, written
 * once. It lives in the lowest layer that needs it (observations, below the
 * localizer and the simulator): the localizer's likelihood and the
 * simulator's truth evaluate this same function. Units: metres and volts
 * (the thesis' fit takes millimetres). */
#pragma once

namespace rfir::ir {
/** Receiver voltage vs horizontal receiver-emitter distance d (eq. 5.3):
 * V = c2 d^2 + c1 d + c0. The thesis fits d in mm at a 1.2 m vertical distance
 * over 0-300 mm (-3.27e-5, 2.855e-3, 1.81997); in metres c2 = -32.7 V/m^2,
 * c1 = 2.855 V/m. */
struct TVoltageCurve {
    double c0 = 1.81997, c1 = 2.855, c2 = -32.7;
    double fitHeight = 1.2;     //!< vertical emitter-receiver distance of the fit (m)
    double maxDistance = 0.28;  //!< horizontal radius the fit (and sight) covers (m)
    enum class HeightModel {
        /** The curve as fitted, whatever the actual height (the thesis). */
        Fixed,
        /** The fitted profile scaled by the inverse square of the height:
         * V(d, h) = (h0/h)^2 V(d). */
        InverseSquare,
        /** Same off-axis angle gives the same beam intensity, scaled by the
         * inverse square of the distance: V(d, h) = (h0/h)^2 V(d h0 / h). */
        Angular
    };
    HeightModel heightModel = HeightModel::Fixed;

    /** Expected voltage (>= 0) at horizontal distance d for vertical distance h
     * (h only matters for Angular); 0 beyond visibleRadius(h). */
    double expected(double d, double h) const;
    /** Horizontal radius within which the emitter is seen. */
    double visibleRadius(double h) const;
};

}  // namespace rfir::ir
