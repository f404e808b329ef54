// gnomon::keepFreedHeap: memory the process frees stays in its heap (no GL).
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "gnomon/gnomon.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

// 8 MiB in blocks of 64 KiB (below any mmap threshold, so they come from the heap's top),
// freed newest first: with glibc's defaults (a 128 KiB trim threshold in a fresh process,
// which each test is under ctest) the freed top goes back to the system and the heap shrinks;
// kept, it stays as large as it grew.
TEST(Heap, WhatIsFreedStaysInTheHeap) {
#if defined(__SANITIZE_ADDRESS__) || !defined(__GLIBC__)
    EXPECT_FALSE(gnomon::keepFreedHeap());
    GTEST_SKIP() << "not glibc's allocator: nothing to keep";
#else
    ASSERT_TRUE(gnomon::keepFreedHeap());
    constexpr std::size_t kBlock = 64 << 10, kBlocks = 128;
    std::vector<void*> blocks;
    for (std::size_t i = 0; i < kBlocks; ++i) {
        void* b = std::malloc(kBlock);
        ASSERT_NE(b, nullptr);
        std::memset(b, int(i), kBlock);
        blocks.push_back(b);
    }
    const std::size_t grown = mallinfo2().arena;
    for (auto it = blocks.rbegin(); it != blocks.rend(); ++it)
        std::free(*it);
    EXPECT_GE(mallinfo2().arena, grown);
    EXPECT_GE(grown, kBlock * kBlocks);
#endif
}
