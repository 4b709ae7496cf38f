#include <rfir/view/CLiveView.h>

#include <rfir/common/usage_error.h>

#include <mrpt/gui/CDisplayWindow3D.h>
#include <mrpt/gui/keycodes.h>
#include <mrpt/opengl/CFBORender.h>

#include <X11/Xlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

namespace rfir::view {
namespace {
/** Looking down, x to the right and y up (a map); 90 degrees exactly would
 * leave the camera's up direction undefined. */
constexpr float kAzimuthDeg = -90, kElevationDeg = 89.9f;
}  // namespace

void checkDisplay(const std::string& program) {
    const char* d = std::getenv("DISPLAY");
    if (!d || !*d)
        throw rfir::common::CUsageError(
            "--gui: no display (DISPLAY is not set); " + program +
            " draws the live view in a window: run it on a desktop, or under "
            "xvfb-run to record frames headless (--gui-record DIR)");
    // Ask the X server itself: wxWidgets would otherwise fail silently.
    Display* x = XOpenDisplay(d);
    if (!x)
        throw rfir::common::CUsageError("--gui: cannot open the display '" +
                                        std::string(d) + "' (no X server answers)");
    XCloseDisplay(x);
}

namespace {
/** The recording folder: created at the first frame (with its parents), so
 * it must be creatable; one with frames of another run is refused (a video of both
 * would mix them). */
void checkRecordDir(const std::string& dir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw rfir::common::CUsageError("--gui-record: '" + dir + "' is not a folder");
    if (fs::is_directory(dir, ec)) {
        for (const auto& e : fs::directory_iterator(dir, ec))
            if (e.path().filename().string().rfind("frame_", 0) == 0)
                throw rfir::common::CUsageError(
                    "--gui-record: '" + dir +
                    "' already holds frames (frame_*.png): give a new or empty folder");
        return;
    }
    // Created with its parents: the nearest one that exists must be a folder.
    fs::path up = fs::absolute(dir, ec).parent_path();
    while (!up.empty() && !fs::exists(up, ec) && up != up.parent_path())
        up = up.parent_path();
    if (!fs::is_directory(up, ec))
        throw rfir::common::CUsageError("--gui-record: cannot create '" + dir + "' ('" +
                                        up.string() + "' is not a folder)");
}
}  // namespace

CLiveView::CLiveView(const TLiveViewOptions& o) : opts_(o) {
    if (!o.recordDir.empty()) checkRecordDir(o.recordDir);
    checkDisplay(o.program);
    if (opts_.every == 0) opts_.every = 1;
}

CLiveView::~CLiveView() = default;

bool CLiveView::due(size_t step, bool last) const {
    return !closed_ && (step % opts_.every == 0 || last || stepOnce_);
}

void CLiveView::openWindow() {
    std::error_code ec;
    if (!opts_.recordDir.empty() &&
        !std::filesystem::create_directories(opts_.recordDir, ec) &&
        !std::filesystem::is_directory(opts_.recordDir))
        throw std::runtime_error("--gui-record: cannot create the folder '" +
                                 opts_.recordDir + "'");
    win_ = std::make_shared<mrpt::gui::CDisplayWindow3D>(opts_.program + " (live view)",
                                                         opts_.width, opts_.height);
    win_->setCameraAzimuthDeg(kAzimuthDeg);
    win_->setCameraElevationDeg(kElevationDeg);
    win_->setCameraProjective(false);  // a map view: no perspective
}

void CLiveView::fitCamera(const TFrame& f) {
    auto b = mrpt::math::TBoundingBox::PlusMinusInfinity();
    growBox(b, f.extent), growBox(b, f.path), growBox(b, f.landmarks);
    growBox(b, f.particles);
    if (b.min.x > b.max.x) return;
    const double x0 = b.min.x, y0 = b.min.y, x1 = b.max.x, y1 = b.max.y;
    // MRPT's orthographic view shows a width of zoom / kZoomPerWidth (m).
    constexpr double kZoomPerWidth = 1.5;
    const double aspect = double(opts_.height) / opts_.width;
    const double visW = zoom_ / kZoomPerWidth, visH = visW * aspect;
    const double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
    // Refitted only when the scene leaves the view: a user's zoom stays.
    if (zoom_ > 0 && std::abs(mx - cx_) + 0.5 * (x1 - x0) < 0.5 * visW &&
        std::abs(my - cy_) + 0.5 * (y1 - y0) < 0.5 * visH)
        return;
    const double need = std::max({x1 - x0, (y1 - y0) / aspect, 1.0});
    cx_ = mx, cy_ = my, zoom_ = kZoomPerWidth * 1.25 * need;
    win_->setCameraPointingToPoint(cx_, cy_, 0);
    win_->setCameraZoom(zoom_);
}

void CLiveView::record(const mrpt::opengl::COpenGLScene& scene) {
    // Off-screen: reading back the window's own buffer gives black frames
    // with Mesa's software renderer (Xvfb). The camera is the view's fitted
    // one (the window's answers its setters later, from its own thread), so
    // that the frames do not depend on the window's timing.
    mrpt::opengl::COpenGLScene copy = scene;
    auto& cam = copy.getViewport()->getCamera();
    cam.setPointingAt(cx_, cy_, 0);
    cam.setZoomDistance(zoom_);
    cam.setAzimuthDegrees(kAzimuthDeg);
    cam.setElevationDegrees(kElevationDeg);
    cam.setProjectiveModel(false);
    if (!fbo_)
        fbo_ = std::make_unique<mrpt::opengl::CFBORender>(
            mrpt::opengl::CFBORender::Parameters(opts_.width, opts_.height));
    fbo_->setCamera(copy, cam);
    mrpt::img::CImage img;
    fbo_->render_RGB(copy, img);
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%06zu.png", frames_ + 1);
    const std::string file = opts_.recordDir + "/" + name;
    if (!img.saveToFile(file))
        throw std::runtime_error("--gui-record: cannot write " + file);
}

std::string CLiveView::keysLine() const {
    std::string s = paused_ ? "PAUSED" : "running";
    if (delayMs_ > 0) s += " (" + std::to_string(delayMs_) + " ms/frame)";
    return s + "   space pause | s step | +/- speed | q close";
}

void CLiveView::handleKeys() {
    using namespace mrpt::gui;  // the MRPTK_* key codes
    stepOnce_ = false;
    do {
        if (!win_->isOpen()) {
            closed_ = true;
            return;
        }
        while (win_->keyHit()) {
            const int k = win_->getPushedKey();
            if (k == ' ') paused_ = !paused_;
            if (k == 's' || k == 'S' || k == MRPTK_RIGHT || k == MRPTK_NUMPAD_RIGHT) {
                paused_ = true;
                stepOnce_ = true;
            }
            // '=' is '+' without shift on many layouts; the keypad's too.
            if (k == '+' || k == '=' || k == MRPTK_ADD || k == MRPTK_NUMPAD_ADD)
                delayMs_ = delayMs_ <= 10 ? 0 : delayMs_ / 2;
            if (k == '-' || k == MRPTK_SUBTRACT || k == MRPTK_NUMPAD_SUBTRACT)
                delayMs_ = std::min(2000, delayMs_ == 0 ? 10 : delayMs_ * 2);
            if (k == 'q' || k == 'Q' || k == MRPTK_ESCAPE) {
                closed_ = true;  // the run goes on without the view
                win_.reset();
                return;
            }
        }
        if (paused_ && !stepOnce_)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
    } while (paused_ && !stepOnce_);
    if (delayMs_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(delayMs_));
}

void CLiveView::show(const TFrame& frame) {
    if (closed_) return;
    if (!win_) openWindow();
    TFrame f = frame;
    f.text.push_back(keysLine());
    fitCamera(f);
    {
        auto& scene = win_->get3DSceneAndLock();
        drawFrame(f, *scene);
        if (!opts_.recordDir.empty()) record(*scene);
        win_->unlockAccess3DScene();
    }
    if (!opts_.recordDir.empty()) frames_++;
    win_->forceRepaint();
    handleKeys();
}

}  // namespace rfir::view
