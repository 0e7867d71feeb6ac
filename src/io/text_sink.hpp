// TextSink: buffered formatting into an AtomicFile for the writers, into a function that
// takes the text in pieces, or into memory (parts of a file that several processes write:
// par/rank_files.hpp). Numbers are formatted with std::to_chars: integers exactly, doubles
// in the shortest form that reads back to the same bits (so a write/read round trip is
// bit-exact). The buffer is handed to the file or the function in chunks of about 1 MiB;
// flush() must be called at the end (before the file is committed).
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "io/atomic_file.hpp"

namespace pdr::io {

class TextSink {
 public:
  explicit TextSink(AtomicFile& file) : file_(&file), limit_(kChunk) { buf_.reserve(kChunk + 256); }
  // Into `out`, piece by piece, in order.
  explicit TextSink(std::function<void(std::string_view)> out)
      : out_(std::move(out)), limit_(kChunk) {
    if (!out_) throw std::invalid_argument("TextSink: no function to take the text");
    buf_.reserve(kChunk + 256);
  }
  // Into memory: everything stays in text() (flush() does nothing).
  TextSink() = default;
  std::string& text() { return buf_; }

  TextSink& put(std::string_view s) {
    buf_.append(s);
    maybe_flush();
    return *this;
  }
  TextSink& put(char c) {
    buf_.push_back(c);
    maybe_flush();
    return *this;
  }
  TextSink& put_int(std::int64_t v) { return put_number(v); }
  TextSink& put_uint(std::uint64_t v) { return put_number(v); }
  TextSink& put_double(double v) { return put_number(v); }
  // Raw bytes of a trivially copyable value or array (binary formats).
  TextSink& put_bytes(const void* data, std::size_t n) {
    buf_.append(static_cast<const char*>(data), n);
    maybe_flush();
    return *this;
  }

  void flush() {
    if (file_ != nullptr)
      file_->write(buf_);
    else if (out_)
      out_(buf_);
    else
      return;
    buf_.clear();
  }

 private:
  static constexpr std::size_t kChunk = std::size_t{1} << 20;

  template <class T>
  TextSink& put_number(T v) {
    char tmp[32];
    const auto res = std::to_chars(tmp, tmp + sizeof tmp, v);
    buf_.append(tmp, static_cast<std::size_t>(res.ptr - tmp));
    maybe_flush();
    return *this;
  }
  void maybe_flush() {
    if (buf_.size() >= limit_) flush();
  }

  AtomicFile* file_ = nullptr;
  std::function<void(std::string_view)> out_;
  std::size_t limit_ = static_cast<std::size_t>(-1);  // flush from this size on: never in memory
  std::string buf_;
};

}  // namespace pdr::io
