// Out-of-line probes of pdr_geom's floating-point compilation flags (fp_probe.hpp).
#include "geom/fp_probe.hpp"

#include "geom/expansion.hpp"

namespace pdr::detail {

double fp_contract_probe(double a, double b, double c) { return a * b + c; }

void probe_two_sum(double a, double b, double& x, double& y) {
  expansion::two_sum(a, b, x, y);
}

void probe_two_product(double a, double b, double& x, double& y) {
  expansion::two_product(a, b, x, y);
}

}  // namespace pdr::detail
