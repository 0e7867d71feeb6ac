// Probes of the floating-point environment pdr_geom was compiled in (docs/design.md §7).
//
// The functions below are compiled inside pdr_geom, with its flags, and never inlined
// into callers (separate translation unit, no LTO), so a test calling them sees exactly
// the arithmetic the predicates use. tests/geom/fp_contract_test.cpp fails if
// floating-point contraction (a*b+c fused into one fma) leaks into pdr_geom, e.g. from a
// build with -march=native without -ffp-contract=off, and checks that the error-free
// transformations of expansion.hpp, as compiled there, are exact.
#pragma once

namespace pdr::detail {

// a * b + c with two roundings (unless contraction leaked in).
double fp_contract_probe(double a, double b, double c);

// expansion::two_sum and expansion::two_product as compiled in pdr_geom: x + y == a op b.
void probe_two_sum(double a, double b, double& x, double& y);
void probe_two_product(double a, double b, double& x, double& y);

}  // namespace pdr::detail
