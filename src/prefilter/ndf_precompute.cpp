#include "prefilter/ndf_precompute.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <mutex>
#include <optional>
#include <sstream>

#include "core/error.hpp"
#include "prefilter/position_normal.hpp"
#include "scene/normal_maps/parallel_rows.hpp"

namespace glintlab {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// One group's result before it is appended to the pyramid's arrays.
struct GroupResult {
  std::vector<FootprintRecord> records;  ///< first_row relative to the group, group unset
  std::vector<float> angular;            ///< a, b, SA, SB
  std::vector<float> rows;
  double squared_error = 0.0, squared_norm = 0.0;
  std::size_t kept_blocks = 0;
  double ndf_seconds = 0.0, compress_seconds = 0.0;
  std::vector<std::pair<int, NdfImage>> kept_images;  ///< uncompressed images the stop test needs
};

std::vector<float> angular_factors(const CpFactors& f, int b, int r) {
  // a (B x R), b (B x R), then their exclusive prefix sums (B + 1) x R, accumulated in double.
  std::vector<float> out;
  out.reserve(static_cast<std::size_t>((4 * b + 2) * r));
  for (const Eigen::MatrixXf* m : {&f.a, &f.b})
    for (int i = 0; i < b; ++i)
      for (int k = 0; k < r; ++k) out.push_back((*m)(i, k));
  for (const Eigen::MatrixXf* m : {&f.a, &f.b}) {
    const std::size_t base = out.size();
    out.resize(base + static_cast<std::size_t>((b + 1) * r));
    for (int k = 0; k < r; ++k) {
      double sum = 0.0;
      for (int i = 0; i <= b; ++i) {
        out[base + static_cast<std::size_t>(i * r + k)] = static_cast<float>(sum);
        if (i < b) sum += (*m)(i, k);
      }
    }
  }
  return out;
}

}  // namespace

PrefilteredNdf empty_pyramid(const PrefilterSettings& settings, double extent, double intrinsic_roughness) {
  PrefilteredNdf out;
  out.settings = settings;
  const NdfGridChoice chosen = choose_ndf_grid(settings, extent, intrinsic_roughness);
  out.settings.ndf_resolution = chosen.resolution;
  out.settings.block_size = chosen.block_size;
  out.settings.validate();  // an explicit block_size must divide the N chosen
  out.intrinsic_roughness = intrinsic_roughness;
  out.grid = {chosen.resolution, extent};
  return out;
}

