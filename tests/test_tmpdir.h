/* rfir tests: a temporary folder, removed with the object. ctest runs every
 * test case as its own process, in parallel: the name holds the process ID
 * and a counter. */
#pragma once

#include <unistd.h>

#include <filesystem>
#include <iterator>
#include <string>

namespace rfir_test {
struct TmpDir {
    std::filesystem::path p;
    TmpDir() {
        static int n = 0;
        p = std::filesystem::temp_directory_path() /
            ("rfir_test_" + std::to_string(getpid()) + "_" + std::to_string(n++));
        std::filesystem::create_directories(p);
    }
    ~TmpDir() {
        std::error_code ec;
        std::filesystem::remove_all(p, ec);
    }
    TmpDir(const TmpDir&) = delete;
    TmpDir& operator=(const TmpDir&) = delete;
    std::string operator/(const std::string& f) const { return (p / f).string(); }
    size_t count() const {
        return size_t(std::distance(std::filesystem::directory_iterator(p), {}));
    }
};
}  // namespace rfir_test
