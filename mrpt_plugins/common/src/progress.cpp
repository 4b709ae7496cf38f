#include <rfir/common/progress.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace rfir::common {
CProgress::CProgress(std::string what, size_t total, std::ostream* out)
    : what_(std::move(what)),
      total_(std::max<size_t>(1, total)),
      out_(out),
      tty_(out == &std::cerr && ::isatty(STDERR_FILENO) != 0),
      t0_(std::chrono::steady_clock::now()) {}

void CProgress::update(size_t i) {
    if (!out_) return;
    const size_t done = std::min(i + 1, total_);
    // Percent shown: every 1 % on a terminal, every 10 % in a log.
    const size_t step = tty_ ? 1 : 10;
    const size_t pct = done * 100 / total_;
    const size_t shown = pct / step;
    if (shown == lastShown_) return;
    lastShown_ = shown;
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    const double eta = done ? s * (total_ - done) / done : 0;
    char buf[160];
    std::snprintf(buf, sizeof(buf), "%s: %3zu%% (%zu/%zu) %.1f s elapsed, ~%.1f s left",
                  what_.c_str(), pct, done, total_, s, eta);
    *out_ << (tty_ ? "\r" : "") << buf << (tty_ ? "" : "\n") << std::flush;
}

void CProgress::finish() {
    if (out_ && tty_ && lastShown_ != size_t(-1)) *out_ << "\n";
}

}  // namespace rfir::common