void build_levels(PrefilteredNdf& out, const PositionNormalDistribution& pnd, const ElementWindow* window,
                  glm::dvec2 shift, const LevelLayout& layout, bool stop_test) {
  const PrefilterSettings& settings = out.settings;
  const int n = out.grid.resolution, b = settings.block_size, nb = n / b, r = settings.cp.rank;
  const int g = settings.group_footprints;
  // Images of the level below that the stop test compares with (keyed by footprint index).
  std::vector<std::pair<int, NdfImage>> below;
  int below_nx = 0;
  for (int l = 0; l < settings.max_levels; ++l) {
    const std::optional<PrefilterLevel> laid = layout(l);
    if (!laid) break;
    PrefilterLevel level = *laid;
    level.groups_x = (level.nx + g - 1) / g;
    level.groups_y = (level.ny + g - 1) / g;
    level.first_footprint = static_cast<std::uint32_t>(out.footprints.size());
    level.first_group = static_cast<std::uint32_t>(out.group_offsets.size());
    const bool top = level.nx == 1 && level.ny == 1;
    // The stop test uses every `step`-th footprint of this level per axis (at most 16 x 16); they
    // keep their image, and so do the level's footprints the next level's test will need.
    const int step = std::max(1, std::max(level.nx, level.ny) / 16);
    const int next_step = std::max(1, std::max(std::max(1, level.nx / 2), std::max(1, level.ny / 2)) / 16);
    auto tested = [&](int x, int y) { return stop_test && l > 0 && x % step == 0 && y % step == 0; };
    auto needed_next = [&](int x, int y) { return stop_test && (x / 2) % next_step == 0 && (y / 2) % next_step == 0; };

    const int group_count = level.groups_x * level.groups_y;
    std::vector<GroupResult> results(static_cast<std::size_t>(group_count));
    std::ostringstream what;
    what << "prefiltering level " << l << " (" << level.nx << "x" << level.ny << " footprints, sigma "
         << level.sigma << " texels)";
    for_each_row(
        group_count, std::max(1, std::min(group_count, row_workers(64 * group_count))),
        [&](int group, int) {
          GroupResult& res = results[static_cast<std::size_t>(group)];
          const int gx = group % level.groups_x, gy = group / level.groups_x;
          std::vector<std::pair<int, NdfImage>> images;
          auto t0 = Clock::now();
          for (int y = gy * g; y < std::min(level.ny, (gy + 1) * g); ++y)
            for (int x = gx * g; x < std::min(level.nx, (gx + 1) * g); ++x) {
              const Footprint f =
                  Footprint::isotropic(level.origin + (glm::dvec2(x, y) + 0.5) * level.spacing + shift, level.sigma);
              images.emplace_back(y * level.nx + x, pnd.image(f, out.grid, window));
            }
          res.ndf_seconds = seconds_since(t0);
          // Blocks with mass, stacked along k in footprint order then bit order.
          std::vector<std::pair<std::size_t, int>> blocks;  // (image, bit)
          for (std::size_t m = 0; m < images.size(); ++m) {
            FootprintRecord rec;
            rec.first_row = static_cast<std::uint32_t>(blocks.size());
            const NdfImage& img = images[m].second;
            for (int bit = 0; bit < nb * nb; ++bit) {
              const int bx = bit % nb, by = bit / nb;
              double mass = 0.0;
              for (int j = by * b; j < (by + 1) * b; ++j)
                for (int i = bx * b; i < (bx + 1) * b; ++i) mass += img.at(i, j);
              if (mass * out.grid.pixel_area() <= settings.empty_block_mass) continue;
              (bit < 32 ? rec.mask_lo : rec.mask_hi) |= 1u << (bit % 32);
              blocks.emplace_back(m, bit);
            }
            res.records.push_back(rec);
          }
          t0 = Clock::now();
          Tensor3 x(b, b, static_cast<int>(blocks.size()));
          for (std::size_t k = 0; k < blocks.size(); ++k) {
            const NdfImage& img = images[blocks[k].first].second;
            const int bx = blocks[k].second % nb, by = blocks[k].second / nb;
            for (int i = 0; i < b; ++i)
              for (int j = 0; j < b; ++j) x.at(i, j, static_cast<int>(k)) = img.at(bx * b + i, by * b + j);
          }
          CpSettings cp = settings.cp;
          cp.seed = settings.cp.seed + static_cast<std::uint32_t>(level.first_group + group);
          const CpFactors factors = blocks.empty() ? CpFactors{} : decompose(x, cp);
          res.compress_seconds = seconds_since(t0);
          if (!blocks.empty()) {
            res.angular = angular_factors(factors, b, r);
            res.rows.resize(blocks.size() * static_cast<std::size_t>(r));
            for (std::size_t k = 0; k < blocks.size(); ++k)
              for (int q = 0; q < r; ++q) res.rows[k * r + q] = factors.c(static_cast<Eigen::Index>(k), q);
            double norm = 0.0;
            for (float v : x.values) norm += static_cast<double>(v) * v;
            res.squared_norm = norm;
            res.squared_error = factors.relative_error * factors.relative_error * norm;
          } else {
            res.angular.assign(static_cast<std::size_t>((4 * b + 2) * r), 0.0f);
          }
          res.kept_blocks = blocks.size();
          for (auto& [index, img] : images)
            if (tested(index % level.nx, index / level.nx) || needed_next(index % level.nx, index / level.nx))
              res.kept_images.emplace_back(index, std::move(img));
        },
        what.str());

    // Append the groups in order: the result does not depend on the thread count.
    std::vector<std::pair<int, NdfImage>> kept;
    double squared_error = 0.0, squared_norm = 0.0;
    out.footprints.resize(out.footprints.size() + static_cast<std::size_t>(level.nx) * level.ny);
    for (int group = 0; group < group_count; ++group) {
      GroupResult& res = results[static_cast<std::size_t>(group)];
      const auto first_row = static_cast<std::uint32_t>(out.rows.size() / static_cast<std::size_t>(r));
      const int gx = group % level.groups_x, gy = group / level.groups_x;
      std::size_t m = 0;
      for (int y = gy * g; y < std::min(level.ny, (gy + 1) * g); ++y)
        for (int x = gx * g; x < std::min(level.nx, (gx + 1) * g); ++x) {
          FootprintRecord rec = res.records[m++];
          rec.first_row += first_row;
          rec.group = level.first_group + static_cast<std::uint32_t>(group);
          out.footprints[level.first_footprint + static_cast<std::size_t>(y * level.nx + x)] = rec;
        }
      out.group_offsets.push_back(static_cast<std::uint32_t>(out.angular.size()));
      out.angular.insert(out.angular.end(), res.angular.begin(), res.angular.end());
      out.rows.insert(out.rows.end(), res.rows.begin(), res.rows.end());
      squared_error += res.squared_error;
      squared_norm += res.squared_norm;
      level.kept_blocks += res.kept_blocks;
      level.ndf_seconds += res.ndf_seconds;
      level.compress_seconds += res.compress_seconds;
      for (auto& k : res.kept_images) kept.push_back(std::move(k));
    }
    level.compression_error = squared_norm > 0 ? std::sqrt(squared_error / squared_norm) : 0.0;

    // Stop test (sec. 4.1): this level's images against the mean of the 2 x 2 footprints of the
    // level below whose centres surround each of them.
    bool converged = false;
    if (stop_test && l > 0) {
      double distance = 0.0;
      int count = 0;
      auto find = [&](int index) -> const NdfImage* {
        for (const auto& [i, img] : below)
          if (i == index) return &img;
        return nullptr;
      };
      for (const auto& [index, img] : kept) {
        const int x = index % level.nx, y = index / level.nx;
        if (!tested(x, y)) continue;
        NdfImage mean{out.grid, std::vector<float>(out.grid.pixel_count(), 0.0f)};
        int found = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const int bxi = std::min(2 * x + dx, below_nx - 1);
            const int byi = 2 * y + dy;
            if (const NdfImage* p = find(byi * below_nx + bxi)) {
              for (std::size_t q = 0; q < mean.values.size(); ++q) mean.values[q] += p->values[q];
              ++found;
            }
          }
        if (found == 0) continue;
        for (float& v : mean.values) v /= static_cast<float>(found);
        distance += relative_l2(img, mean);
        ++count;
      }
      level.distance_to_level_below = count > 0 ? distance / count : 0.0;
      converged = count > 0 && level.distance_to_level_below < settings.stop_tolerance;
    }
    out.levels.push_back(level);
    below = std::move(kept);
    below_nx = level.nx;
    if (converged || top) break;
  }
}

