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

mrpt::img::CImage mapPanels(const TRowResults& r) {
    const auto& d = *r.firstData;
    const auto odo = odometryPath(d);
    std::vector<mrpt::img::CImage> panels;
    for (const auto& run : r.firstRuns) {
        const auto* spec = &r.row.methods[panels.size()];
        for (const auto& m : r.row.methods)
            if (m.label == run.method) spec = &m;
        if (isReference(*spec)) continue;
        rfir::eval::TMapFigure f;
        f.title =
            run.method + " (" + r.row.id + ", seed " + std::to_string(run.seed) + ")";
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

TLinePlot kidnapPlot(const TRowResults& r) {
    TLinePlot p;
    p.title = "kidnapping: robot error over time (seed " +
              std::to_string(r.firstRuns.empty() ? 0 : r.firstRuns.front().seed) + ")";
    p.xLabel = "time [s]";
    p.yLabel = "robot distance error [mm]";
    p.logY = true;
    for (const auto& run : r.firstRuns) {
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

std::vector<std::string> figureNames(const TRowResults& r) {
    std::vector<std::string> v;
    const std::string b = "img/exp_" + r.row.id;
    if (r.row.figure && r.firstData) v.push_back(b + ".png");
    if (r.row.kind == TRowKind::Sweep) {
        v.push_back(b + "_robot.png");
        v.push_back(b + "_tags.png");
        if (r.row.plotTime) v.push_back(b + "_time.png");
    }
    if (r.row.kind == TRowKind::Kidnap && !r.firstRuns.empty())
        v.push_back(b + "_error.png");
    return v;
}

std::vector<std::string> writeFigures(const std::string& outDir, const TRowResults& r) {
    const auto names = figureNames(r);
    const std::string b = outDir + "/img/exp_" + r.row.id;
    if (r.row.figure && r.firstData)
        rfir::eval::savePngAtomically(b + ".png", mapPanels(r));
    if (r.row.kind == TRowKind::Sweep) {
        rfir::eval::plotLines(b + "_robot.png", sweepPlot(r, "robot error [mm]",
                                                          robotMeanDist, 1e3, false));
        rfir::eval::plotLines(b + "_tags.png",
                              sweepPlot(r, "tag error [mm]", tagMeanDist, 1e3, false));
        if (r.row.plotTime)
            rfir::eval::plotLines(
                b + "_time.png",
                sweepPlot(
                    r, "time per update [ms]",
                    [](const TRunResult& x) { return x.msPerStep; }, 1.0, true));
    }
    if (r.row.kind == TRowKind::Kidnap && !r.firstRuns.empty())
        rfir::eval::plotLines(b + "_error.png", kidnapPlot(r));
    return names;
}

}  // namespace rfir::experiments
