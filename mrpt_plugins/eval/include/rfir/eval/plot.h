/* rfir: PNG figures drawn with mrpt::img::CImage: the path-and-map figure of
 * the papers (thesis figs. 3.10, 4.2; PS-SLAM paper figs. 5-10) and line plots
 * for parameter sweeps. Files are written atomically. */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>
#include <rfir/eval/metrics.h>

#include <mrpt/img/CImage.h>
#include <mrpt/img/TColor.h>

#include <optional>
#include <string>
#include <vector>

namespace rfir::eval {
/** Linear world <-> pixel mapping of a drawn plot area (y up in the world). */
struct TPlotAxes {
    int left = 0, top = 0, right = 0, bottom = 0;  //!< plot area, pixels
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;         //!< data range shown
    bool logX = false, logY = false;
    /** Pixel column / row of a data value (log10 applied on log axes). */
    double px(double x) const;
    double py(double y) const;
};

/** One extra path drawn in a map figure. */
struct TPlotPath {
    std::string label;
    rfir::common::TPath2D path;
    mrpt::img::TColor color{0, 0, 0};
    unsigned width = 2;
};

/** The path-and-map figure. Styles follow the papers: ground-truth path blue,
 * estimated path red, odometry grey; ground-truth tags/landmarks purple dots,
 * estimated ones green circles (with 2-sigma ellipses from sx, sy); emitters
 * orange squares. Entries of the maps of every kind are drawn. */
struct TMapFigure {
    std::string title;
    std::optional<rfir::common::TPath2D> gtPath, estPath, odomPath;
    rfir::common::TMapFile gtMap, estMap;
    std::vector<TPlotPath> extraPaths;
    std::string gtPathLabel = "ground truth", estPathLabel = "estimate",
                odomPathLabel = "odometry";
    /** Whose map estMap is, in the legend (figures with several paths). */
    std::string estMapLabel;
    bool showEllipses = true;  //!< 2-sigma ellipses of estimated entries
    bool showIds = false;      //!< write the IDs of estimated entries
    /** Heading arrows along the paths and start / end markers. */
    bool showHeadings = true;
    /** Link each estimated landmark to its true position (error vectors). */
    bool showErrorLinks = false;
    int width = 1000, height = 900;  //!< whole image, pixels (at most, see fitToData)
    /** Shrink the image's width or height to the data's aspect ratio (the
     * axes have equal scales), instead of widening the shown data range. */
    bool fitToData = true;
    /** Extra margin around the data, metres. */
    double marginMetres = 0.1;
};

/** One series of a line plot. NaN points break the line. */
struct TSeries {
    std::string label;
    std::vector<double> x, y;
    std::optional<mrpt::img::TColor> color;  //!< default: a fixed palette
    bool markers = true;
    bool line = true;
};

struct TLinePlot {
    std::string title, xLabel, yLabel;
    std::vector<TSeries> series;
    bool logX = false, logY = false;  //!< non-positive values are skipped
    /** Optional fixed ranges (default: auto from the data, padded). */
    std::optional<double> xMin, xMax, yMin, yMax;
    int width = 900, height = 600;
};

/** Renders the map figure; `axes` (if given) receives the world->pixel map. */
mrpt::img::CImage renderMapFigure(const TMapFigure& fig, TPlotAxes* axes = nullptr);
/** Renders and writes a PNG atomically; throws std::runtime_error on failure. */
void plotMapFigure(const std::string& pngPath, const TMapFigure& fig);

mrpt::img::CImage renderLinePlot(const TLinePlot& plot, TPlotAxes* axes = nullptr);
void plotLines(const std::string& pngPath, const TLinePlot& plot);

/** A robot-error-vs-time series (distance, metres; or mm with `mm`) for a
 * line plot, e.g. the kidnapping figure (thesis fig. 3.12(b)). */
TSeries errorVsTime(const std::string& label, const std::vector<TPoseError>& perPose,
                    bool mm = true);

/** Writes any CImage as PNG through a temporary file (writeViaTempFile). */
void savePngAtomically(const std::string& pngPath, const mrpt::img::CImage& img);

/** Default colour of series i in line plots. */
mrpt::img::TColor paletteColor(size_t i);

}  // namespace rfir::eval
