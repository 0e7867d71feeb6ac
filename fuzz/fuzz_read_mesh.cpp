// Fuzz target: the readers (io/mesh_io.hpp) on arbitrary bytes. The first byte picks the
// format; the rest is the file. A reader may only return a mesh or throw InputError: any
// other exception, a crash or a sanitizer report is a bug.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>

#include "fuzz_target.hpp"
#include "io/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const ext[] = {".msh", ".mesh", ".vtu", ".node", ".poly", ".smesh"};
  const int kind = data[0] % 6;
  const std::string path = "/tmp/pdr-fuzz-" + std::to_string(::getpid()) + ext[kind];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    if (kind <= 2)
      (void)pdr::io::read_mesh(path);
    else
      (void)pdr::io::read_domain(path);
  } catch (const pdr::InputError&) {
    // the expected answer to a malformed file
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_read_mesh: unexpected exception: %s\n", e.what());
    std::remove(path.c_str());
    std::abort();
  }
  std::remove(path.c_str());
  return 0;
}
