// Hilbert keys and BRIO rounds (spatial_sort.hpp).
#include "delaunay/spatial_sort.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

namespace pdr {

namespace {

// Spreads the low 10 bits of x to bits 0, 3, 6, ..., 27.
std::uint64_t spread3(std::uint32_t x) {
  std::uint64_t v = x & 0x3FFu;
  v = (v | (v << 16)) & 0x30000FFull;
  v = (v | (v << 8)) & 0x300F00Full;
  v = (v | (v << 4)) & 0x30C30C3ull;
  v = (v | (v << 2)) & 0x9249249ull;
  return v;
}

}  // namespace

std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) {
  assert(bits >= 1 && bits <= 10);
  std::uint32_t X[3] = {x, y, z};
  const std::uint32_t top = std::uint32_t{1} << (bits - 1);
  // Undo the excess work of the curve's reflections and rotations, level by level:
  // where bit q of X[i] is set, invert the low bits of X[0]; else exchange the low bits
  // of X[0] and X[i]. Written with masks instead of branches (the bits are random).
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t set = 0u - static_cast<std::uint32_t>((X[i] & q) != 0);
      const std::uint32_t t = (X[0] ^ X[i]) & p & ~set;
      X[0] ^= (p & set) | t;
      X[i] ^= t;
    }
  }
  // Gray encode.
  for (int i = 1; i < 3; ++i) X[i] ^= X[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (X[2] & q) t ^= q - 1;
  for (int i = 0; i < 3; ++i) X[i] ^= t;
  // Interleave: the transposed index, most significant bit first, X[0] leading.
  return (spread3(X[0]) << 2) | (spread3(X[1]) << 1) | spread3(X[2]);
}

namespace {

// Grid resolution: about 2^9 cells per point along the curve is plenty for locality, and
// each bit costs a round of the index computation. At most 10 bits per axis, so that a
// 30-bit key and a 32-bit id pack into one 64-bit word for the radix sort.
int grid_bits(std::size_t n) {
  int log2n = 0;
  while ((std::size_t{1} << log2n) < n && log2n < 63) ++log2n;
  return std::clamp(log2n / 3 + 3, 2, 10);
}

struct Grid {
  Point lo{};
  double scale[3] = {0, 0, 0};  // cells per unit length, per axis
  int bits = 1;

  Grid(const Point& lo_, const Point& hi, int b) : lo(lo_), bits(b) {
    const double cells = static_cast<double>((std::uint32_t{1} << bits) - 1);
    for (int k = 0; k < 3; ++k) scale[k] = hi[k] > lo[k] ? cells / (hi[k] - lo[k]) : 0.0;
  }
  std::uint32_t cell(const Point& p, int k) const {
    const double max = static_cast<double>((std::uint32_t{1} << bits) - 1);
    return static_cast<std::uint32_t>(std::clamp((p[k] - lo[k]) * scale[k], 0.0, max));
  }
  std::uint64_t key(const Point& p) const {
    return hilbert_index(cell(p, 0), cell(p, 1), cell(p, 2), bits);
  }
};

// splitmix64: the seeded generator for the shuffle.
std::uint64_t next_random(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Sorts words (key << 32 | id) by key: least-significant-digit radix sort, 10-bit digits.
void radix_sort_by_key(std::span<std::uint64_t> words, int key_bits,
                       std::vector<std::uint64_t>& scratch) {
  if (words.size() < 256) {
    std::sort(words.begin(), words.end());
    return;
  }
  constexpr int kDigit = 10;
  scratch.resize(words.size());
  std::span<std::uint64_t> from = words, to(scratch.data(), words.size());
  int passes = 0;
  for (int shift = 32; shift < 32 + key_bits; shift += kDigit, ++passes) {
    std::size_t count[(1 << kDigit) + 1] = {};
    for (std::uint64_t w : from) ++count[((w >> shift) & ((1u << kDigit) - 1)) + 1];
    for (int d = 0; d < (1 << kDigit); ++d) count[d + 1] += count[d];
    for (std::uint64_t w : from) to[count[(w >> shift) & ((1u << kDigit) - 1)]++] = w;
    std::swap(from, to);
  }
  if (passes % 2 == 1) std::copy(from.begin(), from.end(), words.begin());
}

// Words (key << 32 | id) for ids, keys computed in the given order (sequential reads of
// the points when ids are ascending, as they are before the shuffle).
std::vector<std::uint64_t> keyed_words(std::span<const std::uint32_t> ids,
                                       std::span<const Point> pts, const Grid& g) {
  std::vector<std::uint64_t> words(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) words[i] = (g.key(pts[ids[i]]) << 32) | ids[i];
  return words;
}

Point box_lo(std::span<const std::uint32_t> ids, std::span<const Point> pts, bool upper) {
  Point b = pts[ids[0]];
  for (std::uint32_t id : ids)
    for (int k = 0; k < 3; ++k) b[k] = upper ? std::max(b[k], pts[id][k]) : std::min(b[k], pts[id][k]);
  return b;
}

}  // namespace

void hilbert_sort(std::span<std::uint32_t> ids, std::span<const Point> pts, const Point& lo,
                  const Point& hi) {
  const Grid g(lo, hi, grid_bits(ids.size()));
  std::vector<std::uint64_t> words = keyed_words(ids, pts, g), scratch;
  radix_sort_by_key(words, 3 * g.bits, scratch);
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<std::uint32_t>(words[i]);
}

std::vector<std::uint32_t> hilbert_tet_order(const TetStore& s, std::span<const Point> pts,
                                             std::span<const TetId> tets) {
  std::vector<Point> centroid(tets.size());
  std::vector<std::uint32_t> order(tets.size());
  Point lo{}, hi{};
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const VertexId* v = s.vertices(tets[i]);
    for (int k = 0; k < 3; ++k) {
      // A quarter of each: their sum stays finite whatever the coordinates.
      const double c = pts[v[0]][k] / 4 + pts[v[1]][k] / 4 + pts[v[2]][k] / 4 + pts[v[3]][k] / 4;
      centroid[i][k] = c;
      lo[k] = i == 0 ? c : std::min(lo[k], c);
      hi[k] = i == 0 ? c : std::max(hi[k], c);
    }
    order[i] = static_cast<std::uint32_t>(i);
  }
  hilbert_sort(order, centroid, lo, hi);
  return order;
}

std::vector<std::uint32_t> brio_order(std::vector<std::uint32_t> ids,
                                      std::span<const Point> pts, std::uint64_t seed,
                                      std::size_t min_round) {
  if (ids.empty()) return ids;
  const Grid g(box_lo(ids, pts, false), box_lo(ids, pts, true), grid_bits(ids.size()));
  std::vector<std::uint64_t> words = keyed_words(ids, pts, g), scratch;
  std::uint64_t s = seed;
  for (std::size_t i = words.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(
        (static_cast<unsigned __int128>(next_random(s)) * i) >> 64);
    std::swap(words[i - 1], words[j]);
  }
  std::size_t end = words.size();
  while (end > 0) {
    const std::size_t begin = end > min_round ? end / 2 : 0;
    radix_sort_by_key(std::span<std::uint64_t>(words).subspan(begin, end - begin),
                      3 * g.bits, scratch);
    end = begin;
  }
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<std::uint32_t>(words[i]);
  return ids;
}

}  // namespace pdr
