// XmlScanner; see xml_lite.hpp.
#include "io/xml_lite.hpp"

#include <algorithm>

#include "io/error.hpp"

namespace pdr::io {

namespace {
bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }
bool is_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         c == '_' || c == '-' || c == '.' || c == ':';
}
}  // namespace

std::string_view XmlTag::attr(std::string_view key, std::string_view fallback) const {
  for (const auto& [k, v] : attributes)
    if (k == key) return v;
  return fallback;
}

bool XmlTag::has(std::string_view key) const {
  return std::any_of(attributes.begin(), attributes.end(),
                     [&](const auto& a) { return a.first == key; });
}

std::size_t XmlScanner::line_of(std::size_t offset) const {
  offset = std::min(offset, text_.size());
  return 1 + static_cast<std::size_t>(std::count(text_.begin(),
                                                 text_.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

void XmlScanner::fail_at(std::size_t offset, const std::string& problem) const {
  throw InputError(file_, line_of(offset), problem);
}

std::size_t XmlScanner::find_closing(std::string_view name, std::size_t from) const {
  std::size_t at = from;
  while ((at = text_.find("</", at)) != std::string_view::npos) {
    if (text_.substr(at + 2, name.size()) == name) {
      const std::size_t after = at + 2 + name.size();
      if (after < text_.size() && !is_name_char(text_[after])) return at;
    }
    at += 2;
  }
  return std::string_view::npos;
}

bool XmlScanner::next(XmlTag& tag) {
  for (;;) {
    const std::size_t lt = text_.find('<', pos_);
    if (lt == std::string_view::npos) {
      pos_ = text_.size();
      return false;
    }
    const std::string_view rest = text_.substr(lt);
    auto skip_to = [&](std::string_view close, const char* what) {
      const std::size_t e = text_.find(close, lt);
      if (e == std::string_view::npos)
        fail_at(lt, std::string("unterminated ") + what + "; the file is truncated");
      pos_ = e + close.size();
    };
    if (rest.substr(0, 4) == "<!--") { skip_to("-->", "comment"); continue; }
    if (rest.substr(0, 9) == "<![CDATA[") { skip_to("]]>", "CDATA section"); continue; }
    if (rest.substr(0, 2) == "<?") { skip_to("?>", "processing instruction"); continue; }
    if (rest.substr(0, 2) == "<!") { skip_to(">", "declaration"); continue; }

    tag = XmlTag{};
    tag.begin = lt;
    std::size_t p = lt + 1;
    if (p < text_.size() && text_[p] == '/') {
      tag.closing = true;
      ++p;
    }
    const std::size_t name_start = p;
    while (p < text_.size() && is_name_char(text_[p])) ++p;
    if (p == name_start) fail_at(lt, "malformed XML: '<' not followed by a tag name");
    tag.name = text_.substr(name_start, p - name_start);
    for (;;) {
      while (p < text_.size() && is_space(text_[p])) ++p;
      if (p >= text_.size()) fail_at(lt, "unterminated XML tag <" + std::string(tag.name) + ">");
      if (text_[p] == '>') { ++p; break; }
      if (text_[p] == '/' && p + 1 < text_.size() && text_[p + 1] == '>') {
        tag.self_closing = true;
        p += 2;
        break;
      }
      const std::size_t key_start = p;
      while (p < text_.size() && is_name_char(text_[p])) ++p;
      if (p == key_start || tag.closing)
        fail_at(p, "malformed XML in tag <" + std::string(tag.name) + ">");
      const std::string_view key = text_.substr(key_start, p - key_start);
      while (p < text_.size() && is_space(text_[p])) ++p;
      if (p >= text_.size() || text_[p] != '=')
        fail_at(p, "malformed XML: attribute " + std::string(key) + " has no value");
      ++p;
      while (p < text_.size() && is_space(text_[p])) ++p;
      if (p >= text_.size() || (text_[p] != '"' && text_[p] != '\''))
        fail_at(p, "malformed XML: attribute " + std::string(key) + " value is not quoted");
      const char quote = text_[p++];
      const std::size_t close = text_.find(quote, p);
      if (close == std::string_view::npos)
        fail_at(p, "malformed XML: unterminated value of attribute " + std::string(key));
      tag.attributes.emplace_back(key, text_.substr(p, close - p));
      p = close + 1;
    }
    tag.end = p;
    pos_ = p;
    return true;
  }
}

}  // namespace pdr::io
