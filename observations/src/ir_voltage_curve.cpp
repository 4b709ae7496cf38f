/* rfir: thesis eq. 5.3, the IR voltage curve (ir_voltage_curve.h). */
#include <rfir/obs/ir_voltage_curve.h>

#include <algorithm>

namespace rfir::ir {
double TVoltageCurve::visibleRadius(double h) const {
    if (heightModel == HeightModel::Angular && h > 0) return maxDistance * h / fitHeight;
    return maxDistance;
}

double TVoltageCurve::expected(double d, double h) const {
    double scale = 1.0, dd = d;
    if (heightModel != HeightModel::Fixed && h > 0)
        scale = (fitHeight / h) * (fitHeight / h);
    // Same angle off the LED axis: d / h = d0 / h0.
    if (heightModel == HeightModel::Angular && h > 0) dd = d * fitHeight / h;
    if (dd > maxDistance) return 0.0;
    return std::max(0.0, scale * (c2 * dd * dd + c1 * dd + c0));
}

}  // namespace rfir::ir
