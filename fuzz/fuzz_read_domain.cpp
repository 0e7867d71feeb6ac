// Fuzz target: the domain readers (io/mesh_io.hpp read_domain: TetGen .poly, .smesh and
// .node point sets, and the closed surfaces of io/surface.hpp: .off, .stl, .ply, .obj, medit
// .mesh, Gmsh .msh, with their coplanar merge) and the domain analysis behind `pdr mesh` (domain/analysis.hpp: the
// PLC's validation, admissibility and d) on arbitrary bytes. The first byte picks the
// format; the rest is the file. Reading may only return a PLC or throw InputError, and so
// may the analysis: any other exception, a crash or a sanitizer report is a bug.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>

#include "domain/analysis.hpp"
#include "fuzz_target.hpp"
#include "io/error.hpp"
#include "io/mesh_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const ext[] = {".poly", ".smesh", ".node", ".off", ".stl",
                                    ".ply",  ".mesh",  ".msh",  ".obj"};
  const std::size_t format = data[0] % std::size(ext);
  const std::string path = "/tmp/pdr-fuzz-domain-" + std::to_string(::getpid()) + ext[format];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    const pdr::Plc plc = pdr::io::read_domain(path);
    if (format != 2) (void)pdr::domain::analyze(plc);
  } catch (const pdr::InputError&) {
    // the expected answer to a malformed or invalid domain
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_read_domain: unexpected exception: %s\n", e.what());
    std::remove(path.c_str());
    std::abort();
  }
  std::remove(path.c_str());
  return 0;
}
