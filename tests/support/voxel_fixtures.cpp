// Voxel solids as PLCs; see tests/support/voxel_fixtures.hpp.
#include "support/voxel_fixtures.hpp"

#include <map>
#include <set>
#include <utility>

#include "support/plc_fixtures.hpp"

namespace pdr::test {

using Cell = std::array<int, 3>;

bool VoxelSet::inside_grid(Cell c) const {
  for (int a = 0; a < 3; ++a)
    if (c[a] < 0 || c[a] >= n_[a]) return false;
  return true;
}

bool VoxelSet::at(Cell c) const { return inside_grid(c) && cells_[index(c)] != 0; }

void VoxelSet::set(Cell c, bool v) { cells_[index(c)] = v ? 1 : 0; }

std::size_t VoxelSet::count() const {
  std::size_t k = 0;
  for (const auto c : cells_) k += c;
  return k;
}

VoxelSet voxels_of(std::array<int, 3> n, const std::vector<GridBox>& boxes) {
  VoxelSet s(n);
  for (const GridBox& b : boxes)
    for (int z = b.lo[2]; z < b.hi[2]; ++z)
      for (int y = b.lo[1]; y < b.hi[1]; ++y)
        for (int x = b.lo[0]; x < b.hi[0]; ++x)
          if (s.inside_grid({x, y, z})) s.set({x, y, z});
  return s;
}

namespace {

Cell offset(Cell c, int a, int d) {
  c[a] += d;
  return c;
}

// Repairs the critical configurations based at cell c; true when a cell was added.
bool repair_at(VoxelSet& s, Cell c) {
  // 2x2 squares in the three axis planes through c.
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    const Cell c10 = offset(c, u, 1), c01 = offset(c, v, 1), c11 = offset(c10, v, 1);
    if (!s.inside_grid(c11)) continue;
    const bool q00 = s.at(c), q10 = s.at(c10), q01 = s.at(c01), q11 = s.at(c11);
    if (q00 && q11 && !q10 && !q01) {
      s.set(c10);
      return true;
    }
    if (q10 && q01 && !q00 && !q11) {
      s.set(c);
      return true;
    }
  }
  // The 2x2x2 block at c: two antipodal cells alone, or two antipodal holes alone.
  if (!s.inside_grid({c[0] + 1, c[1] + 1, c[2] + 1})) return false;
  std::array<bool, 8> q{};
  int occupied = 0;
  for (int k = 0; k < 8; ++k) {
    q[k] = s.at({c[0] + (k & 1), c[1] + (k >> 1 & 1), c[2] + (k >> 2)});
    occupied += q[k];
  }
  for (int k = 0; k < 4; ++k) {
    const int o = 7 - k;  // antipodal corner
    const Cell ck{c[0] + (k & 1), c[1] + (k >> 1 & 1), c[2] + (k >> 2)};
    if (occupied == 2 && q[k] && q[o]) {
      s.set(offset(ck, 0, (k & 1) ? -1 : 1));  // the neighbour of k towards o along x
      return true;
    }
    if (occupied == 6 && !q[k] && !q[o]) {
      s.set(ck);
      return true;
    }
  }
  return false;
}

}  // namespace

void make_well_composed(VoxelSet& s) {
  const auto& n = s.size();
  for (bool changed = true; changed;) {
    changed = false;
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x)
          while (repair_at(s, {x, y, z})) changed = true;
  }
}

std::vector<std::array<double, 3>> enclosed_voids(const VoxelSet& s) {
  const auto& n = s.size();
  // Flood the empty cells from outside, over the grid padded by one cell (6-adjacency).
  std::set<Cell> seen;
  std::vector<Cell> stack{{-1, -1, -1}};
  seen.insert(stack.back());
  auto flood = [&](std::vector<Cell>& st) {
    while (!st.empty()) {
      const Cell c = st.back();
      st.pop_back();
      for (int a = 0; a < 3; ++a)
        for (const int d : {-1, 1}) {
          const Cell e = offset(c, a, d);
          if (e[a] < -1 || e[a] > n[a] || s.at(e) || seen.count(e)) continue;
          seen.insert(e);
          st.push_back(e);
        }
    }
  };
  flood(stack);
  std::vector<std::array<double, 3>> out;
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const Cell c{x, y, z};
        if (s.at(c) || seen.count(c)) continue;
        out.push_back({x + 0.5, y + 0.5, z + 0.5});
        seen.insert(c);
        stack.push_back(c);
        flood(stack);
      }
  return out;
}

