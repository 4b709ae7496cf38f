/* rfir fuzzing: the rawlog reader (CRawlogReader, as every program reads a
 * rawlog: the project's observation classes and the MRPT classes around
 * them) on the bytes as a rawlog file, gzip-compressed or not, and, when the
 * whole file reads, its export to a text log (lossy, as rfir-import --lossy). */
#include "fuzz_util.h"

#include <rfir/common/log_convert.h>
#include <rfir/common/rawlog_io.h>

using namespace rfir::common;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = rfir::fuzz::writeInput("in.rawlog", data, size);
    try {
        CRawlogReader r(path);
        TRawlogStep step;
        size_t n = 0;
        while (r.next(step)) n++;
        (void)n;
    } catch (const std::exception&) {
        return 0;  // refused with an error: fine
    }
    const std::string txt = rfir::fuzz::scratchDir() + "/out.txt";
    try {
        TConvertOptions o;
        o.lossy = true;
        convertRawlogToTextLog(path, txt, o);
    } catch (const std::exception&) {
    }
    rfir::fuzz::removeFile(txt);
    return 0;
}
