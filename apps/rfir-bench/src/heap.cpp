#include "bench.h"

#include <malloc.h>

namespace rfir::bench
{
size_t heapInUse()
{
    // Bytes handed out by malloc and not freed (small chunks + mmapped ones),
    // summed over every arena: the state's own allocations, without the
    // allocator's cached free memory that RSS would include.
    const struct mallinfo2 mi = mallinfo2();
    return mi.uordblks + mi.hblkhd;
}
}  // namespace rfir::bench
