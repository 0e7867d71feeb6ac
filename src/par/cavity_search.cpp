// The two local steps of the distributed cavity search (par/cavity_search.hpp).
#include "par/cavity_search.hpp"

#include "delaunay/conflict.hpp"

namespace pdr::par {

const RootCavity& CavitySearch::root_cavity(const Submesh& s, const Point& p, TetId hint,
                                            bool hint_conflicts, const Reject& reject) {
  RootCavity& out = root_;
  out.kind = RootCavity::Kind::Complete;
  out.cavity.clear();
  out.fetch.clear();
  out.walk = false;
  const TetStore& st = s.store();
  TetId seed = kNoTet;
  if (hint_conflicts && seeds_cavity(st, s.points(), hint, p)) {
    seed = hint;
  } else {
    const Location loc = locate(st, s.points(), p, hint, rng_);
    if (loc.kind == Location::Kind::OnVertex) {
      out.kind = RootCavity::Kind::OnVertex;
      return out;
    }
    if (loc.kind == Location::Kind::Remote) {
      const Side& side = s.proxy_side(loc.tet);
      out.kind = RootCavity::Kind::Remote;
      out.walk = true;
      out.fetch[side.claim.holder].push_back(side);
      return out;
    }
    seed = loc.tet;
  }
  if (reject) {
    if (!builder_.build_until(st, s.points(), p, seed, out.cavity,
                              [&](TetId, int, TetId u) { return reject(u); })) {
      out.kind = RootCavity::Kind::Rejected;
      return out;
    }
  } else {
    builder_.build(st, s.points(), p, seed, out.cavity);
  }
  for (const TetId t : out.cavity.ring)
    if (st.is_proxy(t)) {
      const Side& side = s.proxy_side(t);
      out.kind = RootCavity::Kind::Remote;
      out.fetch[side.claim.holder].push_back(side);
    }
  return out;
}

CavitySearch::FetchSet CavitySearch::fetch_set(const Submesh& s, const Point& p,
                                               std::span<const Gid> wanted, bool walk,
                                               const Reject& reject) {
  const TetStore& st = s.store();
  FetchSet result;
  std::vector<TetId>& out = result.tets;
  taken_.clear();
  const auto add = [&](TetId t) {
    if (st.is_proxy(t) || taken_.contains(t)) return;
    taken_.insert(t);
    out.push_back(t);
  };
  for (const Gid g : wanted) {
    TetId t = s.find_tet(g);
    if (t == kNoTet || taken_.contains(t)) continue;
    if (walk) {
      const Location loc = locate(st, s.points(), p, t, rng_);
      t = loc.kind == Location::Kind::Remote ? st.neighbour(loc.tet, 3) : loc.tet;
    }
    add(t);
    if (!in_conflict(st, s.points(), t, p)) continue;
    if (reject) {
      if (!builder_.build_until(st, s.points(), p, t, part_,
                                [&](TetId, int, TetId u) { return reject(u); })) {
        result.tets.clear();
        result.rejected = true;
        return result;
      }
    } else {
      builder_.build(st, s.points(), p, t, part_);
    }
    for (const TetId u : part_.conflict) add(u);
    for (const TetId u : part_.ring) add(u);
  }
  return result;
}

}  // namespace pdr::par
