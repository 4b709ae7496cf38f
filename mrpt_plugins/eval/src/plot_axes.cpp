#include "plot_internal.h"

#include <rfir/common/atomic_file.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace rfir::eval {
namespace {
double axisValue(double v, bool log) {
    return log ? std::log10(v) : v;
}
}  // namespace

double TPlotAxes::px(double x) const {
    const double a = axisValue(x0, logX), b = axisValue(x1, logX);
    return left + (axisValue(x, logX) - a) / (b - a) * (right - left);
}

double TPlotAxes::py(double y) const {
    const double a = axisValue(y0, logY), b = axisValue(y1, logY);
    return bottom - (axisValue(y, logY) - a) / (b - a) * (bottom - top);
}

mrpt::img::TColor paletteColor(size_t i) {
    // Distinguishable on white, and in grey print (alternating lightness).
    static const mrpt::img::TColor pal[] = {
        {31, 119, 180}, {214, 39, 40}, {44, 160, 44},   {255, 127, 14}, {148, 103, 189},
        {23, 190, 207}, {140, 86, 75}, {227, 119, 194}, {90, 90, 90}};
    return pal[i % (sizeof(pal) / sizeof(pal[0]))];
}

void savePngAtomically(const std::string& pngPath, const mrpt::img::CImage& img) {
    // OpenCV picks the encoder from the extension, so the temporary file the
    // atomic writer names is first written with a ".png" suffix.
    rfir::common::writeViaTempFile(pngPath, [&](const std::string& tmp) {
        const std::string tmpPng = tmp + ".png";
        bool ok = false;
        try {
            ok = img.saveToFile(tmpPng);
        } catch (const std::exception& e) {
            std::remove(tmpPng.c_str());
            throw std::runtime_error("cannot write PNG '" + pngPath + "': " + e.what());
        }
        if (!ok || std::rename(tmpPng.c_str(), tmp.c_str()) != 0) {
            std::remove(tmpPng.c_str());
            throw std::runtime_error("cannot write PNG '" + pngPath + "'");
        }
    });
}

namespace detail {
CImage blankCanvas(int w, int h) {
    if (w < 200 || h < 150 || w > 20000 || h > 20000)
        throw std::runtime_error("figure size " + std::to_string(w) + "x" +
                                 std::to_string(h) +
                                 " px is out of range (200x150 and up)");
    CImage img(w, h, mrpt::img::CH_RGB);
    img.filledRectangle(0, 0, w - 1, h - 1, TColor(255, 255, 255));
    return img;
}

int textWidth(const std::string& s, const TFont& f) {
    return int(s.size()) * f.w;
}

void text(CImage& img, int x, int y, const std::string& s, TColor c, const TFont& f,
          Align a) {
    const int w = textWidth(s, f);
    if (a == Align::Center)
        x -= w / 2;
    else if (a == Align::Right)
        x -= w;
    img.selectTextFont(f.name);
    img.textOut(x, y, s, c);
}

void textVertical(CImage& img, int cx, int cy, const std::string& s, TColor c,
                  const TFont& f) {
    // Bitmap fonts draw horizontally only: draw on a scratch image, rotate.
    const int w = textWidth(s, f) + 2, h = f.h + 2;
    CImage tmp(w, h, mrpt::img::CH_GRAY);
    tmp.filledRectangle(0, 0, w - 1, h - 1, TColor(255, 255, 255));
    tmp.selectTextFont(f.name);
    tmp.textOut(1, 1, s, TColor(0, 0, 0));
    const int x0 = cx - h / 2, y0 = cy + w / 2;
    const size_t rgb = (size_t(c.R) << 16) | (size_t(c.G) << 8) | c.B;
    for (int v = 0; v < h; v++)
        for (int u = 0; u < w; u++)
            if (tmp.at<uint8_t>(u, v) < 128) img.setPixel(x0 + v, y0 - u, rgb);
}

void fillDisc(CImage& img, int cx, int cy, int r, TColor c) {
    for (int dy = -r; dy <= r; dy++) {
        const int dx = int(std::floor(std::sqrt(double(r * r - dy * dy)) + 0.35));
        img.filledRectangle(cx - dx, cy + dy, cx + dx, cy + dy, c);
    }
}

namespace {
/** Liang-Barsky clipping of a segment to a rectangle; false if outside. */
bool clip(double& x0, double& y0, double& x1, double& y1, double l, double t, double r,
          double b) {
    double u0 = 0, u1 = 1;
    const double dx = x1 - x0, dy = y1 - y0;
    const double p[4] = {-dx, dx, -dy, dy}, q[4] = {x0 - l, r - x0, y0 - t, b - y0};
    for (int i = 0; i < 4; i++) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        const double u = q[i] / p[i];
        if (p[i] < 0)
            u0 = std::max(u0, u);
        else
            u1 = std::min(u1, u);
        if (u0 > u1) return false;
    }
    const double ax = x0 + u0 * dx, ay = y0 + u0 * dy;
    x1 = x0 + u1 * dx, y1 = y0 + u1 * dy, x0 = ax, y0 = ay;
    return true;
}
}  // namespace

void polyline(CImage& img, const TPlotAxes& ax,
              const std::vector<std::pair<double, double>>& pts, TColor c, unsigned width,
              bool dashed) {
    const double dash = 8, gap = 6;
    double along = 0;  // dash phase carried across segments
    for (size_t i = 1; i < pts.size(); i++) {
        const auto& [xa, ya] = pts[i - 1];
        const auto& [xb, yb] = pts[i];
        if (!std::isfinite(xa + ya + xb + yb)) continue;
        double x0 = ax.px(xa), y0 = ax.py(ya), x1 = ax.px(xb), y1 = ax.py(yb);
        if (!std::isfinite(x0 + y0 + x1 + y1)) continue;
        if (!clip(x0, y0, x1, y1, ax.left, ax.top, ax.right, ax.bottom)) continue;
        const double len = std::hypot(x1 - x0, y1 - y0);
        if (!dashed) {
            img.line(int(std::lround(x0)), int(std::lround(y0)), int(std::lround(x1)),
                     int(std::lround(y1)), c, width);
            continue;
        }
        for (double s = 0; s < len;) {
            const double ph = std::fmod(along + s, dash + gap);
            const double run = ph < dash ? dash - ph : dash + gap - ph;
            const double e = std::min(len, s + run);
            if (ph < dash)
                img.line(int(std::lround(x0 + (x1 - x0) * s / len)),
                         int(std::lround(y0 + (y1 - y0) * s / len)),
                         int(std::lround(x0 + (x1 - x0) * e / len)),
                         int(std::lround(y0 + (y1 - y0) * e / len)), c, width);
            s = e;
        }
        along += len;
    }
}

}  // namespace detail
}  // namespace rfir::eval
