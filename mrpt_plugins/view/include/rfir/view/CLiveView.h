/* rfir: the live view of a run (--gui): an MRPT 3D window redrawn every few
 * steps, the keyboard (pause, step, speed, close) and the recording of the
 * frames as PNG files (--gui-record). It only reads the run. */
#pragma once

#include <rfir/localize/localize_run.h>
#include <rfir/slamapp/slam_app.h>
#include <rfir/view/live_scene.h>

#include <memory>
#include <optional>
#include <string>

namespace mrpt::gui {
class CDisplayWindow3D;
}
namespace mrpt::opengl {
class CFBORender;
}

namespace rfir::view {
struct TLiveViewOptions {
    std::string program;    //!< for the messages and the title ("rfir-slam")
    std::string recordDir;  //!< --gui-record; empty: no recording
    unsigned every = 10;    //!< steps between two frames (--gui-every)
    unsigned width = 800, height = 600;
};

/** Throws rfir::common::CUsageError naming --gui when there is no display
 * (DISPLAY unset, or no X server answers): called before any work. */
void checkDisplay(const std::string& program);

class CLiveView {
  public:
    /** Checks the display (checkDisplay); the window opens at the first frame. */
    explicit CLiveView(const TLiveViewOptions& o);
    ~CLiveView();

    /** The observers the runs call after each step. */
    rfir::slamapp::TStepObserver slamObserver();
    rfir::localize::TStepObserver localizeObserver();

    /** Shows (and records) a frame: the step counter decides if it is due. */
    void show(const TFrame& f);
    size_t framesWritten() const { return frames_; }

  private:
    void slamStep(const rfir::slamapp::TStepView& v);
    void localizeStep(const rfir::localize::TStepView& v);
    bool due(size_t step, bool last) const;
    void openWindow();
    void fitCamera(const TFrame& f);
    void record(const mrpt::opengl::COpenGLScene& scene);
    /** Keys; blocks while paused. */
    void handleKeys();
    std::string keysLine() const;

    TLiveViewOptions opts_;
    std::shared_ptr<mrpt::gui::CDisplayWindow3D> win_;
    std::unique_ptr<mrpt::opengl::CFBORender> fbo_;  //!< the recorder's renderer
    bool closed_ = false, paused_ = false, stepOnce_ = false;
    int delayMs_ = 0;
    size_t frames_ = 0;
    /** The path so far (estimate), accumulated by the observers. */
    std::vector<mrpt::math::TPoint2D> path_;
    std::vector<std::string> lastEvents_;
    size_t eventFrames_ = 0;             //!< frames the last events stay on screen
    double cx_ = 0, cy_ = 0, zoom_ = 0;  //!< the camera, refitted as the scene grows
};

}  // namespace rfir::view
