/* The live view's recorded frames show the scene: every frame exists, is
 * PNG, is not uniform, and the last one holds at least kMinPixels pixels of
 * each colour the view draws the named items with (rfir/view/live_scene.h).
 *   gui_frames_check DIR MIN_FRAMES ITEM [ITEM...]
 * ITEM: particles, path, truth, landmark, sensor, read. Exit 0: all good. */
#include <rfir/view/live_scene.h>

#include <mrpt/img/CImage.h>
#include <mrpt/system/filesystem.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

namespace {
// Fixed before the first frame was looked at: a colour counts when every
// channel is within kTolerance of the view's; each item needs kMinPixels.
constexpr int kTolerance = 30;
constexpr size_t kMinPixels = 30;

const std::map<std::string, mrpt::img::TColor> kItems = {
    {"particles", rfir::view::colours::particles},
    {"path", rfir::view::colours::path},
    {"truth", rfir::view::colours::truth},
    {"landmark", rfir::view::colours::landmark},
    {"sensor", rfir::view::colours::sensor},
    {"read", rfir::view::colours::read}};

std::string frameName(const std::string& dir, size_t i) {
    char b[32];
    std::snprintf(b, sizeof(b), "/frame_%06zu.png", i);
    return dir + b;
}

bool near(const mrpt::img::TColor& a, const mrpt::img::TColor& b) {
    return std::abs(int(a.R) - int(b.R)) <= kTolerance &&
           std::abs(int(a.G) - int(b.G)) <= kTolerance &&
           std::abs(int(a.B) - int(b.B)) <= kTolerance;
}

mrpt::img::TColor pixel(const mrpt::img::CImage& img, int x, int y) {
    // CImage keeps 3-channel images as BGR.
    const auto* p = img.ptr<uint8_t>(x, y);
    return {p[2], p[1], p[0]};
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::cerr << "usage: gui_frames_check DIR MIN_FRAMES ITEM [ITEM...]\n";
        return 2;
    }
    const std::string dir = argv[1];
    const size_t minFrames = std::strtoul(argv[2], nullptr, 10);
    size_t n = 0;
    while (mrpt::system::fileExists(frameName(dir, n + 1))) n++;
    std::cout << dir << ": " << n << " frames\n";
    if (n < minFrames) {
        std::cerr << "FAIL: fewer than " << minFrames << " frames\n";
        return 1;
    }
    int fails = 0;
    mrpt::img::CImage img;
    for (size_t i = 1; i <= n; i++) {
        if (!img.loadFromFile(frameName(dir, i)) || img.getChannelCount() != 3) {
            std::cerr << "FAIL: " << frameName(dir, i) << " is not an RGB image\n";
            return 1;
        }
        const auto first = pixel(img, 0, 0);
        bool uniform = true;
        for (int y = 0; y < int(img.getHeight()) && uniform; y++)
            for (int x = 0; x < int(img.getWidth()) && uniform; x++) {
                const auto c = pixel(img, x, y);
                uniform = c.R == first.R && c.G == first.G && c.B == first.B;
            }
        if (uniform) std::cerr << "FAIL: " << frameName(dir, i) << " is uniform\n";
        fails += uniform;
    }
    // The last frame (img): the whole run's scene.
    for (int a = 3; a < argc; a++) {
        const auto it = kItems.find(argv[a]);
        if (it == kItems.end()) {
            std::cerr << "unknown item " << argv[a] << "\n";
            return 2;
        }
        size_t count = 0;
        for (int y = 0; y < int(img.getHeight()); y++)
            for (int x = 0; x < int(img.getWidth()); x++)
                count += near(pixel(img, x, y), it->second);
        std::cout << "  last frame: " << count << " pixels of " << it->first << "\n";
        if (count < kMinPixels) {
            std::cerr << "FAIL: " << it->first << ": " << count << " pixels < "
                      << kMinPixels << "\n";
            fails++;
        }
    }
    return fails ? 1 : 0;
}
