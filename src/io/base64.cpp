// Base64 encoding and tolerant decoding; see base64.hpp.
#include "io/base64.hpp"

#include <array>

namespace pdr::io {

namespace {

constexpr char kAlphabet[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

constexpr std::array<signed char, 256> make_table() {
  std::array<signed char, 256> t{};
  for (auto& v : t) v = -1;
  for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(kAlphabet[i])] = static_cast<signed char>(i);
  return t;
}
constexpr std::array<signed char, 256> kTable = make_table();

bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }

}  // namespace

void base64_encode(std::string_view bytes, std::string& out) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size();
  const std::size_t start = out.size();
  out.resize(start + base64_length(n));
  char* o = out.data() + start;
  std::size_t i = 0;
  for (; i + 3 <= n; i += 3) {
    const unsigned v = (p[i] << 16) | (p[i + 1] << 8) | p[i + 2];
    *o++ = kAlphabet[(v >> 18) & 63];
    *o++ = kAlphabet[(v >> 12) & 63];
    *o++ = kAlphabet[(v >> 6) & 63];
    *o++ = kAlphabet[v & 63];
  }
  if (i < n) {
    const unsigned v = (p[i] << 16) | (i + 1 < n ? p[i + 1] << 8 : 0);
    *o++ = kAlphabet[(v >> 18) & 63];
    *o++ = kAlphabet[(v >> 12) & 63];
    *o++ = i + 1 < n ? kAlphabet[(v >> 6) & 63] : '=';
    *o++ = '=';
  }
}

bool Base64Decoder::decode_quantum(std::string& error) {
  int vals[4];
  int got = 0, pads = 0;
  while (got < 4) {
    while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
    if (pos_ >= text_.size()) {
      error = got == 0 ? "base64 data ends early" : "base64 data ends inside a 4-character group";
      return false;
    }
    const char c = text_[pos_];
    if (c == '=' && got >= 2) {
      vals[got++] = 0;
      ++pads;
    } else {
      const int v = kTable[static_cast<unsigned char>(c)];
      if (v < 0 || pads > 0) {
        error = std::string("invalid base64 character '") + c + "'";
        return false;
      }
      vals[got++] = v;
    }
    ++pos_;
  }
  const unsigned v = (vals[0] << 18) | (vals[1] << 12) | (vals[2] << 6) | vals[3];
  pending_[0] = static_cast<unsigned char>(v >> 16);
  pending_[1] = static_cast<unsigned char>(v >> 8);
  pending_[2] = static_cast<unsigned char>(v);
  npending_ = 3 - static_cast<std::size_t>(pads);
  pending_at_ = 0;
  return true;
}

bool Base64Decoder::read(std::size_t n, std::string& out, std::string& error) {
  out.reserve(out.size() + n);
  while (n > 0) {
    if (pending_at_ == npending_ && !decode_quantum(error)) return false;
    while (n > 0 && pending_at_ < npending_) {
      out.push_back(static_cast<char>(pending_[pending_at_++]));
      --n;
    }
  }
  return true;
}

}  // namespace pdr::io
