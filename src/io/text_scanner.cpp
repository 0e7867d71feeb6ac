// TextScanner; see text_scanner.hpp for the conventions.
#include "io/text_scanner.hpp"

#include <algorithm>
#include <cstring>

namespace pdr::io {

TextScanner::TextScanner(std::string_view text, std::string file, char comment)
    : text_(text), file_(std::move(file)), comment_(comment) {}

bool TextScanner::next_line() {
  while (next_ < text_.size()) {
    const std::size_t start = next_;
    const char* nl = static_cast<const char*>(
        std::memchr(text_.data() + start, '\n', text_.size() - start));
    const std::size_t end = nl ? static_cast<std::size_t>(nl - text_.data()) : text_.size();
    line_ = next_line_no_++;
    next_ = nl ? end + 1 : end;
    std::size_t stop = end;
    if (comment_ != '\0') {
      const char* c = static_cast<const char*>(
          std::memchr(text_.data() + start, comment_, end - start));
      if (c) stop = static_cast<std::size_t>(c - text_.data());
    }
    pos_ = start;
    line_end_ = stop;
    skip_blanks();
    if (pos_ < line_end_) return true;
  }
  pos_ = line_end_ = next_;
  return false;
}

void TextScanner::require_line(std::string_view expecting) {
  if (!next_line())
    fail("unexpected end of file while expecting " + std::string(expecting) +
         "; the file is truncated or a count in it is too large");
}

void TextScanner::resume_at(std::size_t offset) {
  offset = std::min(offset, text_.size());
  if (offset > next_) {
    next_line_no_ += static_cast<std::size_t>(
        std::count(text_.begin() + static_cast<std::ptrdiff_t>(next_),
                   text_.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
  }
  next_ = offset;
  pos_ = line_end_ = offset;
}

void TextScanner::skip_blanks() {
  while (pos_ < line_end_ && is_blank(text_[pos_])) ++pos_;
}

bool TextScanner::has_token() {
  skip_blanks();
  return pos_ < line_end_;
}

std::string_view TextScanner::token(std::string_view what) {
  skip_blanks();
  if (pos_ >= line_end_)
    fail("missing " + std::string(what) + " at the end of the line; complete the line");
  const std::size_t start = pos_;
  while (pos_ < line_end_ && !is_blank(text_[pos_])) ++pos_;
  return text_.substr(start, pos_ - start);
}

std::string_view TextScanner::token_any() {
  if (!has_token() && !next_line()) return {};
  return token("token");
}

std::string_view TextScanner::rest_of_line() {
  skip_blanks();
  std::size_t end = line_end_;
  while (end > pos_ && is_blank(text_[end - 1])) --end;
  const std::string_view rest = text_.substr(pos_, end - pos_);
  pos_ = line_end_;
  return rest;
}

std::size_t TextScanner::count(std::string_view what, std::size_t min_bytes) {
  const std::string_view tok = token(what);
  std::uint64_t n = 0;
  if (!parse_number(tok, n)) bad_number(what, tok, "a non-negative integer");
  const std::size_t left = text_.size() - std::min(pos_, text_.size());
  if (min_bytes > 0 && n > left / min_bytes)
    fail(std::string(what) + " " + std::to_string(n) + " is more than the " +
         std::to_string(left) + " bytes left in the file can hold; the count is wrong or " +
         "the file is truncated");
  return static_cast<std::size_t>(n);
}

void TextScanner::end_line(std::string_view what) {
  if (!has_token()) return;
  const std::string_view extra = token("token");
  fail("unexpected '" + std::string(extra) + "' after " + std::string(what) +
       "; remove it or fix the count in the header");
}

void TextScanner::bad_number(std::string_view what, std::string_view tok,
                             const char* kind) const {
  std::string shown(tok.substr(0, 40));
  if (tok.size() > 40) shown += "...";
  fail("expected " + std::string(kind) + " for " + std::string(what) + ", found '" + shown +
       "'; fix the number");
}

}  // namespace pdr::io
