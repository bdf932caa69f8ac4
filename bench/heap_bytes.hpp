// Heap bytes in use, as the C library's allocator counts them (its own overhead included); 0 where
// the allocator does not say (only glibc's is read).
#pragma once
#include <cstddef>
#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
inline std::size_t heapBytesInUse() {
    const auto m = mallinfo2();
    return m.uordblks + m.hblkhd;  // small blocks, and the large ones glibc maps on their own
}
#else
inline std::size_t heapBytesInUse() { return 0; }
#endif
