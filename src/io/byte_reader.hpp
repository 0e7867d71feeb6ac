// ByteReader: a bounds-checked cursor over binary data inside a file held in memory (Gmsh
// binary sections, VTK raw appended data, binary STL and PLY). Values are read with memcpy
// (no aliasing, no alignment assumptions), in the host's byte order (`get`: Gmsh and VTK
// files, whose readers check the file's byte-order marker first and reject a foreign order)
// or in a byte order the format fixes (`get_in`: STL is little-endian, PLY says which).
//
// Errors are InputError(file, 0, "at byte offset N: problem; what to do"): a line number
// makes no sense inside binary data, the absolute byte offset does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <bit>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

#include "io/error.hpp"

namespace pdr::io {

class ByteReader {
 public:
  // `data` is the whole file; reading starts at byte `offset`.
  ByteReader(std::string_view data, std::size_t offset, std::string file)
      : data_(data), pos_(offset), file_(std::move(file)) {}

  std::size_t offset() const { return pos_; }
  std::size_t left() const { return pos_ < data_.size() ? data_.size() - pos_ : 0; }

  template <class T>
  T get(std::string_view what) {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }

  // A value stored in byte order `order`.
  template <class T>
  T get_in(std::endian order, std::string_view what) {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T), what);
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, data_.data() + pos_, sizeof(T));
    if (order != std::endian::native) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }

  // An unsigned integer of `width` bytes (4 or 8), e.g. Gmsh's size_t of the data-size.
  std::uint64_t get_uint(std::size_t width, std::string_view what) {
    if (width == 4) return get<std::uint32_t>(what);
    return get<std::uint64_t>(what);
  }

  // Checks that `n` items of `item_bytes` each fit in the rest of the data.
  void need_items(std::uint64_t n, std::size_t item_bytes, std::string_view what) const {
    if (item_bytes != 0 && n > left() / item_bytes)
      fail(std::string(what) + " needs " + std::to_string(n) + " x " +
           std::to_string(item_bytes) + " bytes but only " + std::to_string(left()) +
           " are left; the count is wrong or the file is truncated");
  }

  void need(std::size_t bytes, std::string_view what) const {
    if (bytes > left())
      fail("truncated data: " + std::string(what) + " needs " + std::to_string(bytes) +
           " bytes but only " + std::to_string(left()) +
           " are left; the file is truncated, re-export it");
  }

  void skip(std::size_t bytes, std::string_view what) {
    need(bytes, what);
    pos_ += bytes;
  }

  // The next `n` bytes as a view, advancing past them.
  std::string_view bytes(std::size_t n, std::string_view what) {
    need(n, what);
    const std::string_view v = data_.substr(pos_, n);
    pos_ += n;
    return v;
  }

  [[noreturn]] void fail(const std::string& problem) const { fail_at(pos_, problem); }
  [[noreturn]] void fail_at(std::size_t offset, const std::string& problem) const {
    throw InputError(file_, 0, "at byte offset " + std::to_string(offset) + ": " + problem);
  }

 private:
  std::string_view data_;
  std::size_t pos_;
  std::string file_;
};

}  // namespace pdr::io
