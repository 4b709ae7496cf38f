/* The path-and-map figure of the papers (thesis figs. 3.10, 3.11, 4.2, 4.3). */
#include "plot_internal.h"

#include <mrpt/math/CMatrixFixed.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace rfir::eval {
using namespace detail;
using rfir::common::TMapEntry;

namespace {
const TColor kGtPath(0, 90, 200), kEstPath(220, 30, 30), kOdomPath(130, 130, 130),
    kGtTag(128, 0, 160), kEstTag(0, 150, 0), kEllipse(0, 80, 60), kEmitter(240, 140, 0),
    kLink(150, 150, 150);

struct TBounds {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    void add(double x, double y, double r = 0) {
        x0 = std::min(x0, x - r), x1 = std::max(x1, x + r);
        y0 = std::min(y0, y - r), y1 = std::max(y1, y + r);
    }
    bool empty() const { return !(x1 >= x0); }
};

TBounds dataBounds(const TMapFigure& f) {
    TBounds b;
    auto addPath = [&](const rfir::common::TPath2D& p) {
        for (const auto& s : p) b.add(s.pose.x(), s.pose.y());
    };
    for (const auto* p : {&f.gtPath, &f.estPath, &f.odomPath})
        if (*p) addPath(**p);
    for (const auto& p : f.extraPaths) addPath(p.path);
    for (const auto& e : f.gtMap) b.add(e.x, e.y);
    for (const auto& e : f.estMap) b.add(e.x, e.y);
    if (b.empty()) b.add(0, 0, 1);
    return b;
}

std::string entryNoun(const rfir::common::TMapFile& m) {
    bool tag = false, lm = false;
    for (const auto& e : m) {
        tag |= e.kind == TMapEntry::Kind::Tag;
        lm |= e.kind == TMapEntry::Kind::Landmark;
    }
    return tag && lm ? "tags/landmarks" : lm ? "landmarks" : "tags";
}

std::vector<TLegendEntry> legendOf(const TMapFigure& f) {
    std::vector<TLegendEntry> l;
    if (f.gtPath) l.push_back({f.gtPathLabel, kGtPath, TLegendEntry::Line});
    if (f.estPath) l.push_back({f.estPathLabel, kEstPath, TLegendEntry::Line});
    if (f.odomPath) l.push_back({f.odomPathLabel, kOdomPath, TLegendEntry::DashedLine});
    for (const auto& p : f.extraPaths)
        l.push_back({p.label, p.color, TLegendEntry::Line});
    const auto notEmitter = [](const TMapEntry& e) {
        return e.kind != TMapEntry::Kind::Emitter;
    };
    const auto isEmitter = [](const TMapEntry& e) {
        return e.kind == TMapEntry::Kind::Emitter;
    };
    if (std::any_of(f.gtMap.begin(), f.gtMap.end(), notEmitter))
        l.push_back({"true " + entryNoun(f.gtMap), kGtTag, TLegendEntry::Dot});
    if (std::any_of(f.estMap.begin(), f.estMap.end(), notEmitter))
        l.push_back({"estimated " + entryNoun(f.estMap) +
                         (f.estMapLabel.empty() ? "" : " (" + f.estMapLabel + ")"),
                     kEstTag, TLegendEntry::Circle});
    if (f.showEllipses && std::any_of(f.estMap.begin(), f.estMap.end(),
                                      [](const TMapEntry& e) { return e.sx && e.sy; }))
        l.push_back({"2-sigma ellipse", kEllipse, TLegendEntry::Circle});
    if (std::any_of(f.gtMap.begin(), f.gtMap.end(), isEmitter) ||
        std::any_of(f.estMap.begin(), f.estMap.end(), isEmitter))
        l.push_back({"IR emitters", kEmitter, TLegendEntry::Square});
    if (f.showHeadings && (f.gtPath || f.estPath || !f.extraPaths.empty())) {
        l.push_back({"heading", TColor(0, 0, 0), TLegendEntry::Arrow});
        l.push_back({"start", TColor(0, 0, 0), TLegendEntry::StartMark});
        l.push_back({"end", TColor(0, 0, 0), TLegendEntry::EndMark});
    }
    return l;
}

/** Equal-aspect axes filling the plot area, centred on the data. */
TPlotAxes fitAxes(const TBounds& b, double margin, int left, int top, int right,
                  int bottom) {
    TPlotAxes ax;
    ax.left = left, ax.top = top, ax.right = right, ax.bottom = bottom;
    const double rx = std::max(b.x1 - b.x0 + 2 * margin, 0.05);
    const double ry = std::max(b.y1 - b.y0 + 2 * margin, 0.05);
    const double s = std::min((right - left) / rx, (bottom - top) / ry);  // px per metre
    const double cx = 0.5 * (b.x0 + b.x1), cy = 0.5 * (b.y0 + b.y1);
    const double hw = 0.5 * (right - left) / s, hh = 0.5 * (bottom - top) / s;
    ax.x0 = cx - hw, ax.x1 = cx + hw, ax.y0 = cy - hh, ax.y1 = cy + hh;
    return ax;
}

std::vector<std::pair<double, double>> xy(const rfir::common::TPath2D& p) {
    std::vector<std::pair<double, double>> v;
    v.reserve(p.size());
    for (const auto& s : p) v.emplace_back(s.pose.x(), s.pose.y());
    return v;
}

bool inside(const TPlotAxes& ax, double x, double y) {
    return x >= ax.left && x <= ax.right && y >= ax.top && y <= ax.bottom;
}

/** Marker radius [px]: 6 px, less where the true tags are denser than about
 * one per 20 px (a big floor), at least 2 px. */
int markerRadius(const TPlotAxes& ax, const TMapFigure& f, const TBounds& b) {
    const double s = (ax.right - ax.left) / (ax.x1 - ax.x0);
    const size_t n = std::max(f.gtMap.size(), f.estMap.size());
    if (n < 2) return 6;
    const double area = std::max((b.x1 - b.x0) * (b.y1 - b.y0), 1e-6);
    const double spacingPx = s * std::sqrt(area / double(n));
    return std::clamp(int(std::lround(0.3 * spacingPx)), 2, 6);
}

/** Returns whether some ellipse was large enough to show outside its circle. */
bool drawEstimated(CImage& img, const TPlotAxes& ax, const TMapFigure& f, int r) {
    bool ellipses = false;
    const double s = (ax.right - ax.left) / (ax.x1 - ax.x0);
    std::map<std::pair<int, std::string>, const TMapEntry*> truth;
    for (const auto& g : f.gtMap) truth[{int(g.kind), g.id}] = &g;
    for (const auto& e : f.estMap) {
        const double x = ax.px(e.x), y = ax.py(e.y);
        if (!inside(ax, x, y) || e.kind == TMapEntry::Kind::Emitter) continue;
        if (f.showErrorLinks)
            if (auto it = truth.find({int(e.kind), e.id}); it != truth.end())
                img.line(int(x), int(y), int(ax.px(it->second->x)),
                         int(ax.py(it->second->y)), kLink, 1);
        img.drawCircle(int(std::lround(x)), int(std::lround(y)), r, kEstTag,
                       r > 3 ? 2 : 1);
        if (f.showIds) text(img, int(x) + r + 2, int(y) - 14, e.id, kEstTag, kSmall);
        // On top of the circle: a filter's 2 sigma is often smaller than it.
        if (f.showEllipses && e.sx && e.sy && 2 * std::max(*e.sx, *e.sy) * s >= 1) {
            ellipses = true;
            mrpt::math::CMatrixFixed<double, 2, 2> cov;
            cov(0, 0) = std::pow(std::max(*e.sx * s, 0.5), 2);
            cov(1, 1) = std::pow(std::max(*e.sy * s, 0.5), 2);
            cov(0, 1) = cov(1, 0) = 0;
            img.ellipseGaussian(cov, x, y, 2, kEllipse, 1, 36);
        }
    }
    return ellipses;
}

void drawTruth(CImage& img, const TPlotAxes& ax, const TMapFigure& f, int r) {
    for (const auto& e : f.gtMap) {
        const int x = int(std::lround(ax.px(e.x))), y = int(std::lround(ax.py(e.y)));
        if (!inside(ax, x, y)) continue;
        if (e.kind == TMapEntry::Kind::Emitter) {
            img.filledRectangle(x - 5, y - 5, x + 5, y + 5, kEmitter);
            if (f.showIds) text(img, x + 7, y - 14, e.id, TColor(150, 80, 0), kSmall);
        } else
            // Dense floors: a paler dot, so the paths read over the carpet.
            fillDisc(img, x, y, std::max(1, r / 2),
                     r > 3 ? kGtTag : TColor(200, 160, 220));
    }
}
/** Every path, then headings and start / end markers (truth in black). */
void drawPaths(CImage& img, const TPlotAxes& ax, const TMapFigure& f) {
    // The truth underneath, wider: estimates close to it stay visible.
    if (f.gtPath) polyline(img, ax, xy(*f.gtPath), kGtPath, 3);
    if (f.odomPath) polyline(img, ax, xy(*f.odomPath), kOdomPath, 2, true);
    for (const auto& p : f.extraPaths) polyline(img, ax, xy(p.path), p.color, p.width);
    if (f.estPath) polyline(img, ax, xy(*f.estPath), kEstPath, 2);
    if (!f.showHeadings) return;
    const TColor ink(0, 0, 0);
    // Headings on the truth and the estimate only: on every path of a
    // comparison they would bury the paths.
    if (f.estPath) drawHeadings(img, ax, *f.estPath, kEstPath, 150);
    if (f.gtPath) drawHeadings(img, ax, *f.gtPath, kGtPath, 150);
    if (f.estPath) drawStartEnd(img, ax, *f.estPath, kEstPath);
    for (const auto& p : f.extraPaths) drawStartEnd(img, ax, p.path, p.color);
    if (f.gtPath) drawStartEnd(img, ax, *f.gtPath, ink);
}
}  // namespace

