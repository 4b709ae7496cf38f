/* rfir fuzzing: the TUM trajectory reader (loadTUM: ground truth and paths
 * read by rfir-eval, rfir-slam and rfir-localize; the file version opens the
 * file and reads through this one). */
#include <rfir/common/trajectory_io.h>

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        rfir::common::loadTUM(in, "path.tum");
    } catch (const std::exception&) {
    }
    return 0;
}
