/* rfir: drawing helpers shared by the figures (not part of the public API). */
#pragma once

#include <rfir/eval/plot.h>

#include <string>
#include <utility>
#include <vector>

namespace rfir::eval::detail {
using mrpt::img::CImage;
using mrpt::img::TColor;

/** MRPT's bitmap fonts: name and cell size in pixels. */
struct TFont {
    const char* name;
    int w, h;
};
inline constexpr TFont kSmall{"6x13", 6, 13}, kNormal{"9x15", 9, 15},
    kLarge{"10x20", 10, 20};

enum class Align { Left, Center, Right };

/** Text whose cell's top edge is at y. */
void text(CImage& img, int x, int y, const std::string& s, TColor c, const TFont& f,
          Align a = Align::Left);
/** Text rotated 90 degrees (reads bottom to top), centred on (cx, cy). */
void textVertical(CImage& img, int cx, int cy, const std::string& s, TColor c,
                  const TFont& f);
int textWidth(const std::string& s, const TFont& f);

void fillDisc(CImage& img, int cx, int cy, int r, TColor c);

/** Polyline in data coordinates, clipped to the plot area. Points with a NaN
 * coordinate break the line. */
void polyline(CImage& img, const TPlotAxes& ax,
              const std::vector<std::pair<double, double>>& pts, TColor c, unsigned width,
              bool dashed = false);

/** Tick values and their labels. */
struct TTicks {
    std::vector<double> values;
    std::vector<std::string> labels;
};
/** Smallest of 1, 2, 5 x 10^k that is >= rough. */
double niceStep(double rough);
/** Multiples of `step` within [lo, hi], labelled with the decimals `step` needs. */
TTicks linearTicks(double lo, double hi, double step);
/** Decades (and 2, 5 multiples when few decades) within [lo, hi] (> 0). */
TTicks logTicks(double lo, double hi);

/** Grid, frame, tick marks and labels, axis labels. */
void drawFrame(CImage& img, const TPlotAxes& ax, const TTicks& xt, const TTicks& yt,
               const std::string& xLabel, const std::string& yLabel);

/** An arrow of `len` pixels from (x, y) along the world heading phi. */
void drawArrow(CImage& img, double x, double y, double phi, TColor c, int len);
/** Heading arrows along a path, one every `everyPx` pixels of its length. */
void drawHeadings(CImage& img, const TPlotAxes& ax, const rfir::common::TPath2D& p,
                  TColor c, double everyPx);
/** Start (hollow square) and end (cross) of a path. */
void drawStartEnd(CImage& img, const TPlotAxes& ax, const rfir::common::TPath2D& p,
                  TColor c);
void drawStartMark(CImage& img, int x, int y, TColor c);
void drawEndMark(CImage& img, int x, int y, TColor c);

struct TLegendEntry {
    enum Style {
        Line,
        DashedLine,
        LineDot,
        Dot,
        Circle,
        Square,
        StartMark,
        EndMark,
        Arrow
    };
    std::string label;
    TColor color;
    Style style = Line;
};
int legendWidth(const std::vector<TLegendEntry>& e);
/** Boxed legend with its top-left corner at (x, y). */
void drawLegend(CImage& img, int x, int y, const std::vector<TLegendEntry>& e);

/** A white RGB canvas. */
CImage blankCanvas(int w, int h);

}  // namespace rfir::eval::detail