mrpt::img::CImage renderMapFigure(const TMapFigure& f, TPlotAxes* axesOut) {
    const auto legend = legendOf(f);
    const int legendW = legend.empty() ? 0 : legendWidth(legend) + 24;
    const int legendH = int(legend.size()) * 20 + 12;
    int w = f.width, h = f.height;
    const int top = f.title.empty() ? 15 : 45, left = 95, marginB = 62;
    const int marginR = legend.empty() ? 20 : legendW;
    if (w - marginR - left < 100 || h - marginB - top < 100)
        throw std::runtime_error("map figure: the image is too small for its legend");
    const TBounds b = dataBounds(f);
    if (f.fitToData) {
        // Equal aspect: give back the unused width or height of the image.
        const double rx = std::max(b.x1 - b.x0 + 2 * f.marginMetres, 0.05);
        const double ry = std::max(b.y1 - b.y0 + 2 * f.marginMetres, 0.05);
        const int pw = w - marginR - left, ph = h - marginB - top;
        const double s = std::min(pw / rx, ph / ry);
        w -= std::max(0, pw - int(std::ceil(rx * s)) - 1);
        h -= std::max(0, ph - std::max(int(std::ceil(ry * s)) + 1, legendH));
    }
    CImage img = blankCanvas(w, h);
    const int right = w - marginR, bottom = h - marginB;
    const TPlotAxes ax = fitAxes(b, f.marginMetres, left, top, right, bottom);
    const double s = (right - left) / (ax.x1 - ax.x0);
    const double step = niceStep(60 / s);  // ticks at least 60 px apart
    drawFrame(img, ax, linearTicks(ax.x0, ax.x1, step), linearTicks(ax.y0, ax.y1, step),
              "x [m]", "y [m]");
    const int r = markerRadius(ax, f, b);
    drawTruth(img, ax, f, r);
    // Tags first, paths on top: on a big floor the markers would bury them.
    const bool ellipses = drawEstimated(img, ax, f, r);
    drawPaths(img, ax, f);
    auto shown = legend;
    if (!ellipses)  // ellipses hidden under their circles
        shown.erase(
            std::remove_if(shown.begin(), shown.end(),
                           [](const TLegendEntry& e) { return e.color == kEllipse; }),
            shown.end());
    img.rectangle(ax.left, ax.top, ax.right, ax.bottom, TColor(60, 60, 60), 1);
    drawLegend(img, right + 14, top, shown);
    if (!f.title.empty())
        text(img, (left + right) / 2, 12, f.title, TColor(0, 0, 0), kLarge,
             Align::Center);
    if (axesOut) *axesOut = ax;
    return img;
}

void plotMapFigure(const std::string& pngPath, const TMapFigure& fig) {
    savePngAtomically(pngPath, renderMapFigure(fig));
}

}  // namespace rfir::eval
