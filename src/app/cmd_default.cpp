// `pdr` without a command: the default job on an embedded input, so that line 1 of the
// README's Quick start shows the whole pipeline with no file at hand.
//
// Until refinement lands (issue #3) the job is the Delaunay tetrahedralization of an
// embedded point set: the 16 corners of the cube-in-cube domain of paper §5 (cube
// [0,10]^3 with a suspended cubical void [4,6]^3) and a 6x6 grid on every face of both
// cubes (exactly coplanar and cospherical points: the degenerate cases), plus 100,000
// seeded pseudo-random points in the cube; then the exact check and output.
#include <cstdint>
#include <filesystem>

#include "app/commands.hpp"
#include "app/exit_codes.hpp"
#include "app/pipeline.hpp"
#include "app/summary.hpp"

namespace pdr::app {
namespace {

// A portable generator (splitmix64): the same points on every platform and library.
struct SplitMix64 {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

std::vector<Point> embedded_points() {
  std::vector<Point> pts;
  for (double lo : {0.0, 4.0})
    for (int i = 0; i <= 5; ++i)
      for (int j = 0; j <= 5; ++j)
        for (int k = 0; k <= 5; ++k) {
          const double span = lo == 0.0 ? 10.0 : 2.0;
          const double step = span / 5.0;
          const bool on_face = i == 0 || i == 5 || j == 0 || j == 5 || k == 0 || k == 5;
          if (on_face) pts.push_back({lo + step * i, lo + step * j, lo + step * k});
        }
  SplitMix64 rng{20021116};
  for (int i = 0; i < 100000; ++i)
    pts.push_back({10 * rng.unit(), 10 * rng.unit(), 10 * rng.unit()});
  return pts;
}

}  // namespace

int run_default(const DefaultArgs& args) {
  const auto parent = std::filesystem::path(args.prefix).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  PhaseTimer timer;
  Summary summary;
  summary.set("command", "default job: Delaunay tetrahedralization of the embedded point set");
  std::vector<Point> points = embedded_points();
  timer.lap("generate");
  const int code = triangulate_write_check(std::move(points), "<embedded points>",
                                           args.prefix, parse_formats({"node", "vtu"}),
                                           /*check=*/true, /*threads=*/2, timer, summary);
  summary.print(args.json);
  return code;
}

}  // namespace pdr::app
