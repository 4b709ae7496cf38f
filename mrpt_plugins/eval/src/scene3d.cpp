#include <rfir/common/atomic_file.h>
#include <rfir/eval/scene3d.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CEllipsoid2D.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rfir::eval {
using namespace mrpt::opengl;
using rfir::common::TMapEntry;

namespace {
CSetOfLines::Ptr pathLines(const rfir::common::TPath2D& p, const char* name,
                           mrpt::img::TColor c) {
    auto l = CSetOfLines::Create();
    l->setName(name);
    l->setColor_u8(c);
    l->setLineWidth(2);
    for (size_t i = 1; i < p.size(); i++)
        l->appendLine(p[i - 1].pose.x(), p[i - 1].pose.y(), 0.002, p[i].pose.x(),
                      p[i].pose.y(), 0.002);
    return l;
}

CPointCloud::Ptr points(const rfir::common::TMapFile& m, const char* name,
                        mrpt::img::TColor c, float size) {
    auto pc = CPointCloud::Create();
    pc->setName(name);
    pc->setColor_u8(c);
    pc->setPointSize(size);
    for (const auto& e : m)
        if (e.kind != TMapEntry::Kind::Emitter) pc->insertPoint(e.x, e.y, 0.001);
    return pc;
}

CSetOfObjects::Ptr ellipses(const rfir::common::TMapFile& m) {
    auto set = CSetOfObjects::Create();
    set->setName(scene_names::kEstTags);
    for (const auto& e : m) {
        if (e.kind == TMapEntry::Kind::Emitter || !e.sx || !e.sy) continue;
        auto el = CEllipsoid2D::Create();
        mrpt::math::CMatrixFixed<double, 2, 2> cov;
        cov(0, 0) = std::pow(std::max(*e.sx, 1e-6), 2);
        cov(1, 1) = std::pow(std::max(*e.sy, 1e-6), 2);
        cov(0, 1) = cov(1, 0) = 0;
        el->setCovMatrix(cov);
        el->setQuantiles(2);  // 2 sigma, as in the PNG
        el->setLocation(e.x, e.y, 0.003);
        el->setName(e.id);
        el->setColor_u8(mrpt::img::TColor(0, 150, 0));
        set->insert(el);
    }
    return set;
}

/** The readers' detection areas at the robot's last estimated pose. */
CSetOfObjects::Ptr readerBoxes(const std::vector<rfir::obs::TRFIDReader>& readers,
                               const mrpt::poses::CPose2D& at) {
    auto set = CSetOfObjects::Create();
    set->setName(scene_names::kReaders);
    set->setPose(mrpt::poses::CPose3D(at.x(), at.y(), 0, at.phi(), 0, 0));
    for (const auto& r : readers) {
        auto b = CBox::Create(mrpt::math::TPoint3D(r.x - r.halfX, r.y - r.halfY, 0),
                              mrpt::math::TPoint3D(r.x + r.halfX, r.y + r.halfY, 0.01));
        b->setName(r.id);
        b->setColor_u8(mrpt::img::TColor(240, 140, 0, 160));
        set->insert(b);
    }
    return set;
}
}  // namespace

namespace {
COpenGLScene::Ptr buildScene(const TMapFigure& f,
                             const std::vector<rfir::obs::TRFIDReader>& readers) {
    auto scene = COpenGLScene::Create();
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    if (f.gtPath && !f.gtPath->empty()) {
        const auto [xa, xb] = std::minmax_element(
            f.gtPath->begin(), f.gtPath->end(),
            [](const auto& a, const auto& b) { return a.pose.x() < b.pose.x(); });
        const auto [ya, yb] = std::minmax_element(
            f.gtPath->begin(), f.gtPath->end(),
            [](const auto& a, const auto& b) { return a.pose.y() < b.pose.y(); });
        x0 = std::floor(xa->pose.x()) - 1, x1 = std::ceil(xb->pose.x()) + 1;
        y0 = std::floor(ya->pose.y()) - 1, y1 = std::ceil(yb->pose.y()) + 1;
    }
    scene->insert(CGridPlaneXY::Create(x0, x1, y0, y1, 0, 1));
    if (f.gtPath) scene->insert(pathLines(*f.gtPath, scene_names::kGtPath, {0, 90, 200}));
    if (f.odomPath)
        scene->insert(pathLines(*f.odomPath, scene_names::kOdomPath, {130, 130, 130}));
    if (f.estPath)
        scene->insert(pathLines(*f.estPath, scene_names::kEstPath, {220, 30, 30}));
    if (!f.gtMap.empty())
        scene->insert(points(f.gtMap, scene_names::kGtTags, {128, 0, 160}, 4));
    if (!f.estMap.empty()) {
        scene->insert(points(f.estMap, scene_names::kEstTagPoints, {0, 150, 0}, 6));
        scene->insert(ellipses(f.estMap));
    }
    if (!readers.empty() && f.estPath && !f.estPath->empty())
        scene->insert(readerBoxes(readers, f.estPath->back().pose));
    return scene;
}
}  // namespace

void saveScene3D(const std::string& file, const TMapFigure& fig,
                 const std::vector<rfir::obs::TRFIDReader>& readers) {
    const auto scene = buildScene(fig, readers);
    rfir::common::writeViaTempFile(file, [&](const std::string& tmp) {
        mrpt::io::CFileGZOutputStream f;
        if (!f.open(tmp)) throw std::runtime_error("cannot write " + tmp);
        mrpt::serialization::archiveFrom(f) << *scene;
    });
}

}  // namespace rfir::eval