PrefilteredNdf precompute_prefiltered_ndf(const NormalMap& map, double intrinsic_roughness,
                                          const PrefilterSettings& settings) {
  settings.validate();
  if (map.wang) throw InputError("a map of Wang tiles has a pyramid per tile (precompute_wang_tile_pyramid)");
  const auto start = Clock::now();
  const PositionNormalDistribution pnd(map, intrinsic_roughness, settings.elements_per_texel);
  PrefilteredNdf out = empty_pyramid(settings, pnd.suggested_extent(), intrinsic_roughness);
  out.width = map.width;
  out.height = map.height;
  const int nx0 = base_footprints(map.width, settings), ny0 = base_footprints(map.height, settings);
  // Level l: the map's footprints halved l times per axis, sigma doubled; up to a single footprint.
  const LevelLayout layout = [&](int l) -> std::optional<PrefilterLevel> {
    PrefilterLevel level;
    level.nx = std::max(1, nx0 >> l);
    level.ny = std::max(1, ny0 >> l);
    level.spacing = glm::dvec2(map.width, map.height) / glm::dvec2(level.nx, level.ny);
    level.sigma = static_cast<double>(map.width) / nx0 * std::ldexp(1.0, l);
    return level;
  };
  build_levels(out, pnd, nullptr, glm::dvec2(0.0), layout, true);
  out.precompute_seconds = seconds_since(start);
  return out;
}

}  // namespace glintlab
