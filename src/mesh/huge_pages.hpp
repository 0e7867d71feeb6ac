// advise_huge_pages: ask the OS to back a large buffer with huge pages (Linux THP in
// "madvise" mode). The kernel's big arrays (tet records, points, marks) are read in a
// spatially coherent but address-scattered order; 2 MiB pages cut the TLB misses of that
// pattern (measured: about 7% of the bulk construction time, bench/README.md). A hint
// only: no effect on contents, ignored where unsupported; at most one partial huge page
// of extra resident memory per buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pdr {

inline void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
  const auto begin = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t last = (begin + bytes) & ~(kHuge - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

// std::allocator, except that a block of at least one huge page is advised for huge pages
// when it is allocated, before a vector copies into it. A large array (the checker's) is
// then faulted in 2 MiB at a time rather than 4 KiB: on a virtual machine where each page
// fault exits to the hypervisor, faulting a large array in 4 KiB pages costs about as much
// as writing it many times over. Arrays that grow with the mesh are GrowingArrays
// (mesh/growing_array.hpp), which also avoid the copies of growth.
template <class T>
struct HugePageAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = HugePageAllocator<U>;
  };
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    T* p = std::allocator<T>::allocate(n);
    if (n * sizeof(T) >= (std::size_t{1} << 21)) advise_huge_pages(p, n * sizeof(T));
    return p;
  }
};
template <class T, class U>
bool operator==(const HugePageAllocator<T>&, const HugePageAllocator<U>&) noexcept {
  return true;
}

// Capacity for n elements, whose pages (still untouched past the size) are advised for
// huge pages: for an array about to be filled, such as one that receives a message.
template <class Vector>
void reserve_huge(Vector& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(typename Vector::value_type));
}

// A vector whose large buffers are advised for huge pages (above).
template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace pdr
