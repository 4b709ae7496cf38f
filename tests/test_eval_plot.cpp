// PNG figures: size, colours where the paths and tags are, atomic output.
#include <rfir/eval/plot.h>

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

using namespace rfir::eval;
using mrpt::poses::CPose2D;
using rfir::common::TMapEntry;
using rfir::common::TPath2D;
namespace fs = std::filesystem;

namespace {
struct TRGB {
    int r, g, b;
};
/** Pixel of a loaded colour image (CImage stores BGR). */
TRGB pixel(const mrpt::img::CImage& im, int x, int y) {
    return {im.at<uint8_t>(x, y, 2), im.at<uint8_t>(x, y, 1), im.at<uint8_t>(x, y, 0)};
}
/** True if some pixel within `r` of (x, y) satisfies pred. */
template <class P>
bool near(const mrpt::img::CImage& im, double x, double y, int r, P pred) {
    for (int dy = -r; dy <= r; dy++)
        for (int dx = -r; dx <= r; dx++)
            if (pred(pixel(im, int(std::lround(x)) + dx, int(std::lround(y)) + dy)))
                return true;
    return false;
}
bool isRed(TRGB c) {
    return c.r > 180 && c.g < 90 && c.b < 90;
}
bool isBlue(TRGB c) {
    return c.b > 150 && c.r < 60 && c.g < 140;
}
bool isPurple(TRGB c) {
    return c.r > 100 && c.b > 130 && c.g < 40;
}
bool isGreen(TRGB c) {
    return c.g > 120 && c.r < 60 && c.b < 60;
}
bool isWhite(TRGB c) {
    return c.r == 255 && c.g == 255 && c.b == 255;
}

fs::path tempDir() {
    const auto d =
        fs::temp_directory_path() / ("rfir_eval_plot_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

TMapEntry entry(const std::string& id, double x, double y) {
    TMapEntry e;
    e.id = id;
    e.x = x;
    e.y = y;
    return e;
}
}  // namespace

TEST(EvalPlot, MapFigurePixelsAndFile) {
    TMapFigure f;
    f.title = "test figure";
    f.width = 800;
    f.height = 600;
    f.fitToData = false;  // exact size
    f.gtPath = TPath2D{{0, CPose2D(0, 0, 0)}, {1, CPose2D(2, 0, 0)}};
    f.estPath = TPath2D{{0, CPose2D(0, 1, 0)}, {1, CPose2D(2, 1, 0)}};
    f.gtMap = {entry("a", 1.03, 0.53)};  // off the grid lines
    auto est = entry("a", 1.53, 0.53);
    est.sx = 0.05, est.sy = 0.02;
    f.estMap = {est};
    TPlotAxes ax;
    const auto img = renderMapFigure(f, &ax);
    EXPECT_EQ(img.getWidth(), 800u);
    EXPECT_EQ(img.getHeight(), 600u);
    // Equal aspect: one metre spans as many pixels in x as in y.
    EXPECT_NEAR(ax.px(1) - ax.px(0), ax.py(0) - ax.py(1), 1e-6);

    const auto dir = tempDir();
    const std::string png = (dir / "fig.png").string();
    plotMapFigure(png, f);
    mrpt::img::CImage back;
    ASSERT_TRUE(back.loadFromFile(png));
    ASSERT_EQ(back.getWidth(), 800u);
    ASSERT_EQ(back.getHeight(), 600u);
    ASSERT_TRUE(back.isColor());
    EXPECT_TRUE(near(back, ax.px(1), ax.py(0), 1, isBlue));          // ground-truth path
    EXPECT_TRUE(near(back, ax.px(1), ax.py(1), 1, isRed));           // estimated path
    EXPECT_TRUE(near(back, ax.px(1.03), ax.py(0.53), 1, isPurple));  // true tag
    // Estimated tag: a green ring of radius 6 px, white inside.
    EXPECT_TRUE(near(back, ax.px(1.53) + 6, ax.py(0.53), 1, isGreen));
    EXPECT_TRUE(isWhite(
        pixel(back, int(std::lround(ax.px(1.53))), int(std::lround(ax.py(0.53))))));
    // Background away from the data and the grid stays white.
    EXPECT_TRUE(isWhite(pixel(back, int(ax.px(0.73)), int(ax.py(0.27)))));
    // No temporary file is left beside the output.
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 1u);
    fs::remove_all(dir);
}

TEST(EvalPlot, MapFigureFitsDataAspect) {
    TMapFigure f;
    f.width = 1000;
    f.height = 900;
    f.gtPath = TPath2D{{0, CPose2D(0, 0, 0)}, {1, CPose2D(4, 1, 0)}};
    const auto img = renderMapFigure(f);
    EXPECT_EQ(img.getWidth(), 1000u);
    EXPECT_LT(img.getHeight(), 500u);  // wide data: the figure gets shorter
}

TEST(EvalPlot, LinePlotLogAxesAndMarkers) {
    TLinePlot p;
    p.title = "time per update";
    p.xLabel = "robot particles";
    p.yLabel = "time [ms]";
    p.logX = p.logY = true;
    p.series.push_back({"PF-SLAM", {100, 1000, 5000}, {0.5, 5, 25}, {}, true, true});
    p.series.push_back({"FastSLAM",
                        {100, 1000, 5000},
                        {2, 20, 100},
                        mrpt::img::TColor(220, 30, 30),
                        true,
                        true});
    TPlotAxes ax;
    const auto img = renderLinePlot(p, &ax);
    EXPECT_EQ(img.getWidth(), 900u);
    EXPECT_EQ(img.getHeight(), 600u);
    // Log axes: each decade spans the same pixels.
    EXPECT_NEAR(ax.px(1000) - ax.px(100), ax.px(10000) - ax.px(1000), 1e-6);
    EXPECT_TRUE(near(img, ax.px(1000), ax.py(20), 1, isRed));
    EXPECT_TRUE(near(img, ax.px(1000), ax.py(5), 1, [](TRGB c) {
        return c.b > 150 && c.r < 60;  // palette blue
    }));

    const auto dir = tempDir();
    EXPECT_THROW(plotLines((dir / "missing" / "x.png").string(), p), std::runtime_error);
    const std::string png = (dir / "lines.png").string();
    plotLines(png, p);
    mrpt::img::CImage back;
    ASSERT_TRUE(back.loadFromFile(png));
    EXPECT_EQ(back.getWidth(), 900u);
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 1u);
    fs::remove_all(dir);
}

