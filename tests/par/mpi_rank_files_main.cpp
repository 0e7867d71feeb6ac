// write_in_rank_order (par/rank_files.hpp) under mpirun, in the directory argv[1]:
//   - two files, each the ranks' parts in rank order (rank 1's part of the second one
//     empty, rank 0's of the first one empty); rank 0 reads them back byte for byte and
//     finds no temporary left beside them;
//   - the same files again over the first ones (replaced whole), then again with each
//     rank's parts made as they are written, line by line (StreamedPart);
//   - files in a directory that does not exist: rank 0 throws std::system_error, the
//     others return false, and nothing is left behind.
// Exit 0 on success; a failing check aborts the job.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "par/mpi_collect.hpp"
#include "par/mpi_transport.hpp"
#include "par/rank_files.hpp"

namespace {

using pdr::par::MpiSession;

std::string part(int rank, int file, int round) {
  if ((file == 0 && rank == 0) || (file == 1 && rank == 1)) return {};
  std::string s;
  for (int i = 0; i <= rank + round; ++i)
    s += "file " + std::to_string(file) + " rank " + std::to_string(rank) + " line " +
         std::to_string(i) + "\n";
  return s;
}

void fail(const std::string& what) {
  std::fprintf(stderr, "mpi_rank_files: %s\n", what.c_str());
  MpiSession::abort(1);
}

}  // namespace

int main(int argc, char** argv) {
  MpiSession session(&argc, &argv);
  if (argc < 2) fail("usage: mpi_rank_files DIR");
  const std::filesystem::path dir = argv[1];
  const int rank = session.rank(), ranks = session.size();
  if (rank == 0) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  pdr::par::broadcast_from_root(0);  // the directory exists before anyone writes
  const std::vector<std::string> paths{(dir / "a.txt").string(), (dir / "b.txt").string()};
  for (int round = 0; round < 3; ++round) {
    const std::vector<std::string> texts{part(rank, 0, round), part(rank, 1, round)};
    std::vector<pdr::par::StreamedPart> streamed;
    for (const std::string& t : texts)
      streamed.push_back({t.size(), [&t](const std::function<void(std::string_view)>& put) {
                            for (std::size_t at = 0; at < t.size();) {  // a piece a line
                              const std::size_t end = t.find('\n', at) + 1;
                              put(std::string_view(t).substr(at, end - at));
                              at = end;
                            }
                          }});
    if (!(round < 2 ? pdr::par::write_in_rank_order(paths, texts)
                    : pdr::par::write_in_rank_order(paths, streamed)))
      fail("rank " + std::to_string(rank) + ": round " + std::to_string(round) + " not written");
    if (rank != 0) continue;
    for (int file = 0; file < 2; ++file) {
      std::string want;
      for (int r = 0; r < ranks; ++r) want += part(r, file, round);
      std::ifstream in(paths[static_cast<std::size_t>(file)], std::ios::binary);
      const std::string got(std::istreambuf_iterator<char>(in), {});
      if (got != want) fail("round " + std::to_string(round) + ": " + paths[static_cast<std::size_t>(file)] +
                            " holds\n" + got + "instead of\n" + want);
    }
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
    if (entries != 2) fail(std::to_string(entries) + " entries in " + dir.string() + ", expected 2");
  }
  const std::vector<std::string> nowhere{(dir / "missing" / "c.txt").string()};
  bool thrown = false, written = true;
  try {
    written = pdr::par::write_in_rank_order(nowhere, std::vector<std::string>{part(rank, 1, 0)});
  } catch (const std::system_error& e) {
    thrown = true;
    if (std::string(e.what()).find("c.txt") == std::string::npos)
      fail(std::string("the error does not name the file: ") + e.what());
  }
  if (rank == 0 ? !thrown : (thrown || written))
    fail("rank " + std::to_string(rank) + ": a file in a missing directory: " +
         (thrown ? "thrown" : written ? "written" : "false"));
  if (rank == 0 && std::filesystem::exists(dir / "missing")) fail("a missing directory was made");
  pdr::par::broadcast_from_root(0);
  if (rank == 0) std::filesystem::remove_all(dir);
  return 0;
}
