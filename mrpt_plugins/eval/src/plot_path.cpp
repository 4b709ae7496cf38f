/* Path decorations of the map figure: headings, start and end markers. */
#include "plot_internal.h"

#include <cmath>

namespace rfir::eval::detail {
namespace {
bool insideArea(const TPlotAxes& ax, double x, double y) {
    return x >= ax.left && x <= ax.right && y >= ax.top && y <= ax.bottom;
}
}  // namespace

void drawArrow(CImage& img, double x, double y, double phi, TColor c, int len) {
    // Image rows grow downwards: the heading's y component flips.
    const double ux = std::cos(phi), uy = -std::sin(phi);
    const double tx = x + len * ux, ty = y + len * uy;
    img.line(int(std::lround(x)), int(std::lround(y)), int(std::lround(tx)),
             int(std::lround(ty)), c, 2);
    for (double side : {-1.0, 1.0}) {
        const double a = std::atan2(uy, ux) + M_PI + side * 0.5;
        img.line(int(std::lround(tx)), int(std::lround(ty)),
                 int(std::lround(tx + 0.5 * len * std::cos(a))),
                 int(std::lround(ty + 0.5 * len * std::sin(a))), c, 2);
    }
}

void drawHeadings(CImage& img, const TPlotAxes& ax, const rfir::common::TPath2D& p,
                  TColor c, double everyPx) {
    double along = 0;
    for (size_t i = 1; i < p.size(); i++) {
        const double x0 = ax.px(p[i - 1].pose.x()), y0 = ax.py(p[i - 1].pose.y());
        const double x1 = ax.px(p[i].pose.x()), y1 = ax.py(p[i].pose.y());
        along += std::hypot(x1 - x0, y1 - y0);
        if (along < everyPx) continue;
        along = 0;
        if (insideArea(ax, x1, y1)) drawArrow(img, x1, y1, p[i].pose.phi(), c, 10);
    }
}

void drawStartEnd(CImage& img, const TPlotAxes& ax, const rfir::common::TPath2D& p,
                  TColor c) {
    if (p.empty()) return;
    const double xs = ax.px(p.front().pose.x()), ys = ax.py(p.front().pose.y());
    const double xe = ax.px(p.back().pose.x()), ye = ax.py(p.back().pose.y());
    if (insideArea(ax, xs, ys))
        drawStartMark(img, int(std::lround(xs)), int(std::lround(ys)), c);
    if (insideArea(ax, xe, ye))
        drawEndMark(img, int(std::lround(xe)), int(std::lround(ye)), c);
}

void drawStartMark(CImage& img, int x, int y, TColor c) {
    // A hollow square, two pixels thick, 11 px wide.
    img.rectangle(x - 5, y - 5, x + 5, y + 5, c, 2);
}

void drawEndMark(CImage& img, int x, int y, TColor c) {
    // A cross (x), 11 px wide.
    img.line(x - 5, y - 5, x + 5, y + 5, c, 3);
    img.line(x - 5, y + 5, x + 5, y - 5, c, 3);
}

}  // namespace rfir::eval::detail