namespace {

using G2 = std::pair<int, int>;             // a grid point of a plane
using Loop = std::vector<Cell>;             // grid points, in order
struct GridFacet {
  std::vector<Loop> loops;
  std::vector<std::array<double, 3>> holes;  // grid units
};

// The boundary loops of one 4-connected set of squares of the plane g[a] = p (squares
// (iu, iv) with iu along axis u = a+1, iv along v = a+2): one facet, or one facet per
// square when the set touches itself at a vertex (a pinched polygon is not simple).
void facets_of_component(const std::set<G2>& comp, int a, int p, std::vector<GridFacet>& out) {
  const int u = (a + 1) % 3, v = (a + 2) % 3;
  auto to3 = [&](double gu, double gv) {
    std::array<double, 3> g{};
    g[a] = p;
    g[u] = gu;
    g[v] = gv;
    return g;
  };
  auto cell3 = [&](int gu, int gv) {
    Cell g{};
    g[a] = p;
    g[u] = gu;
    g[v] = gv;
    return g;
  };
  auto in = [&](int iu, int iv) { return comp.count({iu, iv}) != 0; };
  bool pinched = false;
  for (const auto& [iu, iv] : comp) {  // square (iu, iv) and a diagonal one above it alone
    const bool up = in(iu, iv + 1);
    pinched = pinched || (in(iu + 1, iv + 1) && !in(iu + 1, iv) && !up) ||
              (in(iu - 1, iv + 1) && !in(iu - 1, iv) && !up);
  }
  if (pinched) {
    for (const auto& [iu, iv] : comp)
      out.push_back({{{cell3(iu, iv), cell3(iu + 1, iv), cell3(iu + 1, iv + 1), cell3(iu, iv + 1)}},
                     {}});
    return;
  }
  // Directed boundary edges with the set on their left; no pinch: one out-edge per vertex.
  std::map<G2, G2> next;
  for (const auto& [iu, iv] : comp) {
    if (!in(iu, iv - 1)) next[{iu, iv}] = {iu + 1, iv};
    if (!in(iu + 1, iv)) next[{iu + 1, iv}] = {iu + 1, iv + 1};
    if (!in(iu, iv + 1)) next[{iu + 1, iv + 1}] = {iu, iv + 1};
    if (!in(iu - 1, iv)) next[{iu, iv + 1}] = {iu, iv};
  }
  GridFacet f;
  while (!next.empty()) {
    const G2 start = next.begin()->first;
    Loop loop;
    long twice_area = 0;
    G2 at = start;
    do {
      const G2 to = next.at(at);
      next.erase(at);
      loop.push_back(cell3(at.first, at.second));
      twice_area += long(at.first) * to.second - long(to.first) * at.second;
      at = to;
    } while (at != start);
    if (twice_area < 0) {  // a hole: the square right of the loop's first edge is in it
      const G2 to{loop[1][u], loop[1][v]};
      const int du = to.first - start.first, dv = to.second - start.second;
      f.holes.push_back(to3(start.first + 0.5 * du + 0.5 * dv, start.second + 0.5 * dv - 0.5 * du));
    }
    f.loops.push_back(std::move(loop));
  }
  out.push_back(std::move(f));
}

}  // namespace

Plc voxel_plc(const VoxelSet& s, double unit, const Point& origin) {
  const auto& n = s.size();
  std::vector<GridFacet> facets;
  for (int a = 0; a < 3; ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    for (int p = 0; p <= n[a]; ++p)
      for (const int side : {1, -1}) {
        std::set<G2> mask;
        for (int iu = 0; iu < n[u]; ++iu)
          for (int iv = 0; iv < n[v]; ++iv) {
            Cell below{};
            below[a] = p - 1;
            below[u] = iu;
            below[v] = iv;
            const bool lo = s.at(below), hi = s.at(offset(below, a, 1));
            if (lo != hi && (lo ? 1 : -1) == side) mask.insert({iu, iv});
          }
        while (!mask.empty()) {  // 4-connected components
          std::set<G2> comp;
          std::vector<G2> stack{*mask.begin()};
          mask.erase(mask.begin());
          while (!stack.empty()) {
            const G2 q = stack.back();
            stack.pop_back();
            comp.insert(q);
            for (const G2& d : {G2{1, 0}, G2{-1, 0}, G2{0, 1}, G2{0, -1}}) {
              const auto it = mask.find({q.first + d.first, q.second + d.second});
              if (it == mask.end()) continue;
              stack.push_back(*it);
              mask.erase(it);
            }
          }
          facets_of_component(comp, a, p, facets);
        }
      }
  }
  // Keep the points where some loop turns (every other point of a loop lies inside one of
  // its straight runs, and on no other facet's corner).
  std::set<Cell> corners;
  for (const GridFacet& f : facets)
    for (const Loop& l : f.loops)
      for (std::size_t i = 0; i < l.size(); ++i) {
        const Cell &p = l[(i + l.size() - 1) % l.size()], &q = l[i], &r = l[(i + 1) % l.size()];
        for (int a = 0; a < 3; ++a)
          if ((q[a] - p[a]) != (r[a] - q[a])) corners.insert(q);
      }
  auto at = [&](const std::array<double, 3>& g) {
    return Point{origin[0] + unit * g[0], origin[1] + unit * g[1], origin[2] + unit * g[2]};
  };
  std::map<Cell, std::uint32_t> id;
  std::vector<Point> points;
  std::vector<FacetSpec> specs;
  for (const GridFacet& f : facets) {
    FacetSpec spec;
    for (const Loop& l : f.loops) {
      Poly poly;
      for (const Cell& c : l) {
        if (!corners.count(c)) continue;
        const auto [it, fresh] = id.emplace(c, static_cast<std::uint32_t>(points.size()));
        if (fresh) points.push_back(at({double(c[0]), double(c[1]), double(c[2])}));
        poly.push_back(it->second);
      }
      spec.push_back(std::move(poly));
    }
    specs.push_back(std::move(spec));
  }
  std::vector<Point> voids;
  for (const auto& g : enclosed_voids(s)) voids.push_back(at(g));
  Plc plc = make_plc(std::move(points), std::move(specs), std::move(voids));
  for (std::size_t k = 0; k < facets.size(); ++k)
    for (const auto& h : facets[k].holes) plc.facets[k].holes.push_back(at(h));
  return plc;
}

}  // namespace pdr::test
