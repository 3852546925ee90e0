#include "prefilter/prefiltered_ndf.hpp"

#include "prefilter/position_normal.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>

#include <glm/common.hpp>

#include "core/error.hpp"
#include "prefilter/normal_field.hpp"

namespace glintlab {

namespace {

bool kept(const FootprintRecord& r, int bit) {
  return ((bit < 32 ? r.mask_lo >> bit : r.mask_hi >> (bit - 32)) & 1u) != 0;
}

/// The row of block `bit` among the footprint's kept blocks (their rows are in bit order).
std::uint32_t row_of(const FootprintRecord& r, int bit) {
  const auto below = [](std::uint32_t m, int b) { return b >= 32 ? m : (m & ((1u << b) - 1u)); };
  return r.first_row + static_cast<std::uint32_t>(std::popcount(below(r.mask_lo, bit)) +
                                                  (bit > 32 ? std::popcount(below(r.mask_hi, bit - 32)) : 0));
}

}  // namespace

std::string PrefilterSettings::describe() const {
  std::ostringstream s;
  s.precision(17);
  s << "elements_per_texel=" << elements_per_texel << " ndf_resolution=" << ndf_resolution
    << " block_size=" << block_size << " base_stride=" << base_stride
    << " group_footprints=" << group_footprints << " stop_tolerance=" << stop_tolerance
    << " max_levels=" << max_levels << " empty_block_mass=" << empty_block_mass << " rank=" << cp.rank
    << " max_iterations=" << cp.max_iterations << " tolerance=" << cp.tolerance
    << " nonnegative=" << cp.nonnegative << " seed=" << cp.seed << " restarts=" << cp.restarts;
  return s.str();
}

void PrefilterSettings::validate() const {
  auto need = [](bool ok, const std::string& name, double value, const std::string& allowed) {
    if (!ok) {
      std::ostringstream m;
      m << "prefilter setting '" << name << "' is " << value << "; allowed: " << allowed;
      throw InputError(m.str());
    }
  };
  need(elements_per_texel >= 1 && elements_per_texel <= 2, "elements_per_texel", elements_per_texel, "1 .. 2");
  need(ndf_resolution == 0 || (ndf_resolution >= 8 && ndf_resolution <= 256), "ndf_resolution", ndf_resolution,
       "0 (from sigma_r) or 8 .. 256");
  need(block_size == 0 || (block_size >= 4 && (ndf_resolution == 0 || (ndf_resolution % block_size == 0 &&
                                                                       ndf_resolution / block_size <= 8))),
       "block_size", block_size, "0 (N / 4), or a divisor of ndf_resolution, >= 4, with at most 8 blocks per side");
  need(base_stride >= 1 && base_stride <= 64, "base_stride", base_stride, "1 .. 64");
  need(group_footprints >= 1 && group_footprints <= 64, "group_footprints", group_footprints, "1 .. 64");
  need(stop_tolerance >= 0 && stop_tolerance <= 1, "stop_tolerance", stop_tolerance, "0 .. 1");
  need(max_levels >= 1 && max_levels <= 16, "max_levels", max_levels, "1 .. 16");
  need(empty_block_mass >= 0 && empty_block_mass < 1, "empty_block_mass", empty_block_mass, "0 .. 1");
  cp.validate();
}

NdfGridChoice choose_ndf_grid(const PrefilterSettings& settings, double extent, double sigma_r) {
  NdfGridChoice c{settings.ndf_resolution, settings.block_size};
  if (c.resolution == 0) {
    const double pixels = 4.0 * extent / std::max(sigma_r, 1e-6);  // 2 extent / (sigma_r / 2)
    c.resolution = std::clamp(16 * static_cast<int>(std::ceil(std::min(pixels, 256.0) / 16.0)), 32, 256);
  }
  if (c.block_size == 0) c.block_size = c.resolution / 4;
  return c;
}

std::uint64_t pyramid_bytes_bound(const PrefilterSettings& settings,
                                  const std::vector<std::array<std::uint64_t, 2>>& level_footprints, bool box_prefix_tables) {
  // Before the map's extent is known: the finest grid ndf_resolution 0 may choose.
  const NdfGridChoice grid = choose_ndf_grid(settings, 1.0, settings.ndf_resolution == 0 ? 1e-6 : 1.0);
  const std::uint64_t blocks = static_cast<std::uint64_t>(grid.resolution / grid.block_size) *
                               static_cast<std::uint64_t>(grid.resolution / grid.block_size);
  const std::uint64_t rank = static_cast<std::uint64_t>(settings.cp.rank);
  const std::uint64_t b = static_cast<std::uint64_t>(grid.block_size);
  // The header's words and the zeros that align its three value regions to vec4s
  // (src/prefilter/prefiltered_ndf_layout.hpp).
  std::uint64_t bytes = 4 * 16 + 4 * 9;
  for (const auto& [nx, ny] : level_footprints) {
    bytes += 4 * 8;  // the level's words
    const std::uint64_t footprints = nx * ny;
    const std::uint64_t g = static_cast<std::uint64_t>(settings.group_footprints);
    const std::uint64_t groups = ((nx + g - 1) / g) * ((ny + g - 1) / g);
    // A row of R floats per kept block; per group and block a, b (B x R) and their prefix sums
    // ((B + 1) x R each); a record per footprint and an offset per group.
    bytes += 4 * (footprints * blocks * rank + groups * blocks * (4 * b + 2) * rank) + sizeof(FootprintRecord) * footprints +
             4 * groups + (box_prefix_tables ? 4 * footprints * blocks * (2 * rank + 1) : 0);
  }
  return bytes;
}

std::uint64_t prefiltered_ndf_bytes_bound(const PrefilterSettings& settings, int width, int height,
                                          bool box_prefix_tables) {
  std::uint64_t nx = static_cast<std::uint64_t>(base_footprints(width, settings));
  std::uint64_t ny = static_cast<std::uint64_t>(base_footprints(height, settings));
  std::vector<std::array<std::uint64_t, 2>> levels;
  for (int level = 0; level < settings.max_levels; ++level) {
    levels.push_back({nx, ny});
    if (nx == 1 && ny == 1) break;
    nx = (nx + 1) / 2;
    ny = (ny + 1) / 2;
  }
  return pyramid_bytes_bound(settings, levels, box_prefix_tables);
}

std::size_t PrefilteredNdf::storage_bytes() const {
  return footprints.size() * sizeof(FootprintRecord) + group_offsets.size() * sizeof(std::uint32_t) +
         (angular.size() + rows.size()) * sizeof(float) + levels.size() * 16 * sizeof(float);
}

PrefilteredNdf::AngularFactors PrefilteredNdf::angular_factors(std::uint32_t footprint) const {
  const auto br = static_cast<std::size_t>(settings.block_size * rank());
  const float* a = &angular[group_offsets[footprints[footprint].group]];
  return {a, a + br, a + 2 * br, a + 3 * br + static_cast<std::size_t>(rank())};
}

const float* PrefilteredNdf::block_factor(std::uint32_t footprint, int bit) const {
  const FootprintRecord& rec = footprints[footprint];
  return kept(rec, bit) ? &rows[static_cast<std::size_t>(row_of(rec, bit)) * static_cast<std::size_t>(rank())] : nullptr;
}

double PrefilteredNdf::pixel(std::uint32_t footprint, int i, int j) const {
  const int b = settings.block_size, nb = blocks_per_side(), r = rank();
  const float* c = block_factor(footprint, (j / b) * nb + i / b);
  if (!c) return 0.0;
  const auto [a, bf, sa, sb] = angular_factors(footprint);
  double v = 0.0;
  for (int k = 0; k < r; ++k) v += static_cast<double>(a[(i % b) * r + k]) * bf[(j % b) * r + k] * c[k];
  return v;
}

NdfImage PrefilteredNdf::image(std::uint32_t footprint) const {
  NdfImage img{grid, std::vector<float>(grid.pixel_count())};
  for (int j = 0; j < grid.resolution; ++j)
    for (int i = 0; i < grid.resolution; ++i)
      img.values[static_cast<std::size_t>(j) * grid.resolution + i] = static_cast<float>(pixel(footprint, i, j));
  return img;
}

double PrefilteredNdf::pixel_range_sum(std::uint32_t footprint, glm::dvec2 x0, glm::dvec2 x1) const {
  const int b = settings.block_size, nb = blocks_per_side(), r = rank();
  const auto [a, bf, sa, sb] = angular_factors(footprint);
  // S(t) = S[floor t] + frac(t) m[floor t]: the integral of a piecewise-constant column up to t.
  auto prefix = [&](const float* sums, const float* m, double t, int k) {
    const int f = std::min(static_cast<int>(t), b - 1);
    return static_cast<double>(sums[f * r + k]) + (t - f) * m[f * r + k];
  };
  double total = 0.0;
  const int bx0 = static_cast<int>(x0.x) / b, bx1 = std::min(nb - 1, static_cast<int>(std::ceil(x1.x)) / b);
  const int by0 = static_cast<int>(x0.y) / b, by1 = std::min(nb - 1, static_cast<int>(std::ceil(x1.y)) / b);
  for (int by = by0; by <= by1; ++by)
    for (int bx = bx0; bx <= bx1; ++bx) {
      const float* c = block_factor(footprint, by * nb + bx);
      if (!c) continue;
      const double lx = std::clamp(x0.x - bx * b, 0.0, double(b)), hx = std::clamp(x1.x - bx * b, 0.0, double(b));
      const double ly = std::clamp(x0.y - by * b, 0.0, double(b)), hy = std::clamp(x1.y - by * b, 0.0, double(b));
      if (!(hx > lx && hy > ly)) continue;
      for (int k = 0; k < r; ++k)
        total += (prefix(sa, a, hx, k) - prefix(sa, a, lx, k)) * (prefix(sb, bf, hy, k) - prefix(sb, bf, ly, k)) * c[k];
    }
  return std::max(total, 0.0);
}

std::vector<PrefilteredNdf::Weighted> PrefilteredNdf::interpolation(glm::dvec2 centre, double sigma) const {
  std::vector<Weighted> out;
  const int last = static_cast<int>(levels.size()) - 1;
  if (partial && sigma > levels.back().sigma) {
    // Wider than the last level: its footprint at the tile's centre (its grid's middle), scaled.
    const PrefilterLevel& top = levels.back();
    const glm::dvec2 middle(0.5 * width, 0.5 * height);
    const double share = tile_share(middle, top.sigma);
    if (share > 0.0)
      out.push_back({top.first_footprint + static_cast<std::uint32_t>((top.ny / 2) * top.nx + top.nx / 2),
                     tile_share(centre, sigma) / share});
    return out;
  }
  const double lambda =
      std::clamp(std::log2(std::max(sigma, 1e-9) / levels.front().sigma), 0.0, static_cast<double>(last));
  const int l0 = std::min(static_cast<int>(lambda), last);
  const int l1 = std::min(l0 + 1, last);
  const double t = lambda - l0;
  for (int side = 0; side < 2; ++side) {
    const double level_weight = side == 0 ? 1.0 - t : t;
    if (level_weight <= 0.0 || (side == 1 && l1 == l0)) continue;
    const PrefilterLevel& level = levels[static_cast<std::size_t>(side == 0 ? l0 : l1)];
    const glm::dvec2 g = (centre - level.origin) / level.spacing - 0.5;
    const glm::dvec2 g0 = glm::floor(g), f = g - g0;
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const double w = level_weight * (dx ? f.x : 1 - f.x) * (dy ? f.y : 1 - f.y);
        if (w <= 0.0) continue;
        int x = static_cast<int>(g0.x) + dx, y = static_cast<int>(g0.y) + dy;
        if (partial && (x < 0 || y < 0 || x >= level.nx || y >= level.ny)) continue;  // sees none of the tile
        x = wrap_texel(x, level.nx);
        y = wrap_texel(y, level.ny);
        out.push_back({level.first_footprint + static_cast<std::uint32_t>(y * level.nx + x), w});
      }
  }
  return out;
}

