#include "scene/normal_maps/wang_tiles.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/shader_hash.hpp"

namespace glintlab {

namespace {

/// a mod n in [0, n) for any sign of a.
std::int64_t wrapped(std::int64_t a, std::int64_t n) { return ((a % n) + n) % n; }

/// floor(a / n) for n > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t n) { return (a - wrapped(a, n)) / n; }

}  // namespace

std::uint32_t WangLattice::corner_bits(std::int32_t i, std::int32_t j) const {
  if (period_ > 0) {
    i = static_cast<std::int32_t>(wrapped(i, period_));
    j = static_cast<std::int32_t>(wrapped(j, period_));
  }
  // The shaders' hash3 (wang_tiles.glsl draws the same bits); its two highest bits, the most mixed.
  return hash3(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), seed_) >> 30;
}

int WangLattice::edge_along_u(std::int32_t i, std::int32_t j) const { return static_cast<int>(corner_bits(i, j) & 1U); }

int WangLattice::edge_along_v(std::int32_t i, std::int32_t j) const { return static_cast<int>(corner_bits(i, j) >> 1); }

WangEdges WangLattice::cell(std::int32_t i, std::int32_t j) const {
  return {.north = edge_along_u(i, j + 1), .east = edge_along_v(i + 1, j), .south = edge_along_u(i, j),
          .west = edge_along_v(i, j)};
}

namespace {

/// Where a tile's texel is copied from: the diamond of one of its edges, or the tile's own centre patch.
enum Edge { kSouth, kNorth, kWest, kEast, kCentre };

/// One quarter of a tile, seen from its corner: local (x', y') in [0, half)^2 maps to the tile's
/// texel, and `along_u` and `along_v` are the edges that meet at the corner (S or N, W or E).
struct Quarter {
  bool mirror_x, mirror_y;
  Edge along_u, along_v;
};
constexpr std::array<Quarter, 4> kQuarters = {{{false, false, kSouth, kWest},
                                               {true, false, kSouth, kEast},
                                               {false, true, kNorth, kWest},
                                               {true, true, kNorth, kEast}}};

/// The minimum-error cut between the two diamonds of a quarter (Cohen et al. 2003; Efros & Freeman
/// 2001's dynamic programming): on each anti-diagonal k = x' + y' the texels with x' - y' > tau_k
/// take the edge along u, the others the edge along v. tau_k has the parity of k + 1 (it falls
/// between texels) and moves by one from k to k + 1 (the cut is connected); the boundary row and
/// column keep their own edge (tau_k in [1 - k, k - 1]), so that tiles still meet without a seam.
/// `mismatch(x', y')` is the cost of a texel whose two candidates differ; returns tau by k.
template <typename Mismatch>
std::vector<int> minimum_error_cut(int half, const Mismatch& mismatch) {
  const int last = 2 * (half - 1);
  // tau is stored shifted by `span` so that it indexes an array; INFINITY marks what is not allowed.
  const int span = last + 2;
  std::vector<std::vector<double>> best(last + 1, std::vector<double>(2 * span + 1, INFINITY));
  std::vector<std::vector<int>> from(last + 1, std::vector<int>(2 * span + 1, 0));
  auto allowed = [&](int k, int tau) {
    if (((tau + k + 1) & 1) != 0) return false;
    const int lo = 2 * std::max(0, k - (half - 1)) - k, hi = k - 2 * std::max(0, k - (half - 1));  // x' - y' on it
    return tau >= lo - 1 && tau <= hi + 1 && (k == 0 || (tau >= 1 - k && tau <= k - 1));
  };
  auto cost = [&](int k, int tau) {
    double c = 0;
    for (const int d : {tau - 1, tau + 1}) {
      if (((d + k) & 1) != 0) continue;
      const int x = (k + d) / 2, y = (k - d) / 2;
      if (x >= 0 && y >= 0 && x < half && y < half) c += mismatch(x, y);
    }
    return c;
  };
  for (int k = 0; k <= last; ++k)
    for (int tau = -span; tau <= span; ++tau) {
      if (!allowed(k, tau)) continue;
      double previous = 0;
      if (k > 0) {
        previous = INFINITY;
        for (const int p : {tau - 1, tau + 1})
          if (p >= -span && p <= span && best[k - 1][p + span] < previous) {
            previous = best[k - 1][p + span];
            from[k][tau + span] = p;
          }
      }
      if (previous < INFINITY) best[k][tau + span] = previous + cost(k, tau);
    }
  std::vector<int> tau(last + 1);
  int at = -span;
  for (int t = -span; t <= span; ++t)
    if (best[last][t + span] < best[last][at + span]) at = t;
  for (int k = last; k >= 0; --k) {
    tau[k] = at;
    if (k > 0) at = from[k][at + span];
  }
  return tau;
}

/// How deep into the tile from edge e the diamond reaches at position a along the edge, before the
/// tile's centre patch takes over: for each a, depth tau_a in [lo_a, hi_a] (texels from the edge;
/// hi_a: how many texels from the edge the edge's label holds, lo_a: the band every edge keeps,
/// clamped to hi_a), moving by at most 2 from a to a + 1 where the bounds allow (the cut stays
/// connected), minimising the seam it makes: `across(a, tau)`, the cost of the pair of texels the
/// boundary separates in column a, plus `along(a, p, tau)`, that of the pairs between columns a - 1
/// (depth p) and a (depth tau). `cut` false: tau_a = lo_a (a straight band).
template <typename Across, typename Along>
std::vector<int> centre_cut(const std::vector<int>& lo, const std::vector<int>& hi, bool cut, const Across& across,
                            const Along& along) {
  const int n = static_cast<int>(lo.size());
  if (!cut) return lo;
  int deepest = 0;
  for (int v : hi) deepest = std::max(deepest, v);
  std::vector<std::vector<double>> best(n, std::vector<double>(deepest + 1, INFINITY));
  std::vector<std::vector<int>> from(n, std::vector<int>(deepest + 1, -1));
  for (int a = 0; a < n; ++a)
    for (int t = lo[a]; t <= hi[a]; ++t) {
      double previous = 0.0;
      if (a > 0) {
        previous = INFINITY;
        for (int p = std::max(lo[a - 1], t - 2); p <= std::min(hi[a - 1], t + 2); ++p)
          if (best[a - 1][p] + along(a, p, t) < previous) {
            previous = best[a - 1][p] + along(a, p, t);
            from[a][t] = p;
          }
        if (previous == INFINITY)  // the bounds jumped: join the nearest depth of the column before
          for (int p = lo[a - 1]; p <= hi[a - 1]; ++p)
            if (best[a - 1][p] < INFINITY && (from[a][t] < 0 || std::abs(p - t) < std::abs(from[a][t] - t))) {
              previous = best[a - 1][p];
              from[a][t] = p;
            }
      }
      best[a][t] = previous + across(a, t);
    }
  std::vector<int> tau(n);
  int at = lo[n - 1];
  for (int t = lo[n - 1]; t <= hi[n - 1]; ++t)
    if (best[n - 1][t] < best[n - 1][at]) at = t;
  for (int a = n - 1; a >= 0; --a) {
    tau[a] = at;
    if (a > 0) at = from[a][at] >= 0 ? from[a][at] : lo[a - 1];
  }
  return tau;
}

}  // namespace