TEST(EvalPlot, LinePlotRejectsMismatchedSeries) {
    TLinePlot p;
    p.series.push_back({"bad", {1, 2}, {1}, {}, true, true});
    EXPECT_THROW(renderLinePlot(p), std::runtime_error);
}

namespace {
/** A tick mark below the plot area at column x (dark frame grey). */
bool tickAt(const mrpt::img::CImage& im, const TPlotAxes& ax, double x) {
    const TRGB c = pixel(im, int(std::lround(ax.px(x))), ax.bottom + 3);
    return c.r < 100 && c.g < 100 && c.b < 100;
}
}  // namespace

TEST(EvalPlot, LogSweepTickedAtItsValues) {
    // The quick particle sweep: M = 100 and 300 on a log axis. Decade / 1-2-5
    // ticks would give 100 and 200 and leave 300 unlabelled.
    TLinePlot p;
    p.logX = true;
    p.series.push_back({"PF-SLAM", {100, 300}, {1, 2}, {}, true, true});
    TPlotAxes ax;
    const auto img = renderLinePlot(p, &ax);
    EXPECT_TRUE(tickAt(img, ax, 100));
    EXPECT_TRUE(tickAt(img, ax, 300));
    EXPECT_FALSE(tickAt(img, ax, 200));
    // A dense sweep keeps the decade ticks.
    p.series[0].x = {100, 110, 120, 1000};
    p.series[0].y = {1, 2, 3, 4};
    const auto img2 = renderLinePlot(p, &ax);
    EXPECT_TRUE(tickAt(img2, ax, 200));
    EXPECT_TRUE(tickAt(img2, ax, 500));
}

TEST(EvalPlot, MapFigureMarksStartEndAndUncertainty) {
    TMapFigure f;
    f.gtPath =
        TPath2D{{0, CPose2D(0, 0, 0)}, {1, CPose2D(2, 0, 0)}, {2, CPose2D(2, 1, 1.57)}};
    f.estPath = TPath2D{{0, CPose2D(0, 0.2, 0)}, {2, CPose2D(2, 1.2, 1.57)}};
    auto e = entry("t", 1, 0.5);
    e.sx = 0.05, e.sy = 0.02;  // 2 sigma: 100 x 40 mm, well beyond the marker
    f.estMap = {e};
    TPlotAxes ax;
    const auto img = renderMapFigure(f, &ax);
    auto black = [](TRGB c) { return c.r < 40 && c.g < 40 && c.b < 40; };
    // The truth's start square is hollow: black 5 px from its centre.
    EXPECT_TRUE(near(img, ax.px(0) + 5, ax.py(0), 0, black));
    EXPECT_TRUE(near(img, ax.px(2), ax.py(1), 1, black));  // end cross, centre
    // The 2-sigma ellipse (dark green) crosses the x axis through the tag at
    // 2 sx = 0.1 m, outside the 6 px circle.
    const double s = ax.px(1) - ax.px(0);
    ASSERT_GT(0.1 * s, 10);
    auto ellipse = [](TRGB c) { return c.r < 30 && c.g > 60 && c.g < 110 && c.b > 40; };
    EXPECT_TRUE(near(img, ax.px(1.1), ax.py(0.5), 1, ellipse));
    EXPECT_FALSE(near(img, ax.px(1.2), ax.py(0.5), 1, ellipse));
    // Without headings: no start / end markers.
    f.showHeadings = false;
    const auto img2 = renderMapFigure(f, &ax);
    EXPECT_FALSE(near(img2, ax.px(0) + 5, ax.py(0), 0, black));
}
