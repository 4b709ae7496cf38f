/* rfir fuzzing: MRPT records a call-stack backtrace (backtrace() and dladdr()
 * per frame) in every exception it throws, and a corrupt input throws on
 * nearly every run: that was the largest single cost of a refused input. The
 * harnesses define MRPT's function empty; exported from the executable
 * (ENABLE_EXPORTS), it takes precedence over libmrpt-core's for the MRPT
 * libraries too. Messages lose only their backtrace; what is thrown, and
 * where, is unchanged. */
#include <mrpt/core/backtrace.h>

namespace mrpt {
void callStackBackTrace(TCallStackBackTrace& out_bt, const unsigned int,
                        const unsigned int) noexcept {
    out_bt.backtrace_levels.clear();
}
}  // namespace mrpt
