/* rfir-plain-ps: the text log (format textlog 1) as the plain reference
 * reads it: RFID readers, start pose, odometry and RFID reads; any other
 * record, and any malformed line, is refused with its file and line. */
#pragma once

#include <rfir/bench/plain_ps_core.h>

#include <string>
#include <vector>

namespace rfir::bench {
struct TPlainLog {
    std::string text;  //!< the whole file: reads view their tag IDs in it
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

}  // namespace rfir::bench
