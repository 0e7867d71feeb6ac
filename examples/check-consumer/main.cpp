// An in-memory mesh checked by pdr::check from another project (examples/check-consumer).
// A unit cube split into 6 tets around its diagonal (Kuhn): valid and Delaunay (its 8
// vertices are cospherical); then one vertex moved so that every circumsphere holds a
// vertex, which must fail delaunay.empty_sphere. Prints both verdicts; exits 0 when pdr
// judged as expected.
#include <cstdint>
#include <iostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "check/check.hpp"

int main() {
  // Vertex i of the cube has coordinates (i & 1, (i >> 1) & 1, (i >> 2) & 1).
  std::vector<double> xyz;
  for (int i = 0; i < 8; ++i) {
    xyz.push_back(i & 1);
    xyz.push_back((i >> 1) & 1);
    xyz.push_back((i >> 2) & 1);
  }
  // The six tets of the path 0 -> 7 along the permutations of the axes, positively oriented.
  const std::vector<std::uint32_t> tets = {0, 1, 3, 7, 0, 3, 2, 7, 0, 2, 6, 7,
                                           0, 6, 4, 7, 0, 4, 5, 7, 0, 5, 1, 7};
  pdr::check::Options opt;
  opt.ratio_bound = 2.0;
  const pdr::check::Report good = pdr::check::check_arrays(xyz, tets, {}, nullptr, opt);
  std::cout << pdr::check::to_text(good);

  xyz[3 * 7 + 0] = 1.25;  // vertex 7 pushed out along the diagonal: still positive tets,
  xyz[3 * 7 + 1] = 1.25;  // but every circumsphere now holds a cube vertex
  xyz[3 * 7 + 2] = 1.25;
  const pdr::check::Report bad = pdr::check::check_arrays(xyz, tets, {}, nullptr, opt);
  const nlohmann::json j = pdr::check::to_json(bad);
  std::cout << "schema_version " << j["schema_version"] << ", ok " << j["ok"] << "\n";

  const auto* d = bad.find("delaunay.empty_sphere");
  const bool expected = good.ok() && d && d->status == pdr::check::Status::Fail;
  std::cout << (expected ? "consumer: as expected\n" : "consumer: UNEXPECTED verdicts\n");
  return expected ? 0 : 1;
}
