// DataArray decoding for the VTU reader (internal to pdr_io): VTK scalar types, the
// description of one <DataArray>, and decoding of its values from ASCII text, inline
// base64 or appended (base64 or raw) data into doubles or 64-bit integers, with the byte
// count in the header checked against the expected number of values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/xml_lite.hpp"

namespace pdr::io {

enum class VtkType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64,
                     Unknown };

VtkType vtk_type(std::string_view name);
std::size_t vtk_size(VtkType t);
bool vtk_is_float(VtkType t);

struct DataArray {
  std::string_view name;
  VtkType type = VtkType::Unknown;
  std::size_t components = 1;
  enum class Format { Ascii, Binary, Appended } format = Format::Ascii;
  std::uint64_t offset = 0;          // appended: offset in the appended block
  std::size_t tag_at = 0;            // offset of the <DataArray> tag, for diagnostics
  std::size_t content_begin = 0;     // inline: the text between the tags
  std::size_t content_end = 0;
};

// File-wide facts the decoding needs.
struct VtuContext {
  const XmlScanner* xml = nullptr;
  bool header64 = false;                        // header_type="UInt64"
  std::size_t appended_begin = std::string_view::npos;  // first byte after the '_'
  bool appended_raw = true;
  bool zlib = false;                            // compressor="vtkZLibDataCompressor"
};

// Reads the DataArray tag's attributes; content offsets are filled by the caller.
DataArray describe_array(const XmlScanner& xml, const XmlTag& tag);

// The values of `a`, which must hold exactly `count` values (tuples x components).
std::vector<double> decode_doubles(const VtuContext& c, const DataArray& a, std::size_t count);
std::vector<std::int64_t> decode_ints(const VtuContext& c, const DataArray& a, std::size_t count);

}  // namespace pdr::io
