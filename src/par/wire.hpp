// Wire: the byte layout of the parallel layer's messages. Every field is a trivially
// copyable value or a vector of them, written in the host's byte order (the ranks of a run
// are one binary on one kind of machine) with memcpy, no alignment assumed. A message
// shorter than its fields is a protocol error (std::logic_error): messages only come from
// the run's own ranks.
#pragma once

#include <cstddef>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "par/transport.hpp"

namespace pdr::par {

class WireWriter {
 public:
  template <class T>
  WireWriter& put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::byte*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
    return *this;
  }
  template <class T>
  WireWriter& put_vector(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    put<std::uint64_t>(v.size());
    const auto* p = reinterpret_cast<const std::byte*>(v.data());
    bytes_.insert(bytes_.end(), p, p + v.size() * sizeof(T));
    return *this;
  }
  Bytes take() { return std::move(bytes_); }

 private:
  Bytes bytes_;
};

class WireReader {
 public:
  explicit WireReader(std::span<const std::byte> b) : b_(b) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    if (b_.size() - pos_ < sizeof(T)) throw std::logic_error("wire: a message too short");
    T v;
    std::memcpy(&v, b_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  template <class T>
  std::vector<T> get_vector() {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto n = get<std::uint64_t>();
    if (n > (b_.size() - pos_) / sizeof(T)) throw std::logic_error("wire: a vector too long");
    std::vector<T> v(static_cast<std::size_t>(n));
    if (n > 0) std::memcpy(v.data(), b_.data() + pos_, v.size() * sizeof(T));
    pos_ += v.size() * sizeof(T);
    return v;
  }
  // A vector's bytes left where they are: its element count and where its elements start
  // (unaligned: read each with memcpy). The span must outlive what reads them.
  template <class T>
  std::pair<std::size_t, const std::byte*> get_vector_in_place() {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto n = get<std::uint64_t>();
    if (n > (b_.size() - pos_) / sizeof(T)) throw std::logic_error("wire: a vector too long");
    const std::byte* at = b_.data() + pos_;
    pos_ += static_cast<std::size_t>(n) * sizeof(T);
    return {static_cast<std::size_t>(n), at};
  }
  bool done() const { return pos_ == b_.size(); }

 private:
  std::span<const std::byte> b_;
  std::size_t pos_ = 0;
};

}  // namespace pdr::par