WangTileSet::WangTileSet(const NormalMap& input, int tile_size, std::uint32_t seed, bool cut) : tile_size_(tile_size) {
  if (input.width < 1 || input.height < 1 || input.normals.size() != static_cast<std::size_t>(input.width) * input.height)
    throw std::invalid_argument("Wang tiles: an empty or inconsistent input map");
  if (tile_size < 2 || tile_size > std::min(input.width, input.height))
    throw std::invalid_argument("Wang tiles: tile size " + std::to_string(tile_size) + "; allowed: 2 .. " +
                                std::to_string(std::min(input.width, input.height)));
  // Where in the input each edge colour's diamond is centred: [0, 1] for the edges along u, [2, 3]
  // for those along v.
  std::mt19937 random(seed);
  const auto anywhere = [&]() -> std::array<int, 2> {
    return {std::uniform_int_distribution<int>(0, input.width - 1)(random),
            std::uniform_int_distribution<int>(0, input.height - 1)(random)};
  };
  std::array<std::array<int, 2>, 4> centre{};
  for (auto& c : centre) c = anywhere();
  // And each tile's own centre patch, so that no two tiles share their interior.
  std::array<std::array<int, 2>, 16> patch{};
  for (auto& p : patch) p = anywhere();

  const int t = tile_size, half = tile_size / 2;
  normals_.resize(16 * static_cast<std::size_t>(t) * t);
  sources_.resize(normals_.size());
  for (int tile = 0; tile < 16; ++tile) {
    const std::array<int, 4> colour = {(tile >> 2) & 1, tile & 1, (tile >> 3) & 1, (tile >> 1) & 1};  // S, N, W, E
    // The texel (x, y) of edge e's diamond: offsets from the edge's midpoint into the input.
    auto source_of = [&](Edge e, int x, int y) -> std::array<int, 2> {
      if (e == kCentre)
        return {static_cast<int>(wrapped(patch[static_cast<std::size_t>(tile)][0] + x - half, input.width)),
                static_cast<int>(wrapped(patch[static_cast<std::size_t>(tile)][1] + y - half, input.height))};
      const std::array<int, 2> c = centre[(e == kSouth || e == kNorth ? 0 : 2) + colour[e]];
      const std::array<int, 2> offset = e == kSouth   ? std::array<int, 2>{x - half, y}
                                        : e == kNorth ? std::array<int, 2>{x - half, y - t}
                                        : e == kWest  ? std::array<int, 2>{x, y - half}
                                                      : std::array<int, 2>{x - t, y - half};
      return {static_cast<int>(wrapped(c[0] + offset[0], input.width)), static_cast<int>(wrapped(c[1] + offset[1], input.height))};
    };
    auto normal_of = [&](Edge e, int x, int y) -> const glm::vec3& {
      const auto s = source_of(e, x, y);
      return input.normals[static_cast<std::size_t>(s[1]) * input.width + s[0]];
    };
    // Each texel's edge: the triangle between the diagonals its centre lies in (its nearest edge;
    // ties, on a diagonal, to the edge along u), then in each quarter the minimum-error cut.
    std::vector<Edge> label(static_cast<std::size_t>(t) * t);
    for (int y = 0; y < t; ++y)
      for (int x = 0; x < t; ++x) {
        const int to_south = 2 * y + 1, to_north = 2 * (t - y) - 1, to_west = 2 * x + 1, to_east = 2 * (t - x) - 1;
        label[static_cast<std::size_t>(y) * t + x] = std::min(to_south, to_north) <= std::min(to_west, to_east)
                                                         ? (to_south <= to_north ? kSouth : kNorth)
                                                         : (to_west <= to_east ? kWest : kEast);
      }
    if (cut && half >= 2)
      for (const Quarter& q : kQuarters) {
        auto tile_x = [&](int lx) { return q.mirror_x ? t - 1 - lx : lx; };
        auto tile_y = [&](int ly) { return q.mirror_y ? t - 1 - ly : ly; };
        const std::vector<int> tau = minimum_error_cut(half, [&](int lx, int ly) {
          const glm::vec3 d = normal_of(q.along_u, tile_x(lx), tile_y(ly)) - normal_of(q.along_v, tile_x(lx), tile_y(ly));
          return static_cast<double>(glm::dot(d, d));
        });
        for (int ly = 0; ly < half; ++ly)
          for (int lx = 0; lx < half; ++lx)
            label[static_cast<std::size_t>(tile_y(ly)) * t + tile_x(lx)] = lx - ly > tau[lx + ly] ? q.along_u : q.along_v;
      }
    // The centre patch: every texel at least t / 4 texels from every edge (the core) is the tile's
    // own patch; in each edge's region the diamond keeps a band of t / 8 texels (at least one) from
    // the edge, and between band and core the boundary is again a minimum-error cut (per position
    // along the edge, the depth where the diamond gives way). Local coordinates: a along the edge,
    // b the depth from it.
    const int band = std::max(1, t / 8), core = std::max(band + 1, t / 4);
    for (const Edge e : {kSouth, kNorth, kWest, kEast}) {
      auto at = [&](int a, int b) -> std::pair<int, int> {  // (x, y) of local (a, b)
        switch (e) {
          case kSouth: return {a, b};
          case kNorth: return {a, t - 1 - b};
          case kWest: return {b, a};
          default: return {t - 1 - b, a};
        }
      };
      // region: how deep the edge's label reaches; hi: where the cut must end (the core, or the region's end).
      std::vector<int> lo(static_cast<std::size_t>(t)), hi(static_cast<std::size_t>(t)), region(static_cast<std::size_t>(t));
      for (int a = 0; a < t; ++a) {
        int depth = 0;
        while (depth < t) {
          const auto [x, y] = at(a, depth);
          if (label[static_cast<std::size_t>(y) * t + x] != e) break;
          ++depth;
        }
        region[static_cast<std::size_t>(a)] = depth;
        hi[static_cast<std::size_t>(a)] = std::min(depth, core);
        lo[static_cast<std::size_t>(a)] = std::min(band, hi[static_cast<std::size_t>(a)]);
      }
      // The seam between texel (a, b) taken from `first` and its neighbour (a2, b2) from `second`.
      auto seam = [&](Edge first, int a, int b, Edge second, int a2, int b2) {
        const auto [x, y] = at(a, b);
        const auto [x2, y2] = at(a2, b2);
        const glm::vec3 d = normal_of(first, x, y) - normal_of(second, x2, y2);
        return static_cast<double>(glm::dot(d, d));
      };
      const std::vector<int> tau = centre_cut(
          lo, hi, cut,
          [&](int a, int b) {  // the diamond's last texel of the column against the patch's first
            return b >= 1 && b < region[static_cast<std::size_t>(a)] ? seam(e, a, b - 1, kCentre, a, b) : 0.0;
          },
          [&](int a, int p, int b) {  // between the columns, the depths where one is diamond, the other patch
            double sum = 0.0;
            for (int d = std::min(p, b); d < std::max(p, b); ++d)
              if (d < region[static_cast<std::size_t>(a - 1)] && d < region[static_cast<std::size_t>(a)])
                sum += p < b ? seam(kCentre, a - 1, d, e, a, d) : seam(e, a - 1, d, kCentre, a, d);
            return sum;
          });
      for (int a = 0; a < t; ++a)
        for (int b = tau[static_cast<std::size_t>(a)]; b < region[static_cast<std::size_t>(a)]; ++b) {
          const auto [x, y] = at(a, b);
          label[static_cast<std::size_t>(y) * t + x] = kCentre;
        }
    }
    for (int y = 0; y < t; ++y)
      for (int x = 0; x < t; ++x) {
        const auto s = source_of(label[static_cast<std::size_t>(y) * t + x], x, y);
        const std::size_t at = (static_cast<std::size_t>(tile) * t + y) * t + x;
        normals_[at] = input.normals[static_cast<std::size_t>(s[1]) * input.width + s[0]];
        sources_[at] = s;
      }
  }
}

