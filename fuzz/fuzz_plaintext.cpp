/* rfir fuzzing: rfir-plain-ps's text-log reader (parsePlainTextLog; the file
 * version reads the file and calls it). */
#include <rfir/bench/plain_textlog.h>

#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        rfir::bench::parsePlainTextLog(
            std::string(reinterpret_cast<const char*>(data), size), "log.txt");
    } catch (const std::runtime_error&) {
    }
    return 0;
}
