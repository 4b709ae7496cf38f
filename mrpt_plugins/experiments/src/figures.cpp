/* rfir-experiments: PNG figures: path/map panels of the first seed (one per
 * method, side by side, as the thesis' figs. 3.10, 4.2), sweep line plots
 * (thesis figs. 3.6, 4.4) and the kidnapping error over time (fig. 3.12). */
#include <rfir/experiments/report.h>

#include <rfir/eval/metrics.h>
#include <rfir/eval/plot.h>

#include <mrpt/img/CImage.h>

namespace rfir::experiments {
namespace {
using rfir::eval::TLinePlot;
using rfir::eval::TSeries;

bool isReference(const TMethodSpec& m) {
    return m.method == "odometry";
}

rfir::common::TPath2D odometryPath(const TDataSet& d) {
    rfir::common::TPath2D odo;
    for (const auto& s : d.sim.steps)
        if (s.odometry) odo.push_back({s.t, *s.odometry});
    return rfir::eval::alignOdometryAtStart(odo, d.sim.groundTruth);
}

mrpt::img::CImage mapPanels(const TRow& row, const TDataSet& d,
                            const std::vector<TRunResult>& runs) {
    const auto odo = odometryPath(d);
    std::vector<mrpt::img::CImage> panels;
    for (const auto& run : runs) {
        const auto* spec = &row.methods[panels.size()];
        for (const auto& m : row.methods)
            if (m.label == run.method) spec = &m;
        if (isReference(*spec)) continue;
        rfir::eval::TMapFigure f;
        f.title = run.method + " (" + row.id + ", seed " + std::to_string(run.seed) + ")";
        f.gtPath = d.sim.groundTruth;
        f.estPath = run.estPath;
        f.odomPath = odo;
        f.gtMap = d.sim.gtMap;
        f.estMap = run.estMap;
        f.showEllipses = false;
        f.width = 640;
        f.height = 600;
        panels.push_back(rfir::eval::renderMapFigure(f));
    }
    int w = 0, h = 0;
    for (const auto& p : panels)
        w += int(p.getWidth()), h = std::max(h, int(p.getHeight()));
    mrpt::img::CImage all(std::max(w, 1), std::max(h, 1), mrpt::img::CH_RGB);
    all.filledRectangle(0, 0, all.getWidth() - 1, all.getHeight() - 1,
                        mrpt::img::TColor(255, 255, 255));
    int x = 0;
    for (const auto& p : panels) all.drawImage(x, 0, p), x += int(p.getWidth());
    return all;
}

TLinePlot sweepPlot(const TRowResults& r, const std::string& what, const TGetter& get,
                    double scale, bool logY) {
    TLinePlot p;
    p.title = r.row.source + ": " + what + " (mean over seeds)";
    p.xLabel = r.row.xLabel;
    p.yLabel = what;
    p.logX = r.row.logX;
    p.logY = logY;
    for (const auto& m : r.row.methods) {
        TSeries s;
        s.label = m.label;
        for (size_t i = 0; i < r.row.points.size(); i++) {
            s.x.push_back(r.row.points[i].x);
            s.y.push_back(scale * statOf(perSeed(r, i, m.label, get)).mean);
        }
        p.series.push_back(s);
    }
    return p;
}

TLinePlot kidnapPlot(const std::vector<TRunResult>& runs) {
    TLinePlot p;
    p.title = "kidnapping: robot error over time (seed " +
              std::to_string(runs.empty() ? 0 : runs.front().seed) + ")";
    p.xLabel = "time [s]";
    p.yLabel = "robot distance error [mm]";
    p.logY = true;
    for (const auto& run : runs) {
        TSeries s;
        s.label = run.method;
        s.markers = false;
        for (const auto& e : run.eval.robot->perPose)
            s.x.push_back(e.t), s.y.push_back(std::max(1e3 * e.dist, 0.1));
        p.series.push_back(s);
    }
    return p;
}
}  // namespace

std::vector<std::string> firstSeedFigureNames(const TRow& row) {
    std::vector<std::string> v;
    if (row.figure) v.push_back("exp_" + row.id + ".png");
    if (row.kind == TRowKind::Kidnap) v.push_back("exp_" + row.id + "_error.png");
    return v;
}

std::vector<std::string> sweepFigureNames(const TRow& row) {
    std::vector<std::string> v;
    if (row.kind != TRowKind::Sweep) return v;
    for (const char* s : {"_robot", "_tags", "_time"})
        if (row.plotTime || std::string(s) != "_time")
            v.push_back("exp_" + row.id + s + ".png");
    return v;
}

std::vector<std::string> figureNames(const TRow& row) {
    std::vector<std::string> v;
    for (const auto& names : {firstSeedFigureNames(row), sweepFigureNames(row)})
        for (const auto& n : names) v.push_back("img/" + n);
    return v;
}

void writeFirstSeedFigures(const TFigurePath& path, const TRow& row, const TDataSet& d,
                           const std::vector<TRunResult>& runs) {
    if (row.figure)
        rfir::eval::savePngAtomically(path("exp_" + row.id + ".png"),
                                      mapPanels(row, d, runs));
    if (row.kind == TRowKind::Kidnap)
        rfir::eval::plotLines(path("exp_" + row.id + "_error.png"), kidnapPlot(runs));
}

void writeSweepFigures(const TFigurePath& path, const TRowResults& r) {
    if (r.row.kind != TRowKind::Sweep) return;
    const std::string b = "exp_" + r.row.id;
    rfir::eval::plotLines(path(b + "_robot.png"),
                          sweepPlot(r, "robot error [mm]", robotMeanDist, 1e3, false));
    rfir::eval::plotLines(path(b + "_tags.png"),
                          sweepPlot(r, "tag error [mm]", tagMeanDist, 1e3, false));
    if (r.row.plotTime)
        rfir::eval::plotLines(
            path(b + "_time.png"),
            sweepPlot(
                r, "time per update [ms]",
                [](const TRunResult& x) { return x.msPerStep; }, 1.0, true));
}

}  // namespace rfir::experiments
