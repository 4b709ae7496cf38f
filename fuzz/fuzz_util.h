/* rfir fuzzing: the programs read files by path, so the harnesses write each
 * input to a file of a per-process scratch folder (removed at exit). */
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace rfir::fuzz {
/** The scratch folder: $RFIR_FUZZ_TMP (default /dev/shm, else /tmp) plus the
 * process ID, so parallel jobs do not share files. */
inline const std::string& scratchDir() {
    struct TDir {
        std::string path;
        TDir() {
            const char* env = std::getenv("RFIR_FUZZ_TMP");
            const std::string base = env && *env ? env
                                     : std::filesystem::is_directory("/dev/shm")
                                         ? "/dev/shm"
                                         : "/tmp";
            path = base + "/rfir-fuzz-" + std::to_string(::getpid());
            std::filesystem::create_directories(path);
        }
        ~TDir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const TDir dir;
    return dir.path;
}

/** Writes the bytes to scratchDir()/name and returns the path. */
inline std::string writeInput(const std::string& name, const uint8_t* data, size_t size) {
    const std::string path = scratchDir() + "/" + name;
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!f) std::abort();  // the harness itself failed, not the code under test
    return path;
}

/** Removes a file the code under test may have written. */
inline void removeFile(const std::string& path) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
}

/** Reads a whole file (empty when absent). */
inline std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}
}  // namespace rfir::fuzz
