/* The runs' step views turned into frames: what rfir-slam and rfir-localize
 * show. Only drawn frames read the engine (particles, landmarks). */
#include <rfir/view/CLiveView.h>

#include <cstdio>
#include <map>

namespace rfir::view {
namespace {
using mrpt::math::TPoint2D;
using mrpt::math::TPoint3D;

/** The true path up to `t` (drawn), and all of it (kept in view). */
void addTruth(const rfir::common::TPath2D& p, double t, TFrame& f) {
    for (const auto& s : p) {
        f.extent.push_back({s.pose.x(), s.pose.y()});
        if (s.t <= t) f.truth.push_back({s.pose.x(), s.pose.y()});
    }
}

std::string timeLine(const std::string& what, double t, size_t step, size_t steps) {
    char b[160];
    std::snprintf(b, sizeof(b), "%s   t = %.1f s   step %zu", what.c_str(), t, step + 1);
    std::string s = b;
    if (steps) s += " / " + std::to_string(steps);
    return s;
}

/** RFID readers (at the estimate), the readers that read, lines to the tags. */
void addReaders(const rfir::obs::CObservationRFIDReaders& obs,
                const mrpt::math::TPose2D& robot,
                const std::map<std::string, TLandmarkMark>& tags, TFrame& f) {
    for (const auto& r : obs.readings) {
        const auto& g = r.reader;
        auto fp = footprint(robot, g.x, g.y, g.halfX, g.halfY);
        if (r.tags.empty()) {
            f.readers.push_back(std::move(fp));
            continue;
        }
        double cx = 0, cy = 0;
        mrpt::poses::CPose2D(robot).composePoint(g.x, g.y, cx, cy);
        for (const auto& t : r.tags)
            if (const auto it = tags.find(t); it != tags.end())
                f.reads.push_back({{cx, cy, 0.03}, {it->second.x, it->second.y, 0.03}});
        f.readingReaders.push_back(std::move(fp));
    }
}
}  // namespace

rfir::slamapp::TStepObserver CLiveView::slamObserver() {
    return [this](const rfir::slamapp::TStepView& v) { slamStep(v); };
}

rfir::localize::TStepObserver CLiveView::localizeObserver() {
    return [this](const rfir::localize::TStepView& v) { localizeStep(v); };
}

void CLiveView::slamStep(const rfir::slamapp::TStepView& v) {
    const auto pose = v.engine.pose().asTPose();
    path_.push_back({pose.x, pose.y});
    if (!v.events.empty()) lastEvents_ = v.events, eventFrames_ = 3;
    if (!due(v.step, v.step + 1 == v.steps)) return;
    TFrame f;
    f.particles = v.engine.particlePoses();
    f.path = path_;
    if (v.truth) addTruth(*v.truth, v.input.t, f);
    std::map<std::string, TLandmarkMark> tags;
    for (const auto& l : v.engine.landmarks()) {
        const TLandmarkMark m{l.x, l.y, 0, l.sx, l.sy};
        f.landmarks.push_back(m);
        if (l.isTag) tags[l.id] = m;
    }
    if (v.input.rfid) addReaders(*v.input.rfid, pose, tags, f);
    f.text.push_back(
        timeLine(opts_.program + " " + v.method, v.input.t, v.step, v.steps));
    if (eventFrames_ > 0) {
        eventFrames_--;
        for (const auto& e : lastEvents_) f.text.push_back(e);
    }
    show(f);
}

void CLiveView::localizeStep(const rfir::localize::TStepView& v) {
    const auto pose =
        (v.localizer && v.info.started ? v.localizer->estimate() : v.odometry).asTPose();
    if (!v.localizer || v.info.started) path_.push_back({pose.x, pose.y});
    if (v.info.lost)
        lastEvents_ = {"track lost: particles redrawn from emitter " + v.info.lostId},
        eventFrames_ = 3;
    else if (v.info.resetParticles && !v.info.justStarted)
        lastEvents_ = {"sensor resetting: " + std::to_string(v.info.resetParticles) +
                       " particles redrawn"},
        eventFrames_ = 3;
    if (!due(v.step, false)) return;
    TFrame f;
    if (v.localizer) f.particles = v.localizer->particlePoses();
    f.path = path_;
    if (v.truth) addTruth(*v.truth, v.t, f);
    const auto& emitters = v.cfg.map->emitters().emitters();
    for (const auto& e : emitters) f.landmarks.push_back({e.x, e.y, 0, 0, 0});
    if (v.ir) {
        const mrpt::poses::CPose2D robot(pose);
        for (const auto& r : v.ir->readings) {
            double x = 0, y = 0;
            robot.composePoint(r.receiver.x, r.receiver.y, x, y);
            f.receivers.push_back({x, y});
            if (r.codes.empty()) continue;
            // The emitter the map attributes the reading to at the estimate
            // (a repeated ID: the one the estimate is under).
            if (const auto i = v.cfg.map->associate(r, pose))
                f.reads.push_back({{x, y, 0.03}, {emitters[*i].x, emitters[*i].y, 0.03}});
        }
    }
    f.text.push_back(timeLine(opts_.program + (v.localizer ? " MCL" : " odometry only"),
                              v.t, v.step, 0));
    if (v.localizer && !v.info.started)
        f.text.push_back("waiting for a unique-ID reading");
    if (eventFrames_ > 0) {
        eventFrames_--;
        for (const auto& e : lastEvents_) f.text.push_back(e);
    }
    show(f);
}

}  // namespace rfir::view
