/* rfir-plain-ps: the text log (format textlog 1) as the plain reference
 * reads it: RFID readers, start pose, odometry and RFID reads; any other
 * record, and any malformed line, is refused with its file and line. */
#pragma once

#include <rfir/bench/plain_ps_core.h>

#include <memory>
#include <string>
#include <vector>

namespace rfir::bench {
struct TPlainLog {
    /** The whole file: reads view their tag IDs in it (held by pointer, so
     * that moving the log keeps the views valid). */
    std::shared_ptr<const std::string> text;
    double start[3] = {0, 0, 0};
    /** One sensing instant: its odometry increment (if any) and its reads
     * [firstRead, firstRead + nReads) of `reads`. */
    struct TInstant {
        double t = 0;
        bool hasU = false;
        double u[3] = {0, 0, 0};
        size_t firstRead = 0, nReads = 0;
    };
    std::vector<TInstant> instants;
    std::vector<TPlainRead> reads;
};

/** Throws std::runtime_error "PATH:LINE: what is wrong". */
TPlainLog loadPlainTextLog(const std::string& path);
/** The same on the file's text; `name` is the file named in errors. */
TPlainLog parsePlainTextLog(std::string text, const std::string& name);

}  // namespace rfir::bench
