// The `pdr` executable's operator new: as the standard library's (std::malloc, the new
// handler, std::bad_alloc), except that a block of at least 4 MiB is advised for huge
// pages (mesh/huge_pages.hpp) as soon as it is allocated, before the caller touches it
// (malloc may hand out heap memory that an earlier block already faulted in). Not in
// sanitizer builds, whose own operator new checks new/delete pairs. The
// kernel's own growing arrays are mappings of their own (mesh/growing_array.hpp); this reaches
// every other large array of a run, the checker's, the readers' and the writers' among
// them. Why: on a virtual machine where each page fault exits to the hypervisor, faulting
// in 4 KiB pages costs several times the work done on them (measured: about 11 us a
// fault; `pdr check` of 1.86M tets took 137K faults).
#include <cstdlib>
#include <new>

#include "mesh/huge_pages.hpp"

namespace {

constexpr std::size_t kLarge = std::size_t{4} << 20;

void* allocate(std::size_t n) {
  if (n == 0) n = 1;
  for (;;) {
    if (void* p = std::malloc(n)) {
      if (n >= kLarge) pdr::advise_huge_pages(p, n);
      return p;
    }
    const std::new_handler h = std::get_new_handler();
    if (h == nullptr) throw std::bad_alloc();
    h();
  }
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
