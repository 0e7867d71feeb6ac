// Fuzz target: the mesh readers (io/mesh_io.hpp read_mesh) on arbitrary bytes: Gmsh .msh,
// medit .mesh, VTK .vtu, and TetGen's .node + .ele + .face triple. The first byte picks the
// format; the rest is the file, or for TetGen the three files separated by the byte 0x1e
// (ASCII record separator; a missing .face part is no .face file). A reader may only return
// a mesh or throw InputError: any other exception, a crash or a sanitizer report is a bug.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <string_view>

#include "fuzz_target.hpp"
#include "io/error.hpp"
#include "io/mesh_io.hpp"

namespace {

void write_file(const std::string& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string base = "/tmp/pdr-fuzz-mesh-" + std::to_string(::getpid());
  std::string_view rest(reinterpret_cast<const char*>(data + 1), size - 1);
  std::string path;
  std::vector<std::string> written;
  switch (data[0] % 4) {
    case 0: path = base + ".msh"; break;
    case 1: path = base + ".mesh"; break;
    case 2: path = base + ".vtu"; break;
    default: {
      static const char* const ext[] = {".node", ".ele", ".face"};
      for (int part = 0; part < 3; ++part) {
        const std::size_t cut = rest.find('\x1e');
        if (part == 2 && rest.empty()) break;
        write_file(base + ext[part], rest.substr(0, cut));
        written.push_back(base + ext[part]);
        rest = cut == std::string_view::npos ? std::string_view() : rest.substr(cut + 1);
      }
      path = base + ".ele";
    }
  }
  if (written.empty()) {
    write_file(path, rest);
    written.push_back(path);
  }
  try {
    (void)pdr::io::read_mesh(path);
  } catch (const pdr::InputError&) {
    // the expected answer to a malformed file
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_read_mesh: unexpected exception: %s\n", e.what());
    for (const std::string& f : written) std::remove(f.c_str());
    std::abort();
  }
  for (const std::string& f : written) std::remove(f.c_str());
  return 0;
}
