/* rfir: what one frame of the live view shows, in world coordinates, and the
 * MRPT scene drawn from it. The colours are fixed here: the docs and the
 * frames' test name them. */
#pragma once

#include <mrpt/img/TColor.h>
#include <mrpt/math/TBoundingBox.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/opengl/COpenGLScene.h>

#include <string>
#include <utility>
#include <vector>

namespace rfir::view {
/** The colours of the view (the frames' test counts pixels of each). */
namespace colours {
constexpr mrpt::img::TColor particles{220, 0, 0};   //!< robot particles: red
constexpr mrpt::img::TColor path{0, 0, 230};        //!< estimated path: blue
constexpr mrpt::img::TColor truth{0, 170, 0};       //!< true path: green
constexpr mrpt::img::TColor landmark{200, 0, 200};  //!< tags, emitters: magenta
constexpr mrpt::img::TColor sensor{230, 150, 0};    //!< readers, receivers: orange
constexpr mrpt::img::TColor read{0, 190, 210};      //!< this step's reads: cyan
}  // namespace colours

/** A tag or an emitter: its estimate and standard deviations (0: known). */
struct TLandmarkMark {
    double x = 0, y = 0, z = 0, sx = 0, sy = 0;
};

struct TFrame {
    std::vector<mrpt::math::TPose2D> particles;
    std::vector<mrpt::math::TPoint2D> path, truth;
    /** Reader footprints (closed polygons) and receivers (points), world frame. */
    std::vector<std::vector<mrpt::math::TPoint2D>> readers;
    std::vector<mrpt::math::TPoint2D> receivers;
    /** The sensors that read something this step, and a line to what they read. */
    std::vector<std::vector<mrpt::math::TPoint2D>> readingReaders;
    std::vector<std::pair<mrpt::math::TPoint3D, mrpt::math::TPoint3D>> reads;
    std::vector<TLandmarkMark> landmarks;
    std::vector<std::string> text;  //!< lines at the top left
    /** Points the camera keeps in view, not drawn (the whole true path). */
    std::vector<mrpt::math::TPoint2D> extent;
};

/** Grows `box` (MRPT's, z = 0) by every point (anything with x and y). */
template <class Points>
void growBox(mrpt::math::TBoundingBox& box, const Points& points) {
    for (const auto& p : points) box.updateWithPoint({p.x, p.y, 0});
}

/** Fills `scene` with the frame (clears it first). */
void drawFrame(const TFrame& f, mrpt::opengl::COpenGLScene& scene);

/** Reader footprint (robot frame, centre and half sizes) placed at `robot`. */
std::vector<mrpt::math::TPoint2D> footprint(const mrpt::math::TPose2D& robot, double x,
                                            double y, double halfX, double halfY);

}  // namespace rfir::view
