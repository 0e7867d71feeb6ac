// Meshes for the parallel layer's tests: a refined cube-in-cube (the paper's first
// domain), built once per test binary.
#pragma once

#include <string>

#include "domain/analysis.hpp"
#include "io/mesh_io.hpp"
#include "refine/initial.hpp"
#include "refine/seq_refinement.hpp"
#include "surface/init.hpp"

namespace pdr::par::test {

inline refine::VolumeMesh refined(const std::string& name, double max_volume) {
  const Plc plc = io::read_domain(std::string(PDR_DATA_DIR) + "/" + name);
  domain::DomainAnalysis an = domain::analyze(plc);
  refine::VolumeMesh vm =
      refine::build_initial(surface::init_surface(an).mesh, an.domain.plc.holes);
  refine::RefineOptions o;
  o.max_volume = max_volume;
  o.d = an.report.feature.d;
  refine::refine(vm, o);
  return vm;
}

inline const refine::VolumeMesh& cube_in_cube() {
  static const refine::VolumeMesh vm = refined("cube-in-cube.poly", 0.3);
  return vm;
}

}  // namespace pdr::par::test
