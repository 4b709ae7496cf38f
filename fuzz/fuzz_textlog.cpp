/* rfir fuzzing: the text-log parser (readTextLog from a stream: the file
 * version opens the file and reads through it; CTextLogParser, the strict
 * line parser the import also uses). In memory, so it runs fast; fuzz_import
 * runs the conversions on the logs it accepts. */
#include <rfir/common/textlog.h>

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        rfir::common::readTextLog(in, "input.txt");
    } catch (const std::exception&) {
    }
    return 0;
}
