// The .3Dscene export: written, read back with MRPT's reader, and holding the
// paths, the tags with their 2-sigma ellipses and the readers.
#include <rfir/eval/scene3d.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CEllipsoid2D.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include "test_tmpdir.h"

using namespace rfir::eval;
using mrpt::poses::CPose2D;

TEST(EvalScene, WrittenAndReadBackWithItsObjects) {
    TMapFigure f;
    f.gtPath = rfir::common::TPath2D{
        {0, CPose2D(0, 0, 0)}, {1, CPose2D(1, 0, 0)}, {2, CPose2D(1, 1, 1.5)}};
    f.estPath = rfir::common::TPath2D{
        {0, CPose2D(0, 0.01, 0)}, {1, CPose2D(1, 0.02, 0)}, {2, CPose2D(1.05, 1, 1.4)}};
    rfir::common::TMapEntry a, b, g;
    a.id = "A", a.x = 0.5, a.y = 0.1, a.sx = 0.02, a.sy = 0.01;
    b.id = "B", b.x = 1.1, b.y = 0.6, b.sx = 0.03, b.sy = 0.03;
    g.id = "A", g.x = 0.5, g.y = 0.12;
    f.estMap = {a, b};
    f.gtMap = {g};
    std::vector<rfir::obs::TRFIDReader> readers(2);
    readers[0].id = "left", readers[0].x = 0.1, readers[0].y = 0.05;
    readers[1].id = "right", readers[1].x = 0.1, readers[1].y = -0.05;

    rfir_test::TmpDir d;
    saveScene3D(d / "run.3Dscene", f, readers);
    EXPECT_EQ(d.count(), 1u);  // no temporary file left

    mrpt::opengl::COpenGLScene scene;
    mrpt::io::CFileGZInputStream in(d / "run.3Dscene");
    mrpt::serialization::archiveFrom(in) >> scene;

    auto gt = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(
        scene.getByName(scene_names::kGtPath));
    auto est = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(
        scene.getByName(scene_names::kEstPath));
    ASSERT_TRUE(gt && est);
    EXPECT_EQ(gt->getLineCount(), 2u);
    EXPECT_EQ(est->getLineCount(), 2u);
    EXPECT_FALSE(scene.getByName(scene_names::kOdomPath));  // none given
    auto pts = std::dynamic_pointer_cast<mrpt::opengl::CPointCloud>(
        scene.getByName(scene_names::kEstTagPoints));
    ASSERT_TRUE(pts);
    EXPECT_EQ(pts->size(), 2u);
    auto tags = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(
        scene.getByName(scene_names::kEstTags));
    ASSERT_TRUE(tags);
    EXPECT_EQ(tags->size(), 2u);
    auto ea = std::dynamic_pointer_cast<mrpt::opengl::CEllipsoid2D>(tags->getByName("A"));
    ASSERT_TRUE(ea);
    EXPECT_NEAR(ea->getQuantiles(), 2.0, 1e-6);  // 2 sigma
    EXPECT_NEAR(ea->getCovMatrix()(0, 0), 0.02 * 0.02, 1e-9);
    EXPECT_NEAR(ea->getCovMatrix()(1, 1), 0.01 * 0.01, 1e-9);
    EXPECT_NEAR(ea->getPoseX(), 0.5, 1e-6);
    auto rd = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(
        scene.getByName(scene_names::kReaders));
    ASSERT_TRUE(rd);
    EXPECT_EQ(rd->size(), 2u);
    EXPECT_TRUE(std::dynamic_pointer_cast<mrpt::opengl::CBox>(rd->getByName("left")));
    // At the robot's last estimated pose.
    EXPECT_NEAR(rd->getPoseX(), 1.05, 1e-6);
    EXPECT_NEAR(rd->getPose().yaw, 1.4, 1e-6);
    EXPECT_TRUE(scene.getByName(scene_names::kGtTags));
}
