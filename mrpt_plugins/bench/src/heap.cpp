#include <rfir/bench/bench.h>

#include <malloc.h>
#include <time.h>

#include <chrono>

namespace rfir::bench {
size_t heapInUse() {
    // Bytes handed out by malloc and not freed (small chunks + mmapped ones),
    // summed over every arena: the state's own allocations, without the
    // allocator's cached free memory that RSS would include.
    const struct mallinfo2 mi = mallinfo2();
    return mi.uordblks + mi.hblkhd;
}

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double wallSeconds() {
    return std::chrono::duration<double>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
}  // namespace rfir::bench
