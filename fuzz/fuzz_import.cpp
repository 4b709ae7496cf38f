/* rfir fuzzing: the import (rfir-import's two conversions) of the text logs
 * the parser accepts. Properties: no crash; a log the parser accepts either
 * imports or is refused with an exception; an imported log exports back
 * exactly (not lossy), and the export imports to the same rawlog bytes. */
#include "fuzz_util.h"

#include <rfir/common/log_convert.h>
#include <rfir/common/textlog.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

using namespace rfir::common;

namespace {
void check(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "property violated: %s\n", what);
    std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::istringstream in(text);
    try {
        readTextLog(in, "input.txt");
    } catch (const std::exception&) {
        return 0;  // refused with an error: fine
    }
    const std::string txt = rfir::fuzz::writeInput("in.txt", data, size);
    const std::string d = rfir::fuzz::scratchDir();
    const std::string raw1 = d + "/a.rawlog", txt2 = d + "/b.txt", raw2 = d + "/b.rawlog";
    try {
        convertTextLogToRawlog(txt, raw1);
    } catch (const std::exception&) {
        return 0;  // a rule of the rawlog layout on top of the text format's
    }
    try {
        convertRawlogToTextLog(raw1, txt2);
        convertTextLogToRawlog(txt2, raw2);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "round trip failed: %s\n", e.what());
        std::abort();
    }
    check(rfir::fuzz::slurp(raw1) == rfir::fuzz::slurp(raw2),
          "text -> rawlog -> text -> rawlog changed the rawlog");
    for (const auto& p : {raw1, txt2, raw2}) rfir::fuzz::removeFile(p);
    return 0;
}
