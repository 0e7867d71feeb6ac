// TextScanner: a line-and-token cursor over a text file held in memory, for the ASCII
// readers (TetGen, Gmsh, medit, and the text parts of binary Gmsh files).
//
// Conventions:
//   - Lines are numbered from 1 as an editor shows them; blank lines and lines holding only
//     a comment (from `comment` to the end of line; '\0' = no comments) are skipped.
//   - Tokens are separated by blanks (space, tab, CR, VT, FF); a CR before LF is a blank.
//   - Numbers are parsed with std::from_chars over the whole token (a leading '+' is
//     allowed); doubles must be finite. No heap allocation per token.
//   - Every failure throws InputError(file, line, problem) naming the current line, or the
//     given line. Counts read from headers are checked against the bytes left in the file
//     before anything is reserved, so a bogus count cannot cause a huge allocation.
// Invariant: pos_ <= line_end_ <= next_ <= text_.size() while a line is current.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include "io/error.hpp"

namespace pdr::io {

class TextScanner {
 public:
  TextScanner(std::string_view text, std::string file, char comment = '#');

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  // Byte offset of the first byte after the current line (after its '\n').
  std::size_t after_line() const { return next_; }
  std::size_t size() const { return text_.size(); }
  std::string_view text() const { return text_; }

  // Moves to the next line that holds a token. False at the end of the text.
  bool next_line();
  // Like next_line, but throws "unexpected end of file; <expecting>" at the end.
  void require_line(std::string_view expecting);
  // Continues scanning at byte `offset` (after a binary block), counting the lines skipped.
  void resume_at(std::size_t offset);

  // True when another token is left on the current line.
  bool has_token();
  // The next token of the current line; throws "missing <what>" when the line has none.
  std::string_view token(std::string_view what);
  // The next token of the current line or, when it has none, of the following lines.
  // Empty at the end of the text.
  std::string_view token_any();
  // The rest of the current line with blanks trimmed.
  std::string_view rest_of_line();

  // The next token as a number of type T (integer or double).
  template <class T>
  T number(std::string_view what);
  // A non-negative count of items, each needing at least `min_bytes` bytes in the file.
  std::size_t count(std::string_view what, std::size_t min_bytes);
  // Throws when tokens are left on the line ("unexpected '<tok>' after <what>").
  void end_line(std::string_view what);

  [[noreturn]] void fail(const std::string& problem) const { fail_at(line_, problem); }
  [[noreturn]] void fail_at(std::size_t line, const std::string& problem) const {
    throw InputError(file_, line, problem);
  }

 private:
  [[noreturn]] void bad_number(std::string_view what, std::string_view tok,
                               const char* kind) const;
  void skip_blanks();

  std::string_view text_;
  std::string file_;
  char comment_;
  std::size_t pos_ = 0;        // cursor inside the current line
  std::size_t line_end_ = 0;   // end of the current line's tokens (comment or newline)
  std::size_t next_ = 0;       // first byte of the next physical line
  std::size_t line_ = 0;       // number of the current line (0: none yet)
  std::size_t next_line_no_ = 1;  // number of the line starting at next_
};

// Parses all of `tok` as a T; false when it is not one (or not finite for doubles).
template <class T>
bool parse_number(std::string_view tok, T& out) {
  if (tok.size() > 1 && tok[0] == '+' && tok[1] != '-' && tok[1] != '+') tok.remove_prefix(1);
  const char* end = tok.data() + tok.size();
  auto [p, ec] = std::from_chars(tok.data(), end, out);
  if (ec != std::errc() || p != end) return false;
  if constexpr (std::is_floating_point_v<T>) {
    if (!(out - out == 0)) return false;  // inf or nan
  }
  return true;
}

inline bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

template <class T>
T TextScanner::number(std::string_view what) {
  const std::string_view tok = token(what);
  T value{};
  if (!parse_number(tok, value)) {
    if constexpr (std::is_floating_point_v<T>)
      bad_number(what, tok, "a finite real number");
    else if constexpr (std::is_signed_v<T>)
      bad_number(what, tok, "an integer");
    else
      bad_number(what, tok, "a non-negative integer");
  }
  return value;
}

}  // namespace pdr::io