double PrefilteredNdf::tile_share(glm::dvec2 centre, double sigma) const {
  const double element = position_normal_element_sigma(settings.elements_per_texel);
  const double s = std::sqrt(sigma * sigma + element * element) * std::sqrt(2.0);
  const auto along = [&](double c, double size) { return 0.5 * (std::erf((size - c) / s) - std::erf(-c / s)); };
  return along(centre.x, width) * along(centre.y, height);
}

double PrefilteredNdf::density(glm::dvec2 centre, double sigma, glm::dvec2 s) const {
  const glm::dvec2 x = grid.to_pixels(s) - 0.5;
  const glm::dvec2 x0 = glm::floor(x), f = x - x0;
  double sum = 0.0;
  for (const Weighted& w : interpolation(centre, sigma))
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const int i = static_cast<int>(x0.x) + dx, j = static_cast<int>(x0.y) + dy;
        if (i < 0 || j < 0 || i >= grid.resolution || j >= grid.resolution) continue;
        sum += w.weight * (dx ? f.x : 1 - f.x) * (dy ? f.y : 1 - f.y) * pixel(w.footprint, i, j);
      }
  return std::max(sum, 0.0);  // a CP reconstruction can dip below 0 where the NDF is near it
}

double PrefilteredNdf::range_mean(glm::dvec2 centre, double sigma, glm::dvec2 lo, glm::dvec2 hi) const {
  const double area = (hi.x - lo.x) * (hi.y - lo.y);
  if (!(area > 0)) return density(centre, sigma, 0.5 * (lo + hi));
  const double n = grid.resolution;
  const glm::dvec2 x0 = glm::clamp(grid.to_pixels(lo), 0.0, n), x1 = glm::clamp(grid.to_pixels(hi), 0.0, n);
  if (!(x1.x > x0.x && x1.y > x0.y)) return 0.0;
  double sum = 0.0;
  for (const Weighted& w : interpolation(centre, sigma)) sum += w.weight * pixel_range_sum(w.footprint, x0, x1);
  return sum * grid.pixel_area() / area;
}

