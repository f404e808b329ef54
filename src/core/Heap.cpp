// gnomon::keepFreedHeap (gnomon.h): the process's allocator told to keep what it frees.
#include "gnomon/gnomon.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace gnomon {

bool keepFreedHeap() {
#if defined(__SANITIZE_ADDRESS__)
    return false;  // the sanitizer's allocator serves malloc; glibc's thresholds do nothing
#elif defined(__GLIBC__)
    // Where glibc's own dynamic thresholds stop rising: allocations from 32 MiB on are mapped
    // on their own, and the heap's top goes back to the system only beyond 64 MiB.
    const bool mapped = mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1;
    const bool trimmed = mallopt(M_TRIM_THRESHOLD, 64 << 20) == 1;
    return mapped && trimmed;
#else
    return false;
#endif
}

}  // namespace gnomon
