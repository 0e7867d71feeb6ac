// The domain analysis in one call: validation (plc_validate.hpp), admissibility
// (plc_angles.hpp, paper §1.1) and the distance d (plc_distance.hpp, paper §2.1).
#pragma once

#include "mesh/plc.hpp"
#include "refine/plc_domain.hpp"
#include "refine/plc_report.hpp"

namespace pdr::refine {

struct DomainAnalysis {
  PlcDomain domain;
  DomainReport report;
};

// Throws InputError when the PLC is not a valid polyhedral domain. An inadmissible domain
// is not an error: report.admissible is false and report.violations lists why.
DomainAnalysis analyze(const Plc& plc, const PlcOptions& options = {});
DomainReport analyze_domain(const Plc& plc, const PlcOptions& options = {});

}  // namespace pdr::refine