// ---- serialisation: little-endian PODs, each array with its count ----

namespace {

template <typename T>
void put(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <typename T>
void put_vector(std::ostream& out, const std::vector<T>& v) {
  put<std::uint64_t>(out, v.size());
  out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}
template <typename T>
T get(std::istream& in) {
  T v{};
  if (!in.read(reinterpret_cast<char*>(&v), sizeof(T))) throw RuntimeFailure("prefiltered NDF: truncated");
  return v;
}
template <typename T>
std::vector<T> get_vector(std::istream& in) {
  const auto n = get<std::uint64_t>(in);
  // The count a file claims is checked against the bytes it holds before anything is allocated.
  const auto here = in.tellg();
  in.seekg(0, std::ios::end);
  const auto left = static_cast<std::uint64_t>(in.tellg() - here);
  in.seekg(here);
  if (n > left / sizeof(T)) throw RuntimeFailure("prefiltered NDF: an array of " + std::to_string(n) +
                                                 " entries in " + std::to_string(left) + " bytes");
  std::vector<T> v(n);
  if (!in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T))))
    throw RuntimeFailure("prefiltered NDF: truncated");
  return v;
}

bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

void PrefilteredNdf::write(std::ostream& out) const {
  put(out, settings.elements_per_texel);
  put(out, settings.ndf_resolution);
  put(out, settings.block_size);
  put(out, settings.cp.rank);
  put(out, grid.extent);
  put(out, width);
  put(out, height);
  put(out, intrinsic_roughness);
  put(out, precompute_seconds);
  put<std::uint8_t>(out, partial ? 1 : 0);
  put<std::uint64_t>(out, levels.size());
  for (const PrefilterLevel& l : levels) put(out, l);
  put_vector(out, footprints);
  put_vector(out, group_offsets);
  put_vector(out, angular);
  put_vector(out, rows);
}

