// zlib inflation for compressed VTU data (compressor="vtkZLibDataCompressor"), available
// when pdr_io was built with zlib (CMake found it; PDR_HAVE_ZLIB). Without it the VTU reader
// rejects compressed files with advice to re-export them uncompressed.
#pragma once

#include <cstddef>
#include <string_view>

namespace pdr::io {

bool have_zlib();

// Inflates the zlib stream `in` into exactly `size` bytes at `out`. False when the stream
// is corrupt or does not hold exactly `size` bytes.
bool zlib_inflate(std::string_view in, char* out, std::size_t size);

}  // namespace pdr::io
