// MaybeId: an id of the surface mesh D (a subsegment or subfacet) or none, returned by the
// VolumeMesh lookups (refine/volume_mesh.hpp) that the refinement calls for every edge and face
// of every cavity. Used like std::optional<std::uint32_t> (`if (x)`, `*x`, `has_value()`,
// conversion to the optional), but held in one 32-bit word with kNone for "none": an
// optional's separate flag byte, stored alone and then read back with the id as one
// 8-byte word, stalls store forwarding in those loops (measured: most of their time).
#pragma once

#include <cstdint>
#include <optional>

namespace pdr::refine {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

class MaybeId {
 public:
  constexpr MaybeId() = default;
  constexpr MaybeId(std::nullopt_t) {}
  constexpr MaybeId(std::uint32_t id) : id_(id) {}

  constexpr bool has_value() const { return id_ != kNone; }
  constexpr explicit operator bool() const { return has_value(); }
  // Precondition: has_value().
  constexpr std::uint32_t operator*() const { return id_; }
  constexpr operator std::optional<std::uint32_t>() const {
    return has_value() ? std::optional<std::uint32_t>(id_) : std::nullopt;
  }
  friend constexpr bool operator==(MaybeId, MaybeId) = default;

 private:
  std::uint32_t id_ = kNone;
};

}  // namespace pdr::refine
