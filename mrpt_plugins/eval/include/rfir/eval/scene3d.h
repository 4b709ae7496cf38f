/* rfir: a run as an MRPT 3D scene (.3Dscene, opened by MRPT's SceneViewer3D):
 * the paths, the tags with their 2-sigma ellipses, and the RFID readers at the
 * robot's last estimated pose. */
#pragma once

#include <rfir/eval/plot.h>
#include <rfir/obs/CObservationRFIDReaders.h>

#include <mrpt/opengl/COpenGLScene.h>

#include <string>
#include <vector>

namespace rfir::eval {
/** Object names in the scene (COpenGLScene::getByName). */
namespace scene_names {
inline constexpr const char* kGtPath = "ground_truth_path";
inline constexpr const char* kEstPath = "estimated_path";
inline constexpr const char* kOdomPath = "odometry_path";
inline constexpr const char* kGtTags = "true_tags";
/** A CSetOfObjects of one CEllipsoid2D per estimated tag with stds, named by ID. */
inline constexpr const char* kEstTags = "estimated_tags";
inline constexpr const char* kEstTagPoints = "estimated_tag_positions";
/** A CSetOfObjects of one flat CBox per reader, named by the reader's ID. */
inline constexpr const char* kReaders = "readers";
}  // namespace scene_names

/** Writes the figure's paths and maps in 3D (z = 0, metres; colours as in the
 * PNG) gz-compressed (MRPT's .3Dscene), atomically. */
void saveScene3D(const std::string& file, const TMapFigure& fig,
                 const std::vector<rfir::obs::TRFIDReader>& readers);

}  // namespace rfir::eval
