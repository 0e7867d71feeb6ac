// DataArray decoding for the VTU reader; see vtu_arrays.hpp.
#include "io/vtu_arrays.hpp"

#include <cstring>
#include <limits>

#include "io/text_scanner.hpp"
#include "io/vtu_payload.hpp"

namespace pdr::io {

namespace {

struct TypeName {
  const char* name;
  VtkType type;
  std::size_t size;
};
constexpr TypeName kTypes[] = {
    {"Int8", VtkType::Int8, 1},       {"UInt8", VtkType::UInt8, 1},
    {"Int16", VtkType::Int16, 2},     {"UInt16", VtkType::UInt16, 2},
    {"Int32", VtkType::Int32, 4},     {"UInt32", VtkType::UInt32, 4},
    {"Int64", VtkType::Int64, 8},     {"UInt64", VtkType::UInt64, 8},
    {"Float32", VtkType::Float32, 4}, {"Float64", VtkType::Float64, 8},
};

std::string label(const DataArray& a) { return "DataArray '" + std::string(a.name) + "'"; }

template <class Src, class Out>
void convert_as(std::string_view bytes, std::vector<Out>& out, const char*& error) {
  const std::size_t n = bytes.size() / sizeof(Src);
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Src v;
    std::memcpy(&v, bytes.data() + i * sizeof(Src), sizeof(Src));
    if constexpr (std::is_same_v<Src, std::uint64_t> && std::is_integral_v<Out>) {
      if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        error = "holds an integer too large for an index";
        return;
      }
    }
    out[i] = static_cast<Out>(v);
  }
}

template <class Out>
void convert(VtkType t, std::string_view bytes, std::vector<Out>& out, const char*& error) {
  switch (t) {
    case VtkType::Int8: return convert_as<std::int8_t>(bytes, out, error);
    case VtkType::UInt8: return convert_as<std::uint8_t>(bytes, out, error);
    case VtkType::Int16: return convert_as<std::int16_t>(bytes, out, error);
    case VtkType::UInt16: return convert_as<std::uint16_t>(bytes, out, error);
    case VtkType::Int32: return convert_as<std::int32_t>(bytes, out, error);
    case VtkType::UInt32: return convert_as<std::uint32_t>(bytes, out, error);
    case VtkType::Int64: return convert_as<std::int64_t>(bytes, out, error);
    case VtkType::UInt64: return convert_as<std::uint64_t>(bytes, out, error);
    case VtkType::Float32: return convert_as<float>(bytes, out, error);
    case VtkType::Float64: return convert_as<double>(bytes, out, error);
    case VtkType::Unknown: break;
  }
  error = "has an unknown type";
}

template <class Out>
std::vector<Out> decode(const VtuContext& c, const DataArray& a, std::size_t count) {
  const XmlScanner& xml = *c.xml;
  if constexpr (std::is_integral_v<Out>) {
    if (vtk_is_float(a.type))
      xml.fail_at(a.tag_at, label(a) + " must have an integer type; export it as Int32/Int64");
  }
  std::vector<Out> out;
  if (a.format == DataArray::Format::Ascii) {
    const std::string_view text = xml.text();
    std::size_t p = a.content_begin;
    out.reserve(std::min(count, (a.content_end - a.content_begin) / 2 + 1));
    while (true) {
      while (p < a.content_end && (is_blank(text[p]) || text[p] == '\n')) ++p;
      if (p >= a.content_end) break;
      const std::size_t start = p;
      while (p < a.content_end && !is_blank(text[p]) && text[p] != '\n') ++p;
      const std::string_view tok = text.substr(start, p - start);
      Out v{};
      if (!parse_number(tok, v))
        xml.fail_at(start, label(a) + ": expected a number, found '" +
                               std::string(tok.substr(0, 40)) + "'");
      if (out.size() == count)
        xml.fail_at(start, label(a) + " has more than the " + std::to_string(count) +
                               " values expected; fix NumberOfPoints/NumberOfCells");
      out.push_back(v);
    }
    if (out.size() != count)
      xml.fail_at(a.tag_at, label(a) + " has " + std::to_string(out.size()) + " values, "
                            "expected " + std::to_string(count) + "; the data is truncated");
    return out;
  }
  const std::size_t size = vtk_size(a.type);
  if (count > xml.text().size() / size)
    xml.fail_at(a.tag_at, label(a) + " would need " + std::to_string(count) + " values, more "
                          "than the file can hold; a count is wrong");
  std::string storage;
  const std::string_view bytes = array_payload(c, a, count * size, storage);
  const char* error = nullptr;
  convert(a.type, bytes, out, error);
  if (error) xml.fail_at(a.tag_at, label(a) + " " + error);
  return out;
}

}  // namespace

VtkType vtk_type(std::string_view name) {
  for (const TypeName& t : kTypes)
    if (name == t.name) return t.type;
  return VtkType::Unknown;
}

std::size_t vtk_size(VtkType t) {
  for (const TypeName& n : kTypes)
    if (n.type == t) return n.size;
  return 1;
}

bool vtk_is_float(VtkType t) { return t == VtkType::Float32 || t == VtkType::Float64; }

DataArray describe_array(const XmlScanner& xml, const XmlTag& tag) {
  DataArray a;
  a.tag_at = tag.begin;
  a.name = tag.attr("Name");
  const std::string_view type = tag.attr("type");
  a.type = vtk_type(type);
  if (a.type == VtkType::Unknown)
    xml.fail_at(tag.begin, "DataArray type '" + std::string(type.substr(0, 40)) +
                               "' is not supported; use Int8..UInt64, Float32 or Float64");
  if (tag.has("NumberOfComponents") &&
      (!parse_number(tag.attr("NumberOfComponents"), a.components) || a.components == 0 ||
       a.components > 1024))
    xml.fail_at(tag.begin, "bad NumberOfComponents in DataArray '" + std::string(a.name) + "'");
  const std::string_view format = tag.attr("format", "ascii");
  if (format == "ascii") a.format = DataArray::Format::Ascii;
  else if (format == "binary") a.format = DataArray::Format::Binary;
  else if (format == "appended") a.format = DataArray::Format::Appended;
  else
    xml.fail_at(tag.begin, "DataArray format '" + std::string(format.substr(0, 40)) +
                               "' is not ascii, binary or appended");
  if (a.format == DataArray::Format::Appended && !parse_number(tag.attr("offset"), a.offset))
    xml.fail_at(tag.begin, "appended DataArray '" + std::string(a.name) +
                               "' lacks a valid offset attribute");
  return a;
}

std::vector<double> decode_doubles(const VtuContext& c, const DataArray& a, std::size_t count) {
  return decode<double>(c, a, count);
}

std::vector<std::int64_t> decode_ints(const VtuContext& c, const DataArray& a,
                                      std::size_t count) {
  return decode<std::int64_t>(c, a, count);
}

}  // namespace pdr::io
