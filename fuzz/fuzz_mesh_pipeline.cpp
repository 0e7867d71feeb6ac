// Fuzz target: the whole `pdr mesh` pipeline (src/app mesh_plc: domain analysis, surface
// mesh, initial mesh, SeqRefinement with the Lemma 1 audit on, exact check) on tiny random
// admissible domains. The domain comes from the same generator as the RapidCheck property
// (tests/support/admissible_fixtures.hpp): the input's first 8 bytes seed it, the ninth
// sets its size, the tenth picks an optional volume bound. Property: the run ends with
// exit 0, the domain admissible, the exact checker passing and every tet's ratio below 2
// (tests/refine/property_test.cpp asserts the same).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "app/commands.hpp"
#include "app/summary.hpp"
#include "fuzz_target.hpp"
#include "support/admissible_fixtures.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 10) return 0;
  std::uint64_t seed = 0;
  std::memcpy(&seed, data, sizeof seed);
  const int gen_size = data[8] % 40;
  const pdr::Plc plc = pdr::test::gen_admissible_domain()(rc::Random(seed), gen_size).value();
  pdr::app::MeshArgs args;
  args.prefix = "unused";
  args.formats.clear();
  args.options.ratio = 2.0;
  args.options.audit = true;
  if (data[9] % 4 != 0) {  // a volume bound that cuts the bounding box into tens of pieces
    pdr::Point lo = plc.points[0], hi = plc.points[0];
    for (const pdr::Point& p : plc.points)
      for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    args.options.max_volume =
        (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]) / (8.0 * (data[9] % 4));
  }
  pdr::app::Summary summary;
  std::string why;
  try {
    const int code = pdr::app::mesh_plc(plc, args, summary);
    const auto j = summary.to_json();
    if (code != 0) why += "exit code " + std::to_string(code) + "; ";
    if (j.value("admissible", false) != true) why += "analysis says inadmissible; ";
    if (j.value("check", "") != "pass") why += "checker did not pass; ";
    if (!(j.value("ratio_max", 99.0) < 2.0)) why += "ratio_max >= 2; ";
  } catch (const std::exception& e) {
    why = std::string("exception: ") + e.what();
  }
  if (!why.empty()) {
    std::fprintf(stderr, "fuzz_mesh_pipeline: %s\n%s\n", why.c_str(),
                 pdr::test::poly_text(plc, "fuzz_mesh_pipeline counterexample").c_str());
    std::abort();
  }
  return 0;
}
