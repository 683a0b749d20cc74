// Giving freed memory back to the system after the large, short-lived arrays of loading a
// mesh or building a BVH.
#pragma once

#include <cstddef>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace rts::render {

// Below this many primitives the arrays are small and the heap scan is not worth it.
inline constexpr std::size_t kReleaseMemoryMinItems = 100'000;

// The evaluator keeps large blocks in glibc's heap (runtime/evaluator.cpp: never unmapped,
// never trimmed), so freed transients stay resident and, fragmented, are not always reused:
// profile finding (peak RSS of a 2M-triangle mesh vs. massif's heap peak) that they added
// about a third to the whole process's peak. malloc_trim returns their whole free pages
// (madvise) without moving anything; a scan of the heap, done once per large mesh.
inline void return_free_pages() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}
inline void release_free_memory(std::size_t items) {
  if (items >= kReleaseMemoryMinItems) return_free_pages();
}

}  // namespace rts::render