const glm::vec3& WangTileSet::texel(int t, int x, int y) const {
  return normals_[(static_cast<std::size_t>(t) * tile_size_ + y) * tile_size_ + x];
}

std::array<int, 2> WangTileSet::source(int t, int x, int y) const {
  return sources_[(static_cast<std::size_t>(t) * tile_size_ + y) * tile_size_ + x];
}

const glm::vec3& WangTileSet::surface_texel(const WangLattice& lattice, std::int64_t x, std::int64_t y) const {
  const auto i = static_cast<std::int32_t>(floor_div(x, tile_size_)), j = static_cast<std::int32_t>(floor_div(y, tile_size_));
  return texel(lattice.cell(i, j).tile(), static_cast<int>(wrapped(x, tile_size_)), static_cast<int>(wrapped(y, tile_size_)));
}

NormalMap WangTileSet::atlas() const {
  const int t = tile_size_;
  NormalMap map{.width = 4 * t, .height = 4 * t, .normals = {}, .description = "16 Wang tiles of " + std::to_string(t) + "^2"};
  map.normals.resize(static_cast<std::size_t>(map.width) * map.height);
  for (int tile = 0; tile < 16; ++tile)
    for (int y = 0; y < t; ++y)
      for (int x = 0; x < t; ++x)
        map.normals[static_cast<std::size_t>((tile >> 2) * t + y) * map.width + (tile & 3) * t + x] = texel(tile, x, y);
  return map;
}

