/* rfir: the files rfir-eval scores. TUM paths are checked for their shape (a
 * file that is not TUM is refused, saying what it looks like); the outputs of
 * MRPT's rbpf-slam and pf-localization (their paths, the beacon and landmark
 * maps they save) are read and put in the world frame, so that they are
 * scored like rfir's own runs (docs/mrpt-apps.md). */
#pragma once

#include <rfir/common/map_io.h>
#include <rfir/common/trajectory_io.h>

#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>
#include <vector>

namespace rfir::eval {
/** How an estimated path or map is written (--path-format, --map-format). */
enum class InputFormat {
    Rfir,  //!< a TUM path `t x y z qx qy qz qw`, rfir's map records
    Mrpt   //!< what MRPT's rbpf-slam or pf-localization writes
};

/** "tum" or "rfir": Rfir, "mrpt": Mrpt; else rfir::common::CUsageError
 * naming `option`. */
InputFormat parseInputFormat(const std::string& option, const std::string& s);

/** What puts the outputs of MRPT's apps in the world frame. */
struct TMrptFrame {
    /** The robot's world pose at the start of the log: rbpf-slam's path and
     * maps start at the origin (rfir-eval: --start, else the rawlog
     * header's). pf-localization's are in the map's frame already. */
    std::optional<mrpt::poses::CPose2D> start;
    /** The times of the rawlog's sensing instants (pf-localization's
     * particle files carry none: their step numbers are mapped to these). */
    std::vector<double> instantTimes;
    /** pf-localization's step (its action-observation pair) of the first
     * instant: 1 after the rfir log header's pair, 0 without it. */
    size_t firstInstantStep = 0;
};

/** Empty when `file` is shaped as a TUM path (8 numbers a row, columns 5 to 8
 * a unit quaternion on every row); otherwise what the file looks like, e.g.
 * "it looks like MRPT rbpf-slam's log_estimated_path.txt (step x y z yaw
 * pitch roll t): use --path-format mrpt". Rows that are not numbers are left
 * for the TUM reader to report by line. */
std::string tumShapeProblem(const std::string& file);

/** A TUM path; std::runtime_error "FILE: not a TUM path (t x y z qx qy qz qw,
 * a unit quaternion): <tumShapeProblem>" when it is not one. */
rfir::common::TPath2D loadTumChecked(const std::string& file);

/** rbpf-slam's log_estimated_path.txt: rows `step x y z yaw pitch roll t`
 * (MRPT 2.5's RBPF_SLAM_App), poses from the origin, each composed with
 * `start`. Of rows with one time, the last (rbpf-slam's first step is the
 * rfir log header's pair, at the first instant's time). */
rfir::common::TPath2D loadRbpfSlamPath(const std::string& file,
                                       const mrpt::poses::CPose2D& start);

/** pf-localization's particles_NNNNN.txt files in `dir` (its output folder or
 * that folder's particles/): per file, rows `x y phi log_weight`, the
 * weighted mean pose, at the time of step NNNNN's instant in
 * frame.instantTimes. pf-localization 2.5 writes no path file; these are
 * written every 3DSceneFrequency steps, in the map's frame. */
rfir::common::TPath2D loadPfLocalizationPath(const std::string& dir,
                                             const TMrptFrame& frame);

/** An estimated path: Rfir: loadTumChecked; Mrpt: a folder is
 * pf-localization's, a file rbpf-slam's (needs frame.start). */
rfir::common::TPath2D loadPath(const std::string& file, InputFormat f,
                               const TMrptFrame& frame);

/** An estimated map: Rfir: rfir::common::loadMapFile; Mrpt: a map rbpf-slam
 * saved, from the origin, composed with frame.start: CBeaconMap's text
 * (`ID x y z VX VY VZ DET2D DET3D C12 C13 C23`, finalMap_..._covs.txt) or
 * CLandmarksMap's (`X Y Z TYPE TIMES_SEEN TIME [descriptor] ID`) as
 * landmark records, or rfir's records (rfir's tag map inside rbpf-slam,
 * finalMap_..._tags.txt). Errors name the file and line. */
rfir::common::TMapFile loadMap(const std::string& file, InputFormat f,
                               const TMrptFrame& frame);

}  // namespace rfir::eval
