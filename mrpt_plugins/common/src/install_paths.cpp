#include <rfir/common/install_paths.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>

namespace rfir::common {
namespace {
std::string& stockConfigDirOverride() {
    static std::string dir;
    return dir;
}
}  // namespace

void setStockConfigDir(const std::string& dir) {
    stockConfigDirOverride() = dir;
}

std::string stockConfigDir() {
    if (!stockConfigDirOverride().empty()) return stockConfigDirOverride();
    char buf[4096];
    const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof(buf) - 1);
    if (n <= 0)
        throw std::runtime_error("cannot find the program's folder (/proc/self/exe)");
    buf[n] = 0;
    const auto dir = std::filesystem::path(buf).parent_path();
    return (dir / ".." / "share" / "rfir" / "config_ini").lexically_normal().string();
}

std::string slamIniPath(const std::string& dir, const std::string& method) {
    const std::string m = method == "fastslam" ? "fastslam"
                          : method == "ps"     ? "ps"
                                               : "pf";
    return dir + "/slam_" + m + ".ini";
}

std::string slamIniPath(const std::string& method) {
    return slamIniPath(stockConfigDir(), method);
}

std::string rawlogStem(const std::string& p) {
    for (const std::string ext : {".rawlog.gz", ".rawlog"})
        if (p.size() > ext.size() &&
            p.compare(p.size() - ext.size(), ext.size(), ext) == 0)
            return p.substr(0, p.size() - ext.size());
    return p;
}
}  // namespace rfir::common
