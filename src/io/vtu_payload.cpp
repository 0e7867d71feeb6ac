// The bytes of one binary or appended VTU DataArray; see vtu_payload.hpp.
#include "io/vtu_payload.hpp"

#include <cstring>
#include <optional>
#include <vector>

#include "io/base64.hpp"
#include "io/byte_reader.hpp"
#include "io/vtu_zlib.hpp"

namespace pdr::io {

namespace {

// Sequential reads from the array's encoded bytes, base64 or raw.
class PayloadReader {
 public:
  PayloadReader(const VtuContext& c, const DataArray& a) : xml_(*c.xml), a_(a) {
    const std::string_view text = xml_.text();
    if (a.format == DataArray::Format::Binary) {
      encoded_ = text.substr(a.content_begin, a.content_end - a.content_begin);
      decoder_ = Base64Decoder(encoded_);
      return;
    }
    if (c.appended_begin == std::string_view::npos)
      fail("says format=\"appended\" but the file has no <AppendedData>; the file is truncated");
    if (a.offset > text.size() - c.appended_begin)
      fail("offset " + std::to_string(a.offset) + " is beyond the end of the appended data; "
           "the file is truncated");
    const std::size_t start = c.appended_begin + static_cast<std::size_t>(a.offset);
    if (c.appended_raw) {
      raw_.emplace(text, start, xml_.file());
    } else {
      encoded_ = text.substr(start);
      decoder_ = Base64Decoder(encoded_);
    }
  }

  // Upper bound of the bytes left.
  std::size_t available() const { return raw_ ? raw_->left() : encoded_.size() / 4 * 3 + 3; }

  // The next n bytes: a view into the file (raw) or into `sink` (default: an internal
  // buffer valid until the next call).
  std::string_view take(std::size_t n, const char* what, std::string* sink = nullptr) {
    if (raw_) {
      if (n > raw_->left())
        raw_->fail(label() + ": truncated " + what + ": needs " + std::to_string(n) +
                   " bytes but only " + std::to_string(raw_->left()) + " are left");
      return raw_->bytes(n, what);
    }
    if (n > available()) fail(std::string("is truncated: its ") + what + " needs more data");
    std::string& out = sink ? *sink : buf_;
    out.clear();
    std::string err;
    if (!decoder_.read(n, out, err))
      fail(": " + err + " in its " + what + "; the data is truncated or corrupt");
    return out;
  }

  std::uint64_t take_uint(std::size_t width, const char* what) {
    const std::string_view b = take(width, what);
    if (width == 8) {
      std::uint64_t v;
      std::memcpy(&v, b.data(), 8);
      return v;
    }
    std::uint32_t v;
    std::memcpy(&v, b.data(), 4);
    return v;
  }

  [[noreturn]] void fail(const std::string& problem) const {
    const std::string msg = label() + (problem.rfind(":", 0) == 0 ? "" : " ") + problem;
    if (raw_) raw_->fail(msg);
    xml_.fail_at(a_.tag_at, msg);
  }

 private:
  std::string label() const { return "DataArray '" + std::string(a_.name) + "'"; }

  const XmlScanner& xml_;
  const DataArray& a_;
  std::optional<ByteReader> raw_;
  std::string_view encoded_;
  Base64Decoder decoder_{{}};
  std::string buf_;
};

}  // namespace

std::string_view array_payload(const VtuContext& c, const DataArray& a, std::size_t bytes,
                               std::string& storage) {
  PayloadReader r(c, a);
  const std::size_t hs = c.header64 ? 8 : 4;
  auto mismatch = [&](std::uint64_t n) {
    r.fail("holds " + std::to_string(n) + " bytes, expected " + std::to_string(bytes) +
           " for its values; NumberOfPoints/NumberOfCells or header_type do not match the "
           "data");
  };
  if (!c.zlib) {
    const std::uint64_t n = r.take_uint(hs, "header");
    if (n != bytes) mismatch(n);
    return r.take(bytes, "data", &storage);
  }
  const std::uint64_t nblocks = r.take_uint(hs, "compression header");
  const std::uint64_t block = r.take_uint(hs, "compression header");
  const std::uint64_t last = r.take_uint(hs, "compression header");
  if (nblocks > r.available() / hs)
    r.fail("has a compression header of " + std::to_string(nblocks) + " blocks, more than the "
           "file holds; the data is corrupt");
  // (nblocks - 1) * block must not wrap around: each block then fits in `bytes`.
  if (nblocks > 1 && (block == 0 || nblocks - 1 > bytes / block)) mismatch(nblocks * block);
  const std::uint64_t total =
      nblocks == 0 ? 0 : (nblocks - 1) * block + (last == 0 ? block : last);
  if (last > block || total != bytes) mismatch(total);
  std::vector<std::uint64_t> csize(static_cast<std::size_t>(nblocks));
  for (std::uint64_t& s : csize) s = r.take_uint(hs, "compression header");
  storage.assign(bytes, '\0');
  std::size_t at = 0;
  for (std::size_t b = 0; b < csize.size(); ++b) {
    const std::size_t size =
        static_cast<std::size_t>(b + 1 == csize.size() && last != 0 ? last : block);
    if (csize[b] > r.available())
      r.fail("block " + std::to_string(b) + " is larger than the data left; the file is "
             "truncated");
    const std::string_view in = r.take(static_cast<std::size_t>(csize[b]), "compressed block");
    if (!zlib_inflate(in, storage.data() + at, size))
      r.fail("block " + std::to_string(b) + " does not inflate to " + std::to_string(size) +
             " bytes; the data is corrupt");
    at += size;
  }
  return storage;
}

}  // namespace pdr::io
