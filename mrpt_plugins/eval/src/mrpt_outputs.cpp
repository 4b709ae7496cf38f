/* rfir: what MRPT's rbpf-slam and pf-localization write, read into rfir's
 * paths and maps in the world frame. The layouts are MRPT 2.5.8's
 * (libs/apps/src/RBPF_SLAM_App.cpp, MonteCarloLocalization_App.cpp,
 * libs/maps/src/maps/CBeaconMap.cpp, libs/vision/src/maps/CLandmarksMap.cpp). */
#include <rfir/eval/input_formats.h>

#include "input_rows.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <stdexcept>

namespace rfir::eval {
using detail::numbersOf;
using detail::TTextRow;
using rfir::common::TMapEntry;
using rfir::common::TMapFile;
using rfir::common::TPath2D;
namespace fs = std::filesystem;

TPath2D loadRbpfSlamPath(const std::string& file, const mrpt::poses::CPose2D& start) {
    TPath2D path;
    for (const TTextRow& r : detail::readTextRows(file, "rbpf-slam path file")) {
        const auto v = numbersOf(r, file, 8, "8 numbers 'step x y z yaw pitch roll t'");
        const rfir::common::TStampedPose2D p{
            v[7], start + mrpt::poses::CPose2D(v[1], v[2], v[4])};
        if (!path.empty() && path.back().t == p.t)
            path.back() = p;  // the later step at that time
        else
            path.push_back(p);
    }
    if (path.empty()) throw std::runtime_error(file + ": no pose");
    return path;
}

namespace {
/** The weighted mean pose of one particles_NNNNN.txt (log weights). */
mrpt::poses::CPose2D meanOfParticles(const std::string& file) {
    std::vector<std::vector<double>> parts;
    double maxLw = -INFINITY;
    for (const TTextRow& r : detail::readTextRows(file, "particle file")) {
        parts.push_back(numbersOf(r, file, 4, "4 numbers 'x y phi log_weight'"));
        maxLw = std::max(maxLw, parts.back()[3]);
    }
    if (parts.empty()) throw std::runtime_error(file + ": no particle");
    double sw = 0, sx = 0, sy = 0, sc = 0, ss = 0;
    for (const auto& p : parts) {
        const double w = std::exp(p[3] - maxLw);  // the largest weighs 1
        sw += w, sx += w * p[0], sy += w * p[1];
        sc += w * std::cos(p[2]), ss += w * std::sin(p[2]);
    }
    return {sx / sw, sy / sw, std::atan2(ss, sc)};
}
}  // namespace

TPath2D loadPfLocalizationPath(const std::string& dir, const TMrptFrame& frame) {
    const fs::path d = fs::is_directory(fs::path(dir) / "particles")
                           ? fs::path(dir) / "particles"
                           : fs::path(dir);
    if (frame.instantTimes.empty())
        throw std::runtime_error(dir +
                                 ": pf-localization's particle files carry no time: "
                                 "give the rawlog with --rawlog");
    std::map<size_t, std::string> byStep;  // particles_0_initial.txt is no step
    const std::regex name("particles_([0-9]+)\\.txt");
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(d, ec)) {
        std::smatch m;
        const std::string f = e.path().filename().string();
        if (std::regex_match(f, m, name)) byStep[std::stoul(m[1])] = e.path().string();
    }
    if (ec || byStep.empty())
        throw std::runtime_error(d.string() +
                                 ": no particles_NNNNN.txt (pf-localization's output "
                                 "folder, with 3DSceneFrequency > 0)");
    TPath2D path;
    const size_t n = frame.instantTimes.size();
    for (const auto& [step, file] : byStep) {
        if (step < frame.firstInstantStep || step - frame.firstInstantStep >= n)
            throw std::runtime_error(file + ": step " + std::to_string(step) +
                                     " is none of the rawlog's " + std::to_string(n) +
                                     " instants (another rawlog?)");
        path.push_back(
            {frame.instantTimes[step - frame.firstInstantStep], meanOfParticles(file)});
    }
    return path;
}

namespace {
/** `e` moved from the frame of rbpf-slam's start into the world's: the point
 * composed with `start`, the standard deviations rotated with it. */
TMapEntry toWorld(TMapEntry e, const mrpt::poses::CPose2D& start) {
    const double c = std::cos(start.phi()), s = std::sin(start.phi());
    const double x = e.x, y = e.y;
    e.x = start.x() + c * x - s * y;
    e.y = start.y() + s * x + c * y;
    if (e.sx && e.sy) {
        const double vx = *e.sx * *e.sx, vy = *e.sy * *e.sy;
        e.sx = std::sqrt(c * c * vx + s * s * vy);
        e.sy = std::sqrt(s * s * vx + c * c * vy);
    }
    return e;
}

bool whole(double v) {
    return v == std::floor(v) && std::abs(v) < 1e15;
}

/** A landmark record of MRPT's text maps: CBeaconMap's 12 columns (ID
 * first, variances 5-7) or CLandmarksMap's 7 or more (ID last, its type 4th). */
TMapEntry mrptLandmark(const TTextRow& r, const std::string& file) {
    const auto v = numbersOf(r, file, 0, "numbers");
    TMapEntry e;
    e.kind = TMapEntry::Kind::Landmark;
    e.line = int(r.line);
    if (v.size() == 12 && whole(v[0])) {  // CBeaconMap::saveToTextFile
        e.id = std::to_string(int64_t(v[0]));
        e.x = v[1], e.y = v[2];
        if (v[4] >= 0 && v[5] >= 0) e.sx = std::sqrt(v[4]), e.sy = std::sqrt(v[5]);
    } else if (v.size() >= 7 && whole(v[3]) && whole(v.back())) {
        e.id = std::to_string(int64_t(v.back()));  // CLandmarksMap::saveToTextFile
        e.x = v[0], e.y = v[1];
    } else {
        throw std::runtime_error(
            file + ":" + std::to_string(r.line) +
            ": not a map MRPT's apps save (CBeaconMap: 'ID x y z VX VY VZ DET2D DET3D "
            "C12 C13 C23'; CLandmarksMap: 'X Y Z TYPE TIMES_SEEN TIME [descriptor] ID')");
    }
    return e;
}
}  // namespace

TMapFile loadMap(const std::string& file, InputFormat f, const TMrptFrame& frame) {
    if (f == InputFormat::Rfir) return rfir::common::loadMapFile(file);
    if (!frame.start)
        throw std::runtime_error(file +
                                 ": rbpf-slam's map starts at the origin: give the log's "
                                 "start pose (--start X Y PHI, or --rawlog with a header "
                                 "start pose)");
    const auto rows = detail::readTextRows(file, "map file");
    double first = 0;
    TMapFile m;
    if (!rows.empty() && !detail::toNumber(rows[0].tokens[0], first)) {
        m = rfir::common::loadMapFile(file);  // rfir's records (the tag map's file)
    } else {
        std::set<std::string> ids;
        for (const TTextRow& r : rows) {
            m.push_back(mrptLandmark(r, file));
            if (!ids.insert(m.back().id).second)
                throw std::runtime_error(file + ":" + std::to_string(r.line) +
                                         ": landmark " + m.back().id + " again");
        }
    }
    for (auto& e : m) e = toWorld(e, *frame.start);
    return m;
}

}  // namespace rfir::eval
