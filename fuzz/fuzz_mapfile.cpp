/* rfir fuzzing: the map / ground-truth file reader (loadMapFile, used by
 * rfir-eval and rfir-slam) and, for a file it accepts, the emitter file
 * reader of rfir-localize and the irEmitterMap (TEmitterSet::load, which
 * reads the file through loadMapFile first) on the same bytes. */
#include "fuzz_util.h"

#include <rfir/common/map_io.h>
#include <rfir/ir/emitter_set.h>

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        rfir::common::loadMapFile(in, "map.txt");
    } catch (const std::exception&) {
        return 0;
    }
    try {
        rfir::ir::TEmitterSet::load(rfir::fuzz::writeInput("map.txt", data, size));
    } catch (const std::exception&) {
    }
    return 0;
}
