// XmlScanner: the small subset of XML that VTK's XML files use, scanned in place.
// It yields start, end and empty-element tags with their attributes; it skips text, the
// XML declaration, processing instructions, comments, CDATA and DOCTYPE. Attribute values
// are returned raw (no entity decoding: VTK's names and keywords need none).
// Errors are InputError(file, line, ...) with the line computed from the byte offset.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pdr::io {

struct XmlTag {
  std::string_view name;
  bool closing = false;       // </name>
  bool self_closing = false;  // <name ... />
  std::vector<std::pair<std::string_view, std::string_view>> attributes;
  std::size_t begin = 0;      // offset of '<'
  std::size_t end = 0;        // offset just after '>'

  // The value of attribute `key`, or `fallback` when absent.
  std::string_view attr(std::string_view key, std::string_view fallback = {}) const;
  bool has(std::string_view key) const;
};

class XmlScanner {
 public:
  XmlScanner(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  // The next tag at or after the cursor. False at the end of the text.
  bool next(XmlTag& tag);
  // Moves the cursor to `offset`.
  void seek(std::size_t offset) { pos_ = offset; }
  std::size_t position() const { return pos_; }
  // Offset of the next "</name" at or after `from`; npos when none.
  std::size_t find_closing(std::string_view name, std::size_t from) const;

  std::size_t line_of(std::size_t offset) const;
  [[noreturn]] void fail_at(std::size_t offset, const std::string& problem) const;
  const std::string& file() const { return file_; }
  std::string_view text() const { return text_; }

 private:
  std::string_view text_;
  std::string file_;
  std::size_t pos_ = 0;
};

}  // namespace pdr::io
