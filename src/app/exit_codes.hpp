// The exit codes of the `pdr` command line, one meaning each (README.md, "Exit codes").
#pragma once

namespace pdr::app {

inline constexpr int kExitOk = 0;              // done; every check passed
inline constexpr int kExitViolations = 1;      // the checker found violations
inline constexpr int kExitBadInput = 2;        // malformed input or usage; nothing written
inline constexpr int kExitNotGuaranteed = 3;   // meshed, but some tet kept ratio >= B
inline constexpr int kExitInternal = 4;        // a bug: an internal invariant failed

}  // namespace pdr::app
