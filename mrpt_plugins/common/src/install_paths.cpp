#include <rfir/common/install_paths.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>

namespace rfir::common {
std::string stockConfigDir() {
    char buf[4096];
    const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof(buf) - 1);
    if (n <= 0)
        throw std::runtime_error("cannot find the program's folder (/proc/self/exe)");
    buf[n] = 0;
    const auto dir = std::filesystem::path(buf).parent_path();
    return (dir / ".." / "share" / "rfir" / "config_ini").lexically_normal().string();
}
}  // namespace rfir::common
