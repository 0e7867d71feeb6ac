// Base64 (RFC 4648, standard alphabet) for VTK XML binary data.
//
// Encoding is plain: 3 bytes -> 4 characters, '=' padding at the end.
// Decoding is tolerant of what VTK writers produce: whitespace anywhere is skipped, and a
// padded quantum may be followed by more data (VTK encodes a header and its data either as
// one stream or as two streams, each padded), so the decoder treats '=' as the end of a
// quantum, not of the text.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pdr::io {

// Appends the base64 encoding of `bytes` to `out`.
void base64_encode(std::string_view bytes, std::string& out);

// Length of the encoding of n bytes.
constexpr std::size_t base64_length(std::size_t n) { return (n + 2) / 3 * 4; }

class Base64Decoder {
 public:
  explicit Base64Decoder(std::string_view text) : text_(text) {}
  // Appends the next `n` decoded bytes to `out`. False (with `error` set) when the text
  // ends first or holds a character outside the alphabet.
  bool read(std::size_t n, std::string& out, std::string& error);
  // Characters consumed so far (for error offsets).
  std::size_t position() const { return pos_; }

 private:
  bool decode_quantum(std::string& error);

  std::string_view text_;
  std::size_t pos_ = 0;
  unsigned char pending_[3] = {0, 0, 0};
  std::size_t npending_ = 0, pending_at_ = 0;
};

}  // namespace pdr::io
