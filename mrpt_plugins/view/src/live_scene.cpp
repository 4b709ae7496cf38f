#include <rfir/view/live_scene.h>

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/opengl/CEllipsoid2D.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cmath>

namespace rfir::view {
namespace {
using mrpt::math::TPoint2D;

void setColour(mrpt::opengl::CRenderizable& o, const mrpt::img::TColor& c) {
    o.setColor_u8(c.R, c.G, c.B);
}

/** A polyline at height z (closed: back to the first point). */
void addPolyline(mrpt::opengl::CSetOfLines& lines, const std::vector<TPoint2D>& pts,
                 double z, bool closed) {
    for (size_t i = 1; i < pts.size(); i++)
        lines.appendLine(pts[i - 1].x, pts[i - 1].y, z, pts[i].x, pts[i].y, z);
    if (closed && pts.size() > 2)
        lines.appendLine(pts.back().x, pts.back().y, z, pts[0].x, pts[0].y, z);
}

mrpt::opengl::CSetOfLines::Ptr lines(const mrpt::img::TColor& c, float width) {
    auto l = mrpt::opengl::CSetOfLines::Create();
    setColour(*l, c);
    l->setLineWidth(width);
    return l;
}

/** The floor grid over what the frame shows, 1 m cells. */
void addGrid(const TFrame& f, mrpt::opengl::COpenGLScene& scene) {
    auto b = mrpt::math::TBoundingBox::PlusMinusInfinity();
    growBox(b, f.truth), growBox(b, f.path), growBox(b, f.landmarks);
    if (b.min.x > b.max.x) b.min = {-1, -1, 0}, b.max = {1, 1, 0};
    const double x0 = b.min.x, y0 = b.min.y, x1 = b.max.x, y1 = b.max.y;
    auto grid =
        mrpt::opengl::CGridPlaneXY::Create(std::floor(x0) - 1, std::ceil(x1) + 1,
                                           std::floor(y0) - 1, std::ceil(y1) + 1, 0, 1);
    grid->setColor_u8(200, 200, 200);
    scene.insert(grid);
}

void addLandmarks(const TFrame& f, mrpt::opengl::COpenGLScene& scene) {
    auto centres = mrpt::opengl::CPointCloud::Create();
    setColour(*centres, colours::landmark);
    centres->setPointSize(6);
    for (const auto& l : f.landmarks) {
        centres->insertPoint(l.x, l.y, l.z);
        if (l.sx <= 0 || l.sy <= 0) continue;
        // The 2-sigma ellipse, at least 1 cm across to stay visible.
        auto e = mrpt::opengl::CEllipsoid2D::Create();
        mrpt::math::CMatrixFixed<double, 2, 2> cov;
        cov(0, 0) = std::max(l.sx * l.sx, 1e-4);
        cov(1, 1) = std::max(l.sy * l.sy, 1e-4);
        cov(0, 1) = cov(1, 0) = 0;
        e->setCovMatrix(cov);
        e->setQuantiles(2);
        e->setLocation(l.x, l.y, l.z + 0.01);
        setColour(*e, colours::landmark);
        e->setLineWidth(2);
        scene.insert(e);
    }
    scene.insert(centres);
}
}  // namespace

std::vector<TPoint2D> footprint(const mrpt::math::TPose2D& robot, double x, double y,
                                double halfX, double halfY) {
    const mrpt::poses::CPose2D r(robot);
    std::vector<TPoint2D> out;
    for (const auto& [dx, dy] : {std::pair{-halfX, -halfY}, std::pair{halfX, -halfY},
                                 std::pair{halfX, halfY}, std::pair{-halfX, halfY}}) {
        double wx = 0, wy = 0;
        r.composePoint(x + dx, y + dy, wx, wy);
        out.push_back({wx, wy});
    }
    return out;
}

void drawFrame(const TFrame& f, mrpt::opengl::COpenGLScene& scene) {
    scene.clear();
    scene.getViewport()->setCustomBackgroundColor({1.f, 1.f, 1.f, 1.f});
    addGrid(f, scene);
    auto truth = lines(colours::truth, 2), path = lines(colours::path, 3);
    addPolyline(*truth, f.truth, 0.005, false);
    addPolyline(*path, f.path, 0.01, false);
    scene.insert(truth);
    scene.insert(path);
    addLandmarks(f, scene);
    auto readers = lines(colours::sensor, 2), reading = lines(colours::read, 4);
    for (const auto& r : f.readers) addPolyline(*readers, r, 0.02, true);
    for (const auto& r : f.readingReaders) addPolyline(*reading, r, 0.025, true);
    for (const auto& [a, b] : f.reads) reading->appendLine(a.x, a.y, a.z, b.x, b.y, b.z);
    scene.insert(readers);
    scene.insert(reading);
    auto receivers = mrpt::opengl::CPointCloud::Create();
    setColour(*receivers, colours::sensor);
    receivers->setPointSize(7);
    for (const auto& p : f.receivers) receivers->insertPoint(p.x, p.y, 0.02);
    scene.insert(receivers);
    auto particles = mrpt::opengl::CPointCloud::Create();
    setColour(*particles, colours::particles);
    particles->setPointSize(3);
    for (const auto& p : f.particles) particles->insertPoint(p.x, p.y, 0.03);
    scene.insert(particles);
    auto vp = scene.getViewport();
    vp->clearTextMessages();
    mrpt::opengl::TFontParams font;
    font.color = {0.f, 0.f, 0.f};
    font.vfont_scale = 14;
    for (size_t i = 0; i < f.text.size(); i++)
        vp->addTextMessage(8, 8 + 20.0 * double(f.text.size() - 1 - i), f.text[i], i,
                           font);
}

}  // namespace rfir::view
