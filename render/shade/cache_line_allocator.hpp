// An allocator whose blocks start on a cache line and span whole lines, for per-thread buffers
// that are written per ray: without it a block's first and last lines may hold another
// thread's data (false sharing; see Integrator::PendingStack).
#pragma once

#include <cstddef>
#include <new>

namespace rts::render {

inline constexpr std::size_t kCacheLine = 64;

template <class T>
struct CacheLineAllocator {
  using value_type = T;
  CacheLineAllocator() = default;
  template <class U>
  CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}  // NOLINT: rebinding
  static std::size_t bytes(std::size_t n) { return (n * sizeof(T) + kCacheLine - 1) / kCacheLine * kCacheLine; }
  T* allocate(std::size_t n) {
    return static_cast<T*>(::operator new(bytes(n), std::align_val_t(kCacheLine)));
  }
  // Unsized: clang 14 does not enable sized deallocation by default.
  void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, std::align_val_t(kCacheLine)); }
  template <class U>
  bool operator==(const CacheLineAllocator<U>&) const noexcept { return true; }
};

}  // namespace rts::render
