// The bytes of one binary or appended VTU DataArray (internal to pdr_io).
//
// Uncompressed, an array is a byte-count header (UInt32 or UInt64, per header_type) followed
// by the data. Compressed with zlib, the header is [#blocks, block size, size of the last
// block (0: full), compressed size of each block] and the compressed blocks follow. Inline
// ("binary") arrays are base64 text between the tags; appended arrays start at their offset
// after the '_' of <AppendedData>, as base64 or raw bytes. The header and the data may be
// one base64 stream or two (the decoder accepts both).
//
// Errors name the DataArray; in base64 text they carry the line of its tag, in raw appended
// data the byte offset.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "io/vtu_arrays.hpp"

namespace pdr::io {

// The payload of `a`, which must be exactly `bytes` long. The view points into the file
// (raw, uncompressed) or into `storage`.
std::string_view array_payload(const VtuContext& c, const DataArray& a, std::size_t bytes,
                               std::string& storage);

}  // namespace pdr::io
