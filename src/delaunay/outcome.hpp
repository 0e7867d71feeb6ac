// Outcome: what an attempt to insert a point did (docs/design.md §11).
//
// The Delaunay kernel produces Inserted and Duplicate. The later layers produce the rest,
// and they are declared here now so that every caller switches over one closed enum:
//   Encroaches    refinement (§3): the point's cavity would delete a protected subsegment
//                 or subfacet, which is split instead;
//   OutsideDomain refinement: the point lies outside the meshed domain;
//   Conflict      parallel insertion (§4.1): the cavity's closure met a locked tet; the
//                 only outcome a caller may retry.
// New outcomes are appended (values are stable: they appear in logs and statistics).
#pragma once

#include <cstdint>
#include <string_view>

namespace pdr {

enum class Outcome : std::uint8_t {
  Inserted = 0,
  Duplicate = 1,
  Encroaches = 2,
  OutsideDomain = 3,
  Conflict = 4,
};

constexpr std::string_view to_string(Outcome o) {
  switch (o) {
    case Outcome::Inserted: return "inserted";
    case Outcome::Duplicate: return "duplicate";
    case Outcome::Encroaches: return "encroaches";
    case Outcome::OutsideDomain: return "outside-domain";
    case Outcome::Conflict: return "conflict";
  }
  return "unknown";
}

}  // namespace pdr
