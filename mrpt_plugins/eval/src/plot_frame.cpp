/* Axes: ticks, grid, frame, labels; legends. */
#include "plot_internal.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rfir::eval::detail {
namespace {
const TColor kInk(0, 0, 0), kGrid(225, 225, 225), kFrame(60, 60, 60);

std::string fmtTick(double v, int decimals) {
    if (std::abs(v) < 1e-12) v = 0;  // no "-0.0"
    char b[64];
    std::snprintf(b, sizeof(b), "%.*f", decimals, v);
    return b;
}
}  // namespace

double niceStep(double rough) {
    if (!(rough > 0) || !std::isfinite(rough)) return 1;
    const double p = std::pow(10.0, std::floor(std::log10(rough)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= rough * (1 - 1e-9)) return m * p;
    return 10 * p;
}

TTicks linearTicks(double lo, double hi, double step) {
    TTicks t;
    const int dec = std::max(0, -int(std::floor(std::log10(step) + 1e-9)));
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k++) {
        t.values.push_back(k * step);
        t.labels.push_back(fmtTick(k * step, dec));
    }
    return t;
}

TTicks logTicks(double lo, double hi) {
    TTicks t;
    const int d0 = int(std::floor(std::log10(lo))), d1 = int(std::ceil(std::log10(hi)));
    const bool fine = d1 - d0 <= 3;  // few decades: label 1-2-5
    for (int d = d0; d <= d1; d++)
        for (double m : {1.0, 2.0, 5.0}) {
            if (m != 1.0 && !fine) continue;
            const double v = m * std::pow(10.0, d);
            if (v < lo * (1 - 1e-9) || v > hi * (1 + 1e-9)) continue;
            char b[32];
            std::snprintf(b, sizeof(b), "%g", v);
            t.values.push_back(v);
            t.labels.push_back(b);
        }
    return t;
}

void drawFrame(CImage& img, const TPlotAxes& ax, const TTicks& xt, const TTicks& yt,
               const std::string& xLabel, const std::string& yLabel) {
    for (double v : xt.values) {
        const int x = int(std::lround(ax.px(v)));
        img.line(x, ax.top, x, ax.bottom, kGrid, 1);
    }
    for (double v : yt.values) {
        const int y = int(std::lround(ax.py(v)));
        img.line(ax.left, y, ax.right, y, kGrid, 1);
    }
    img.rectangle(ax.left, ax.top, ax.right, ax.bottom, kFrame, 1);
    for (size_t i = 0; i < xt.values.size(); i++) {
        const int x = int(std::lround(ax.px(xt.values[i])));
        img.line(x, ax.bottom, x, ax.bottom + 5, kFrame, 1);
        text(img, x, ax.bottom + 8, xt.labels[i], kInk, kNormal, Align::Center);
    }
    int widest = 0;
    for (size_t i = 0; i < yt.values.size(); i++) {
        const int y = int(std::lround(ax.py(yt.values[i])));
        img.line(ax.left - 5, y, ax.left, y, kFrame, 1);
        text(img, ax.left - 8, y - kNormal.h / 2, yt.labels[i], kInk, kNormal,
             Align::Right);
        widest = std::max(widest, textWidth(yt.labels[i], kNormal));
    }
    if (!xLabel.empty())
        text(img, (ax.left + ax.right) / 2, ax.bottom + 12 + kNormal.h, xLabel, kInk,
             kLarge, Align::Center);
    if (!yLabel.empty())
        textVertical(img,
                     std::max(kLarge.h / 2 + 2, ax.left - widest - 14 - kLarge.h / 2),
                     (ax.top + ax.bottom) / 2, yLabel, kInk, kLarge);
}

namespace {
constexpr int kSwatch = 34, kPad = 8, kRow = 20;

void drawSwatch(CImage& img, int x, int y, const TLegendEntry& e) {
    const int cx = x + kSwatch / 2;
    switch (e.style) {
        case TLegendEntry::Line:
            img.line(x, y, x + kSwatch, y, e.color, 2);
            break;
        case TLegendEntry::LineDot:
            img.line(x, y, x + kSwatch, y, e.color, 2);
            fillDisc(img, cx, y, 3, e.color);
            break;
        case TLegendEntry::DashedLine:
            img.line(x, y, x + 12, y, e.color, 2);
            img.line(x + 20, y, x + kSwatch, y, e.color, 2);
            break;
        case TLegendEntry::Dot:
            fillDisc(img, cx, y, 3, e.color);
            break;
        case TLegendEntry::Circle:
            img.drawCircle(cx, y, 6, e.color, 2);
            break;
        case TLegendEntry::Square:
            img.filledRectangle(cx - 5, y - 5, cx + 5, y + 5, e.color);
            break;
        case TLegendEntry::StartMark:
            drawStartMark(img, cx, y, e.color);
            break;
        case TLegendEntry::EndMark:
            drawEndMark(img, cx, y, e.color);
            break;
        case TLegendEntry::Arrow:
            drawArrow(img, cx - 8, y, 0, e.color, 16);
            break;
    }
}
}  // namespace

int legendWidth(const std::vector<TLegendEntry>& e) {
    int w = 0;
    for (const auto& x : e) w = std::max(w, textWidth(x.label, kNormal));
    return w + kSwatch + 3 * kPad;
}

void drawLegend(CImage& img, int x, int y, const std::vector<TLegendEntry>& e) {
    if (e.empty()) return;
    const int w = legendWidth(e), h = int(e.size()) * kRow + 2 * kPad - 4;
    img.filledRectangle(x, y, x + w, y + h, TColor(255, 255, 255));
    img.rectangle(x, y, x + w, y + h, TColor(150, 150, 150), 1);
    for (size_t i = 0; i < e.size(); i++) {
        const int cy = y + kPad + int(i) * kRow + kRow / 2 - 2;
        drawSwatch(img, x + kPad, cy, e[i]);
        text(img, x + 2 * kPad + kSwatch, cy - kNormal.h / 2, e[i].label, kInk, kNormal);
    }
}

}  // namespace rfir::eval::detail
