// zlib inflation for compressed VTU data; see vtu_zlib.hpp.
#include "io/vtu_zlib.hpp"

#include <limits>

#if PDR_HAVE_ZLIB
#include <zlib.h>
#endif

namespace pdr::io {

#if PDR_HAVE_ZLIB

bool have_zlib() { return true; }

bool zlib_inflate(std::string_view in, char* out, std::size_t size) {
  if (in.size() > std::numeric_limits<uLong>::max() || size > std::numeric_limits<uLongf>::max())
    return false;
  uLongf out_len = static_cast<uLongf>(size);
  const int rc = ::uncompress(reinterpret_cast<Bytef*>(out), &out_len,
                              reinterpret_cast<const Bytef*>(in.data()),
                              static_cast<uLong>(in.size()));
  return rc == Z_OK && out_len == size;
}

#else

bool have_zlib() { return false; }

bool zlib_inflate(std::string_view, char*, std::size_t) { return false; }

#endif

}  // namespace pdr::io
