/* rfir: progress of long runs on stderr. On a terminal one line is rewritten
 * in place; in a log file (CI, nohup) a line is printed every 10 %. */
#pragma once

#include <chrono>
#include <cstddef>
#include <iostream>
#include <string>

namespace rfir::common {
class CProgress {
  public:
    /** `what` prefixes every line, e.g. "rfir-slam"; total is the step count;
     * `out` nullptr: silent. Rewritten in place only when `out` is std::cerr
     * on a terminal. */
    CProgress(std::string what, size_t total, std::ostream* out = &std::cerr);
    /** Call after step i (0-based) is done; prints only when the display changes. */
    void update(size_t i);
    /** Ends the line on a terminal. */
    void finish();

  private:
    std::string what_;
    size_t total_, lastShown_ = size_t(-1);
    std::ostream* out_;
    bool tty_;
    std::chrono::steady_clock::time_point t0_;
};

}  // namespace rfir::common