PrefilteredNdf PrefilteredNdf::read(std::istream& in) {
  PrefilteredNdf p;
  p.settings.elements_per_texel = get<int>(in);
  p.settings.ndf_resolution = get<int>(in);
  p.settings.block_size = get<int>(in);
  p.settings.cp.rank = get<int>(in);
  p.grid = {p.settings.ndf_resolution, get<double>(in)};
  p.width = get<int>(in);
  p.height = get<int>(in);
  p.intrinsic_roughness = get<double>(in);
  p.precompute_seconds = get<double>(in);
  p.partial = get<std::uint8_t>(in) != 0;
  const auto level_count = get<std::uint64_t>(in);
  if (level_count < 1 || level_count > 16) throw RuntimeFailure("prefiltered NDF: bad level count");
  for (std::uint64_t i = 0; i < level_count; ++i) p.levels.push_back(get<PrefilterLevel>(in));
  p.footprints = get_vector<FootprintRecord>(in);
  p.group_offsets = get_vector<std::uint32_t>(in);
  p.angular = get_vector<float>(in);
  p.rows = get_vector<float>(in);
  p.check_consistent();
  return p;
}

void PrefilteredNdf::check_consistent() const {
  const auto fail = [](const std::string& what) { throw RuntimeFailure("prefiltered NDF: " + what); };
  const int n = settings.ndf_resolution, b = settings.block_size;
  if (n < 1 || n > 4096 || b < 1 || n % b != 0 || n / b > 8) fail("bad angular grid");
  if (rank() < 1 || rank() > 256) fail("bad rank");
  // The precompute's extent covers the projected normals, at most 1, at least 4 sigma_r (an extent
  // of 1e-100 sent a query's pixel position past int: fuzz/fuzz_pyramid.cpp).
  if (width < 1 || height < 1 || !(grid.extent >= 1e-3 && grid.extent <= 1.0) ||
      !(intrinsic_roughness >= 0.0 && intrinsic_roughness <= 1.0))
    fail("bad map size, grid extent or roughness");
  // Every level's footprints and groups follow the level below's; sizes, spacings and sigmas are
  // finite and positive, sigma growing level by level.
  std::uint64_t footprint_count = 0, group_count = 0;
  double sigma_below = 0.0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const PrefilterLevel& l = levels[i];
    const std::string level = "level " + std::to_string(i) + ": ";
    if (!finite_positive(l.sigma) || !(l.sigma > sigma_below)) fail(level + "bad sigma");
    // A map's centres tile the map: spacing = map size / footprints, as the precompute sets it (a
    // spacing of 1e-300 sent a query's grid position past every integer: fuzz/fuzz_pyramid.cpp). A
    // tile's cover the tile and reach past it by at most the footprint's reach and a spacing.
    const auto tiles = [&](double spacing, double origin, int count, int size) {
      if (!finite_positive(spacing) || !std::isfinite(origin)) return false;
      if (!partial) return origin == 0.0 && count <= size && std::abs(spacing * count - size) <= 1e-9 * size;
      const double reach = 4.0 * l.sigma + 2.0 * spacing + 4.0;
      return origin <= 0.0 && origin >= -reach && origin + spacing * count >= size && origin + spacing * count <= size + reach;
    };
    if (l.nx < 1 || l.ny < 1 || !tiles(l.spacing.x, l.origin.x, l.nx, width) || !tiles(l.spacing.y, l.origin.y, l.ny, height))
      fail(level + "bad footprint grid");
    if (l.groups_x < 1 || l.groups_y < 1 || l.groups_x > l.nx || l.groups_y > l.ny) fail(level + "bad group grid");
    if (l.first_footprint != footprint_count || l.first_group != group_count)
      fail(level + "does not start where the level below ends");
    footprint_count += static_cast<std::uint64_t>(l.nx) * static_cast<std::uint64_t>(l.ny);
    group_count += static_cast<std::uint64_t>(l.groups_x) * static_cast<std::uint64_t>(l.groups_y);
    sigma_below = l.sigma;
  }
  if (footprint_count != footprints.size()) fail("levels and footprints disagree");
  if (group_count != group_offsets.size()) fail("levels and groups disagree");
  // Every index the queries follow must land inside its array: each group's factors follow the
  // group before's (zeroed offsets would have every group read the first one's).
  const std::size_t per_group = static_cast<std::size_t>(4 * b + 2) * static_cast<std::size_t>(rank());
  if (angular.size() != group_offsets.size() * per_group) fail("angular factors and groups disagree");
  for (std::size_t g = 0; g < group_offsets.size(); ++g)
    if (group_offsets[g] != g * per_group) fail("group " + std::to_string(g) + " does not follow the one before");
  // A footprint's group is one of its own level's.
  for (const PrefilterLevel& l : levels)
    for (std::uint64_t f = l.first_footprint; f < l.first_footprint + std::uint64_t{1} * l.nx * l.ny; ++f)
      if (footprints[f].group < l.first_group ||
          footprints[f].group >= l.first_group + std::uint64_t{1} * l.groups_x * l.groups_y)
        fail("footprint " + std::to_string(f) + " belongs to another level's group");
  const int blocks = blocks_per_side() * blocks_per_side();
  for (const FootprintRecord& r : footprints) {
    const std::uint64_t mask = r.mask_lo | (static_cast<std::uint64_t>(r.mask_hi) << 32);
    if (blocks < 64 && (mask >> blocks) != 0) fail("footprint keeps a block past the grid");
    const auto kept = static_cast<std::size_t>(std::popcount(r.mask_lo) + std::popcount(r.mask_hi));
    if (r.group >= group_offsets.size() || (static_cast<std::size_t>(r.first_row) + kept) * rank() > rows.size())
      fail("footprint out of range");
  }
  for (const std::vector<float>* values : {&angular, &rows})
    for (float v : *values)
      if (!std::isfinite(v)) fail("a value is not finite");
}

}  // namespace glintlab
