// GrowingArray<T>: a contiguous array of trivially copyable T for the arrays that grow
// with the mesh (the tet store's records, a submesh's per-slot records, the parallel
// phase's queue). It keeps std::vector's contract for the operations it has (size,
// capacity, resize with value-initialized elements, push_back, erase of a prefix), but a
// large buffer grows without copying: it is an anonymous mapping, advised for huge pages
// and 2 MiB aligned, that grows by mremap, which moves page tables and leaves the pages
// where they are. std::vector copies a growing buffer into a fresh one and frees the old:
// every element is written twice, and on a virtual machine whose fresh pages cost a
// hypervisor fault each (measured: about 1.5 ms per 2 MiB page), the copies' pages cost
// about as much as the array's own. Here a page is faulted in once, when the array first
// reaches it.
//
// Small buffers (below kMapBytes) come from malloc and grow by realloc. Elements are
// always value-initialized when resize() adds them (T{}, not zero bytes), so the choice of
// buffer is invisible to the caller. Where mremap is not available (not Linux), and in
// AddressSanitizer builds, every buffer comes from malloc.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "mesh/huge_pages.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pdr {

namespace growing_array_detail {

inline constexpr std::size_t kHugePage = std::size_t{1} << 21;
// At least this many bytes: a mapping.
inline constexpr std::size_t kMapBytes = std::size_t{1} << 21;

inline std::size_t round_to_huge(std::size_t bytes) {
  return (bytes + kHugePage - 1) & ~(kHugePage - 1);
}

// AddressSanitizer sees no overflow of a mapping: its builds keep every buffer on malloc.
#if defined(__SANITIZE_ADDRESS__)
#define PDR_GROWING_ARRAY_MALLOC_ONLY 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PDR_GROWING_ARRAY_MALLOC_ONLY 1
#endif
#endif

#if defined(__linux__) && defined(MREMAP_MAYMOVE) && defined(MREMAP_FIXED) && \
    !defined(PDR_GROWING_ARRAY_MALLOC_ONLY)
inline constexpr bool kCanMap = true;

// A reservation of `bytes` (a multiple of 2 MiB) at a 2 MiB-aligned address, no access.
inline void* reserve_aligned(std::size_t bytes) {
  void* raw = ::mmap(nullptr, bytes + kHugePage, PROT_NONE,
                     MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto begin = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (begin + kHugePage - 1) & ~(kHugePage - 1);
  if (aligned > begin) ::munmap(raw, aligned - begin);
  const std::uintptr_t end = begin + bytes + kHugePage;
  if (end > aligned + bytes) ::munmap(reinterpret_cast<void*>(aligned + bytes), end - aligned - bytes);
  return reinterpret_cast<void*>(aligned);
}

// A fresh readable, writable mapping of `bytes` (a multiple of 2 MiB), 2 MiB aligned.
inline void* map(std::size_t bytes) {
  void* p = reserve_aligned(bytes);
  if (::mprotect(p, bytes, PROT_READ | PROT_WRITE) != 0) {
    ::munmap(p, bytes);
    throw std::bad_alloc();
  }
  advise_huge_pages(p, bytes);
  return p;
}

// The mapping p of `old_bytes` grown to `new_bytes` (multiples of 2 MiB) at a 2 MiB-aligned
// address, its pages moved, not copied.
inline void* remap(void* p, std::size_t old_bytes, std::size_t new_bytes) {
  void* target = reserve_aligned(new_bytes);
  void* q = ::mremap(p, old_bytes, new_bytes, MREMAP_MAYMOVE | MREMAP_FIXED, target);
  if (q == MAP_FAILED) {
    ::munmap(target, new_bytes);
    throw std::bad_alloc();
  }
  return q;
}

inline void unmap(void* p, std::size_t bytes) { ::munmap(p, bytes); }
#else
inline constexpr bool kCanMap = false;
inline void* map(std::size_t) { throw std::bad_alloc(); }
inline void* remap(void*, std::size_t, std::size_t) { throw std::bad_alloc(); }
inline void unmap(void*, std::size_t) {}
#endif

}  // namespace growing_array_detail

template <class T>
class GrowingArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "GrowingArray holds trivially copyable values only");

 public:
  using value_type = T;
  using size_type = std::size_t;
  using iterator = T*;
  using const_iterator = const T*;

  GrowingArray() = default;
  explicit GrowingArray(std::size_t n) { resize(n); }
  GrowingArray(std::size_t n, const T& value) { resize(n, value); }
  GrowingArray(const GrowingArray& o) { append(o.data_, o.size_); }
  GrowingArray(GrowingArray&& o) noexcept
      : data_(std::exchange(o.data_, nullptr)),
        size_(std::exchange(o.size_, 0)),
        capacity_(std::exchange(o.capacity_, 0)),
        mapped_bytes_(std::exchange(o.mapped_bytes_, 0)) {}
  GrowingArray& operator=(const GrowingArray& o) {
    if (this != &o) {
      size_ = 0;
      append(o.data_, o.size_);
    }
    return *this;
  }
  GrowingArray& operator=(GrowingArray&& o) noexcept {
    GrowingArray taken(std::move(o));  // o is left empty, this one's buffer freed below
    std::swap(data_, taken.data_);
    std::swap(size_, taken.size_);
    std::swap(capacity_, taken.capacity_);
    std::swap(mapped_bytes_, taken.mapped_bytes_);
    return *this;
  }
  ~GrowingArray() { release(); }

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T& at(std::size_t i) { return data_[checked(i)]; }
  const T& at(std::size_t i) const { return data_[checked(i)]; }
  T& back() { return data_[size_ - 1]; }
  const T& back() const { return data_[size_ - 1]; }

  void reserve(std::size_t n) {
    if (n > capacity_) grow_to(n);
  }
  // New elements are T{} (or `value`).
  void resize(std::size_t n) { resize(n, T{}); }
  void resize(std::size_t n, const T& value) {
    if (n > capacity_) grow_to(std::max(n, 2 * capacity_));
    if (n > size_) std::fill(data_ + size_, data_ + n, value);
    size_ = n;
  }
  void assign(std::size_t n, const T& value) {
    size_ = 0;
    resize(n, value);
  }
  void push_back(const T& value) {
    if (size_ == capacity_) {
      const T copy = value;  // `value` may be an element, about to move
      grow_to(std::max<std::size_t>(2 * capacity_, 16));
      data_[size_++] = copy;
      return;
    }
    data_[size_++] = value;
  }
  void clear() { size_ = 0; }
  // Removes [first, last), keeping the order of what follows (as std::vector::erase).
  T* erase(T* first, T* last) {
    if (first != last) {
      std::memmove(static_cast<void*>(first), last,
                   static_cast<std::size_t>(end() - last) * sizeof(T));
      size_ -= static_cast<std::size_t>(last - first);
    }
    return first;
  }

 private:
  std::size_t checked(std::size_t i) const {
    if (i >= size_) throw std::out_of_range("GrowingArray::at");
    return i;
  }
  void append(const T* p, std::size_t n) {
    reserve(size_ + n);
    if (n != 0) std::memcpy(static_cast<void*>(data_ + size_), p, n * sizeof(T));
    size_ += n;
  }
  // Capacity for at least n elements; the contents are kept.
  void grow_to(std::size_t n) {
    namespace d = growing_array_detail;
    if (n > (~std::size_t{0} - d::kHugePage) / sizeof(T)) throw std::bad_alloc();
    const std::size_t bytes = n * sizeof(T);
    if (d::kCanMap && bytes >= d::kMapBytes) {
      const std::size_t mapped_bytes = d::round_to_huge(bytes);
      void* p = nullptr;
      if (mapped_bytes_ != 0) {
        p = d::remap(data_, mapped_bytes_, mapped_bytes);
      } else {
        p = d::map(mapped_bytes);
        if (size_ != 0) std::memcpy(p, static_cast<const void*>(data_), size_ * sizeof(T));
        std::free(data_);
      }
      data_ = static_cast<T*>(p);
      capacity_ = mapped_bytes / sizeof(T);
      mapped_bytes_ = mapped_bytes;
      return;
    }
    void* p = std::realloc(static_cast<void*>(data_), bytes);
    if (p == nullptr) throw std::bad_alloc();
    data_ = static_cast<T*>(p);
    capacity_ = n;
  }
  void release() {
    if (mapped_bytes_ != 0)
      growing_array_detail::unmap(data_, mapped_bytes_);
    else
      std::free(data_);
    data_ = nullptr;
    size_ = capacity_ = mapped_bytes_ = 0;
  }

  T* data_ = nullptr;
  std::size_t size_ = 0, capacity_ = 0;
  std::size_t mapped_bytes_ = 0;  // not 0: data_ is a mapping of that many bytes
};

}  // namespace pdr
