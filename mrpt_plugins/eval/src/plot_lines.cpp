/* Line plots for parameter sweeps (thesis figs. 3.6, 3.7, 4.4). */
#include "plot_internal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <tuple>

namespace rfir::eval {
using namespace detail;

namespace {
bool usable(double v, bool log) {
    return std::isfinite(v) && (!log || v > 0);
}

/** Data range of one axis, padded (5 %, in log space for log axes). */
std::pair<double, double> range(const TLinePlot& p, bool isX, std::optional<double> lo,
                                std::optional<double> hi) {
    const bool log = isX ? p.logX : p.logY;
    double a = std::numeric_limits<double>::infinity(), b = -a;
    for (const auto& s : p.series)
        for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); i++)
            if (usable(s.x[i], p.logX) && usable(s.y[i], p.logY)) {
                const double v = isX ? s.x[i] : s.y[i];
                a = std::min(a, v), b = std::max(b, v);
            }
    if (!(b >= a)) a = log ? 1 : 0, b = log ? 10 : 1;
    auto f = [&](double v) { return log ? std::log10(v) : v; };
    auto g = [&](double v) { return log ? std::pow(10.0, v) : v; };
    const double dataMin = a, dataMax = b;
    double fa = f(a), fb = f(b);
    if (fb - fa < 1e-12) {
        const double w = log ? 0.5 : std::max(std::abs(fa) * 0.1, 0.5);
        fa -= w, fb += w;
    }
    const double pad = 0.05 * (fb - fa);
    a = lo ? *lo : g(fa - pad);
    b = hi ? *hi : g(fb + pad);
    // A linear y axis of non-negative data starts at 0 when 0 is not far off
    // (errors, times: the reader compares magnitudes).
    if (!isX && !log && !lo && dataMin >= 0 && dataMin <= 0.3 * dataMax) a = 0;
    if (!(b > a) || (log && a <= 0))
        throw std::runtime_error("line plot: empty or invalid axis range");
    return {a, b};
}

/** A log x axis over a few swept values is ticked at those values (a sweep's
 * 100 and 300 would otherwise show as 100 and 200). Empty when not so. */
TTicks sweptTicks(const TLinePlot& p, double a, double b) {
    std::vector<double> v;
    for (const auto& s : p.series)
        for (double x : s.x)
            if (usable(x, true) && x >= a && x <= b) v.push_back(x);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    TTicks t;
    if (v.size() < 2 || v.size() > 8) return t;
    for (size_t i = 1; i < v.size(); i++)
        if (v[i] / v[i - 1] < 1.15) return t;  // labels would overlap
    for (double x : v) {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%g", x);
        t.values.push_back(x);
        t.labels.push_back(buf);
    }
    return t;
}

TTicks ticksFor(double a, double b, bool log, int pixels) {
    if (log) {
        TTicks t = logTicks(a, b);
        if (t.values.size() >= 2) return t;
    }
    return linearTicks(a, b, niceStep((b - a) / std::max(2, pixels / 90)));
}
}  // namespace

mrpt::img::CImage renderLinePlot(const TLinePlot& p, TPlotAxes* axesOut) {
    CImage img = blankCanvas(p.width, p.height);
    std::vector<TLegendEntry> legend;
    for (size_t i = 0; i < p.series.size(); i++) {
        const auto& s = p.series[i];
        if (s.x.size() != s.y.size())
            throw std::runtime_error("line plot: series '" + s.label +
                                     "' has different numbers of x and y values");
        if (s.label.empty()) continue;
        const auto style = s.line && s.markers ? TLegendEntry::LineDot
                           : s.line            ? TLegendEntry::Line
                                               : TLegendEntry::Dot;
        legend.push_back({s.label, s.color ? *s.color : paletteColor(i), style});
    }
    TPlotAxes ax;
    ax.logX = p.logX, ax.logY = p.logY;
    std::tie(ax.x0, ax.x1) = range(p, true, p.xMin, p.xMax);
    std::tie(ax.y0, ax.y1) = range(p, false, p.yMin, p.yMax);
    ax.top = p.title.empty() ? 15 : 45;
    ax.bottom = p.height - (p.xLabel.empty() ? 40 : 62);
    ax.right = p.width - (legend.empty() ? 25 : legendWidth(legend) + 24);
    const TTicks yt = ticksFor(ax.y0, ax.y1, p.logY, ax.bottom - ax.top);
    int widest = 0;
    for (const auto& l : yt.labels) widest = std::max(widest, textWidth(l, kNormal));
    ax.left = widest + 22 + (p.yLabel.empty() ? 0 : kLarge.h + 10);
    if (ax.right - ax.left < 100 || ax.bottom - ax.top < 80)
        throw std::runtime_error("line plot: the image is too small");
    TTicks xt = p.logX ? sweptTicks(p, ax.x0, ax.x1) : TTicks{};
    if (xt.values.empty()) xt = ticksFor(ax.x0, ax.x1, p.logX, ax.right - ax.left);
    drawFrame(img, ax, xt, yt, p.xLabel, p.yLabel);
    for (size_t i = 0; i < p.series.size(); i++) {
        const auto& s = p.series[i];
        const TColor c = s.color ? *s.color : paletteColor(i);
        std::vector<std::pair<double, double>> pts;
        for (size_t k = 0; k < s.x.size(); k++) {
            const bool ok = usable(s.x[k], p.logX) && usable(s.y[k], p.logY);
            pts.emplace_back(ok ? s.x[k] : NAN, ok ? s.y[k] : NAN);
        }
        if (s.line) polyline(img, ax, pts, c, 2);
        if (!s.markers) continue;
        for (const auto& [x, y] : pts) {
            if (!std::isfinite(x + y)) continue;
            const double u = ax.px(x), v = ax.py(y);
            if (u >= ax.left && u <= ax.right && v >= ax.top && v <= ax.bottom)
                fillDisc(img, int(std::lround(u)), int(std::lround(v)), 4, c);
        }
    }
    img.rectangle(ax.left, ax.top, ax.right, ax.bottom, TColor(60, 60, 60), 1);
    drawLegend(img, ax.right + 14, ax.top, legend);
    if (!p.title.empty())
        text(img, (ax.left + ax.right) / 2, 12, p.title, TColor(0, 0, 0), kLarge,
             Align::Center);
    if (axesOut) *axesOut = ax;
    return img;
}

void plotLines(const std::string& pngPath, const TLinePlot& plot) {
    savePngAtomically(pngPath, renderLinePlot(plot));
}

TSeries errorVsTime(const std::string& label, const std::vector<TPoseError>& perPose,
                    bool mm) {
    TSeries s;
    s.label = label;
    s.markers = false;
    for (const auto& e : perPose) {
        s.x.push_back(e.t);
        s.y.push_back(mm ? 1e3 * e.dist : e.dist);
    }
    return s;
}

}  // namespace rfir::eval