std::array<int, 2> wang_atlas_texel(const WangTiling& tiling, std::int64_t x, std::int64_t y) {
  const std::int64_t t = tiling.tile_size, size = t * tiling.tiles;
  x = wrapped(x, size);
  y = wrapped(y, size);
  const int tile = WangLattice(tiling.seed, tiling.tiles).cell(static_cast<std::int32_t>(x / t), static_cast<std::int32_t>(y / t)).tile();
  return {static_cast<int>((tile & 3) * t + x % t), static_cast<int>((tile >> 2) * t + y % t)};
}

const glm::vec3& surface_texel(const NormalMap& map, std::int64_t x, std::int64_t y) {
  if (map.wang) {
    const auto [ax, ay] = wang_atlas_texel(*map.wang, x, y);
    return map.normals[static_cast<std::size_t>(ay) * map.width + ax];
  }
  return map.normals[static_cast<std::size_t>(wrapped(y, map.height)) * map.width + wrapped(x, map.width)];
}

NormalMap surface_window(const NormalMap& map, std::int64_t x0, std::int64_t y0, int width, int height) {
  NormalMap window{.width = width, .height = height, .normals = {}, .description = "a window of " + map.description};
  window.normals.reserve(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) window.normals.push_back(surface_texel(map, x0 + x, y0 + y));
  return window;
}

NormalMap make_wang_tiled_map(const NormalMap& input, const WangTiling& tiling) {
  const int largest = std::min(input.width, input.height);
  if (tiling.tile_size < 2 || tiling.tile_size > largest)
    throw InputError("wang_tiles.tile_size = " + std::to_string(tiling.tile_size) + ": allowed 2 .. " +
                     std::to_string(largest) + " (the input map's side)");
  if (tiling.tiles < 1) throw InputError("wang_tiles.tiles = " + std::to_string(tiling.tiles) + ": allowed >= 1");
  NormalMap map = WangTileSet(input, tiling.tile_size, tiling.seed).atlas();
  map.wang = tiling;
  map.description = "wang_tiles(tile_size=" + std::to_string(tiling.tile_size) + ", tiles=" + std::to_string(tiling.tiles) +
                    ", seed=" + std::to_string(tiling.seed) + ") of " + input.description;
  return map;
}

}  // namespace glintlab
