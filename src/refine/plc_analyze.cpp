// The domain analysis in one call (paper §1.1, §2.1); see plc_analyze.hpp.
#include "refine/plc_analyze.hpp"

#include "refine/plc_validate.hpp"

namespace pdr::refine {

DomainAnalysis analyze(const Plc& plc, const PlcOptions& options) {
  DomainAnalysis a{build_domain(plc, options), {}};
  a.report = make_report(a.domain, check_admissibility(a.domain), feature_size(a.domain));
  return a;
}

DomainReport analyze_domain(const Plc& plc, const PlcOptions& options) {
  return analyze(plc, options).report;
}

}  // namespace pdr::refine
