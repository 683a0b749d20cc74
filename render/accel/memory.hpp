// Giving freed memory back to the system after the large, short-lived arrays of loading a
// mesh or building a BVH.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>

#include <sys/mman.h>
#include <unistd.h>

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

// Gives back to the system the pages wholly inside [first, last) of a block whose contents
// there are not read again (a finished part of a large array the builder still holds). They
// read as zeros if touched later; pages shared with the rest of the block are kept. Safe on
// heap blocks too: malloc keeps nothing of its own inside a block in use (malloc_trim gives
// back free chunks the same way).
template <class T>
void release_pages(T* first, T* last) {
  // The system's page (4 KB here, 64 KB on some arm64 kernels, where 4 KB steps are refused).
  static const std::uintptr_t kPage = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const std::uintptr_t from = (reinterpret_cast<std::uintptr_t>(first) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t to = reinterpret_cast<std::uintptr_t>(last) & ~(kPage - 1);
  if (to > from) ::madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
}

// Pages mapped for one block and unmapped when it is freed, outside malloc's heaps: for large
// transients made and freed while the peak is being reached (the BVH builder's subtree node
// arrays, built on worker threads), which from a heap stay resident after their free until
// the next trim. Only the pages written become resident, so a generous reservation is free.
template <class T>
struct PageAllocator {
  using value_type = T;
  PageAllocator() = default;
  template <class U>
  PageAllocator(const PageAllocator<U>&) noexcept {}  // NOLINT: rebinding
  T* allocate(std::size_t n) {
    void* p = ::mmap(nullptr, n * sizeof(T), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    // Huge pages where the system gives them on request: a fresh page costs a fault and a
    // clearing, and 4 KB faults made the build 6% slower than recycled heap memory.
    if (n * sizeof(T) >= (std::size_t{4} << 20)) ::madvise(p, n * sizeof(T), MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept { ::munmap(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const PageAllocator<U>&) const noexcept { return true; }
};

}  // namespace rts::render
