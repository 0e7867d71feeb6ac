// Hilbert keys and BRIO rounds (spatial_sort.hpp).
#include "delaunay/spatial_sort.hpp"

#include <algorithm>
#include <utility>

namespace pdr {

std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) {
  std::uint32_t X[3] = {x, y, z};
  const std::uint32_t top = std::uint32_t{1} << (bits - 1);
  // Undo the excess work of the curve's reflections and rotations, level by level.
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & q) {
        X[0] ^= p;  // invert the low bits of X[0]
      } else {
        const std::uint32_t t = (X[0] ^ X[i]) & p;  // exchange low bits of X[0] and X[i]
        X[0] ^= t;
        X[i] ^= t;
      }
    }
  }
  // Gray encode.
  for (int i = 1; i < 3; ++i) X[i] ^= X[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (X[2] & q) t ^= q - 1;
  for (int i = 0; i < 3; ++i) X[i] ^= t;
  // Interleave: the transposed index, most significant bit first, X[0] leading.
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((X[i] >> b) & 1u);
  return key;
}

namespace {

// Grid resolution: about 2^9 cells per point along the curve is plenty for locality, and
// each bit costs a round of the index computation.
int grid_bits(std::size_t n) {
  int log2n = 0;
  while ((std::size_t{1} << log2n) < n && log2n < 63) ++log2n;
  return std::clamp(log2n / 3 + 3, 2, 21);
}

std::uint32_t cell(double x, double lo, double hi, int bits) {
  const double span = hi - lo;
  if (!(span > 0)) return 0;
  const double max = static_cast<double>((std::uint32_t{1} << bits) - 1);
  double c = (x - lo) / span * max;
  c = std::clamp(c, 0.0, max);
  return static_cast<std::uint32_t>(c);
}

// splitmix64: the seeded generator for the shuffle.
std::uint64_t next_random(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

void hilbert_sort(std::span<std::uint32_t> ids, std::span<const Point> pts, const Point& lo,
                  const Point& hi) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(ids.size());
  const int bits = grid_bits(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const Point& p = pts[ids[i]];
    keyed[i] = {hilbert_index(cell(p[0], lo[0], hi[0], bits), cell(p[1], lo[1], hi[1], bits),
                              cell(p[2], lo[2], hi[2], bits), bits),
                ids[i]};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = keyed[i].second;
}

std::vector<std::uint32_t> brio_order(std::vector<std::uint32_t> ids,
                                      std::span<const Point> pts, std::uint64_t seed,
                                      std::size_t min_round) {
  if (ids.empty()) return ids;
  Point lo = pts[ids[0]], hi = pts[ids[0]];
  for (std::uint32_t id : ids)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], pts[id][k]);
      hi[k] = std::max(hi[k], pts[id][k]);
    }
  std::uint64_t s = seed;
  for (std::size_t i = ids.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(
        (static_cast<unsigned __int128>(next_random(s)) * i) >> 64);
    std::swap(ids[i - 1], ids[j]);
  }
  std::size_t end = ids.size();
  while (end > 0) {
    const std::size_t begin = end > min_round ? end / 2 : 0;
    hilbert_sort(std::span<std::uint32_t>(ids).subspan(begin, end - begin), pts, lo, hi);
    end = begin;
  }
  return ids;
}

}  // namespace pdr
