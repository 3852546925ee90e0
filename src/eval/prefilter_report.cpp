#include "eval/prefilter_report.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>

#include "core/atomic_file.hpp"
#include "core/cache_directory.hpp"
#include "core/error.hpp"
#include "prefilter/box_prefix_tables.hpp"
#include "prefilter/position_normal.hpp"
#include "prefilter/prefilter_cache.hpp"
#include "prefilter/wang_tile_pyramids.hpp"
#include "scene/normal_maps/wang_tiles.hpp"

namespace glintlab {

namespace {

using Clock = std::chrono::steady_clock;

/// The reconstruction's NDF image of any footprint: every pixel a box query (its exact average).
NdfImage query_image(const PrefilteredNdf& p, glm::dvec2 centre, double sigma) {
  NdfImage img{p.grid, std::vector<float>(p.grid.pixel_count())};
  const double h = p.grid.pixel_size();
  for (int j = 0; j < p.grid.resolution; ++j)
    for (int i = 0; i < p.grid.resolution; ++i) {
      const glm::dvec2 lo = p.grid.pixel_centre(i, j) - 0.5 * h;
      img.values[static_cast<std::size_t>(j) * p.grid.resolution + i] =
          static_cast<float>(p.range_mean(centre, sigma, lo, lo + h));
    }
  return img;
}

/// Relative L2 of the point query (bilinear in the NDF image, what deng2022 does for delta lights)
/// against the exact P-NDF's density at points of the square's central 60% per axis: the angular
/// grid's error, which image-to-image comparisons on the same grid cannot see (issue 30, item 5).
struct PointError {
  double squared = 0.0, truth_squared = 0.0;
  void add(const PrefilteredNdf& p, const PositionNormalDistribution& pnd, glm::dvec2 centre, double sigma,
           std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-0.6 * p.grid.extent, 0.6 * p.grid.extent);
    const Footprint footprint = Footprint::isotropic(centre, sigma);
    for (int q = 0; q < 64; ++q) {
      const glm::dvec2 s(u(rng), u(rng));
      const double exact = pnd.density(footprint, s), ours = p.density(centre, sigma, s);
      squared += (ours - exact) * (ours - exact);
      truth_squared += exact * exact;
    }
  }
  [[nodiscard]] double relative() const { return truth_squared > 0.0 ? std::sqrt(squared / truth_squared) : 0.0; }
};

nlohmann::json accuracy(const PrefilteredNdf& p, const NormalMap& map, int count) {
  const PositionNormalDistribution pnd(map, p.intrinsic_roughness, p.settings.elements_per_texel);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  nlohmann::json levels = nlohmann::json::array();
  std::printf("  accuracy against yan2016 (relative L2 of NDF images on the same grid, and of point queries\n"
              "  against the exact P-NDF; %d footprints per level):\n", count);
  std::printf("  %5s %8s %12s %12s %12s %12s %10s %12s\n", "level", "sigma", "stored", "in-between", "point, on",
              "point, btw", "mass", "query (us)");
  for (std::size_t l = 0; l < p.levels.size(); ++l) {
    const PrefilterLevel& level = p.levels[l];
    double stored = 0.0, between = 0.0, mass = 0.0, query_us = 0.0;
    PointError point_stored, point_between;
    for (int q = 0; q < count; ++q) {
      const int x = static_cast<int>(u(rng) * level.nx), y = static_cast<int>(u(rng) * level.ny);
      const glm::dvec2 centre = (glm::dvec2(x, y) + 0.5) * level.spacing;
      const NdfImage ours = p.image(level.first_footprint + static_cast<std::uint32_t>(y * level.nx + x));
      stored += relative_l2(ours, pnd.image(Footprint::isotropic(centre, level.sigma), p.grid));
      mass += ours.mass();
      point_stored.add(p, pnd, centre, level.sigma, rng);
      // Between stored centres and levels: the trilinear interpolation's error as well.
      const glm::dvec2 anywhere(u(rng) * p.width, u(rng) * p.height);
      const double sigma = level.sigma * std::pow(2.0, l + 1 < p.levels.size() ? u(rng) : 0.0);
      const auto t0 = Clock::now();
      const NdfImage queried = query_image(p, anywhere, sigma);
      query_us += std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / p.grid.pixel_count();
      between += relative_l2(queried, pnd.image(Footprint::isotropic(anywhere, sigma), p.grid));
      point_between.add(p, pnd, anywhere, sigma, rng);
    }
    levels.push_back({{"level", l}, {"sigma", level.sigma}, {"stored_error", stored / count},
                      {"interpolated_error", between / count}, {"point_error_stored", point_stored.relative()},
                      {"point_error_interpolated", point_between.relative()}, {"mass", mass / count},
                      {"box_query_microseconds", query_us / count}});
    std::printf("  %5zu %8.2f %12.4f %12.4f %12.4f %12.4f %10.4f %12.3f\n", l, level.sigma, stored / count,
                between / count, point_stored.relative(), point_between.relative(), mass / count, query_us / count);
  }
  return levels;
}

/// A Wang-tiled surface's footprint NDF image from its tiles' pyramids: every pixel a box query
/// summed over the reached cells' tiles.
NdfImage wang_query_image(const NormalMap& map, const std::vector<PrefilteredNdf>& tiles, glm::dvec2 centre, double sigma) {
  const PrefilteredNdf& any = tiles.front();
  NdfImage img{any.grid, std::vector<float>(any.grid.pixel_count(), 0.0f)};
  const double h = any.grid.pixel_size();
  for_each_reached_tile(map, centre, sigma, any.settings.elements_per_texel,
                        [&](std::array<std::int64_t, 2>, int tile, glm::dvec2 local) {
                          const PrefilteredNdf& p = tiles[static_cast<std::size_t>(tile)];
                          for (int j = 0; j < any.grid.resolution; ++j)
                            for (int i = 0; i < any.grid.resolution; ++i) {
                              const glm::dvec2 lo = any.grid.pixel_centre(i, j) - 0.5 * h;
                              img.values[static_cast<std::size_t>(j) * any.grid.resolution + i] +=
                                  static_cast<float>(p.range_mean(local, sigma, lo, lo + h));
                            }
                        });
  return img;
}

/// The report of a Wang-tiled map's 16 tile pyramids: their sums per level, and (count > 0) the
/// surface's footprint NDFs from them against the exact ones, anywhere on the surface.
nlohmann::json wang_report(const Material& m, const std::vector<PrefilteredNdf>& tiles, const PrefilterReportOptions& options,
                           double seconds) {
  const NormalMap& map = *m.normal_map;
  const PrefilteredNdf& any = tiles.front();
  std::size_t bytes = 0, tables = 0;
  double precompute = 0.0;
  for (const PrefilteredNdf& p : tiles) {
    bytes += p.storage_bytes();
    tables += box_prefix_tables_bytes(p);
    precompute += p.precompute_seconds;
  }
  std::printf("material '%s': %s, a %dx%d surface of 16 Wang tiles of %d^2, sigma_r %g\n  %s\n", m.name.c_str(),
              map.description.c_str(), map.surface_width(), map.surface_height(), map.wang->tile_size,
              any.intrinsic_roughness, options.settings.describe().c_str());
  std::printf("  a pyramid per tile: NDF images %dx%d in %dx%d blocks over |s| <= %.3f, %zu levels, %.2f MB in all "
              "(box_queries = prefix-tables adds %.2f MB on the GPU), whatever the surface's size; precompute %.1f s "
              "(this run %.1f s)\n",
              any.grid.resolution, any.grid.resolution, any.settings.block_size, any.settings.block_size, any.grid.extent,
              any.levels.size(), bytes / 1e6, tables / 1e6, precompute, seconds);
  std::printf("  %5s %8s %11s %12s %12s %10s %10s   (16 tiles' sums; CP error their mean)\n", "level", "sigma",
              "footprints", "kept blocks", "CP error", "NDF (s)", "CP (s)");
  nlohmann::json levels = nlohmann::json::array();
  for (std::size_t l = 0; l < any.levels.size(); ++l) {
    std::size_t footprints = 0, kept = 0;
    double error = 0.0, ndf = 0.0, cp = 0.0;
    for (const PrefilteredNdf& p : tiles) {
      const PrefilterLevel& v = p.levels[l];
      footprints += static_cast<std::size_t>(v.nx) * v.ny;
      kept += v.kept_blocks;
      error += v.compression_error / 16.0;
      ndf += v.ndf_seconds;
      cp += v.compress_seconds;
    }
    std::printf("  %5zu %8.2f %11zu %12zu %12.4f %10.1f %10.1f\n", l, any.levels[l].sigma, footprints, kept, error, ndf, cp);
    levels.push_back({{"sigma", any.levels[l].sigma}, {"footprints", footprints}, {"kept_blocks", kept},
                      {"compression_error", error}, {"ndf_seconds", ndf}, {"compress_seconds", cp}});
  }
  nlohmann::json entry = {{"material", m.name},
                          {"map", map.description},
                          {"wang_tiles", {{"tile_size", map.wang->tile_size}, {"tiles", map.wang->tiles}, {"seed", map.wang->seed}}},
                          {"width", map.surface_width()},
                          {"height", map.surface_height()},
                          {"settings", options.settings.describe()},
                          {"rank", any.rank()},
                          {"ndf_resolution", any.grid.resolution},
                          {"block_size", any.settings.block_size},
                          {"storage_bytes", bytes},
                          {"box_prefix_tables_bytes", tables},
                          {"precompute_seconds", precompute},
                          {"levels", levels}};
  if (options.accuracy_footprints <= 0) return entry;
  std::printf("  accuracy against yan2016 on the surface (relative L2 of NDF images; %d footprints per sigma, anywhere):\n",
              options.accuracy_footprints);
  std::printf("  %8s %12s %10s %12s\n", "sigma", "error", "mass", "query (us)");
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  nlohmann::json accuracy = nlohmann::json::array();
  for (const PrefilterLevel& level : any.levels) {
    double error = 0.0, mass = 0.0, query_us = 0.0;
    for (int q = 0; q < options.accuracy_footprints; ++q) {
      const glm::dvec2 centre(u(rng) * map.surface_width(), u(rng) * map.surface_height());
      const double sigma = level.sigma * std::pow(2.0, u(rng));
      const auto t0 = Clock::now();
      const NdfImage ours = wang_query_image(map, tiles, centre, sigma);
      query_us += std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / any.grid.pixel_count();
      error += relative_l2(ours, exact_surface_image(map, any.intrinsic_roughness, any.settings.elements_per_texel, centre,
                                                     sigma, any.grid));
      mass += ours.mass();
    }
    const double n = options.accuracy_footprints;
    std::printf("  %8.2f %12.4f %10.4f %12.3f\n", level.sigma, error / n, mass / n, query_us / n);
    accuracy.push_back({{"sigma", level.sigma}, {"error", error / n}, {"mass", mass / n}, {"box_query_microseconds", query_us / n}});
  }
  entry["accuracy"] = accuracy;
  return entry;
}

}  // namespace

void run_prefilter_report(const Scene& scene, const PrefilterReportOptions& options) {
  options.settings.validate();
  nlohmann::json out = nlohmann::json::array();
  for (const Material& m : scene.materials) {
    if (!m.is("normal-map-glints") || !m.normal_map) continue;
    const auto t0 = Clock::now();
    if (m.normal_map->wang) {
      const std::vector<PrefilteredNdf> tiles = load_or_precompute_pyramids(
          *m.normal_map, m.kind_param("intrinsic_roughness"), options.settings,
          options.use_cache ? default_table_cache_directory() : std::filesystem::path());
      out.push_back(wang_report(m, tiles, options, std::chrono::duration<double>(Clock::now() - t0).count()));
      continue;
    }
    const PrefilteredNdf p = load_or_precompute_prefiltered_ndf(
        *m.normal_map, m.kind_param("intrinsic_roughness"), options.settings,
        options.use_cache ? default_table_cache_directory() : std::filesystem::path());
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    std::printf("material '%s': %s, %dx%d, sigma_r %g\n  %s\n", m.name.c_str(), m.normal_map->description.c_str(),
                p.width, p.height, p.intrinsic_roughness, options.settings.describe().c_str());
    std::printf("  NDF images %dx%d in %dx%d blocks over |s| <= %.3f, %zu levels, %.2f MB (box_queries = "
                "prefix-tables adds %.2f MB on the GPU); precompute %.1f s (this run %.1f s)\n",
                p.grid.resolution, p.grid.resolution, p.settings.block_size, p.settings.block_size, p.grid.extent,
                p.levels.size(), p.storage_bytes() / 1e6, box_prefix_tables_bytes(p) / 1e6, p.precompute_seconds,
                seconds);
    std::printf("  %5s %8s %11s %8s %12s %12s %12s %10s %10s\n", "level", "sigma", "footprints", "groups",
                "kept blocks", "CP error", "vs below", "NDF (s)", "CP (s)");
    nlohmann::json levels = nlohmann::json::array();
    double ndf_seconds = 0.0, cp_seconds = 0.0;
    for (std::size_t l = 0; l < p.levels.size(); ++l) {
      const PrefilterLevel& v = p.levels[l];
      std::printf("  %5zu %8.2f %5dx%-5d %8d %12zu %12.4f %12.4f %10.1f %10.1f\n", l, v.sigma, v.nx, v.ny,
                  v.groups_x * v.groups_y, v.kept_blocks, v.compression_error, v.distance_to_level_below,
                  v.ndf_seconds, v.compress_seconds);
      ndf_seconds += v.ndf_seconds;
      cp_seconds += v.compress_seconds;
      levels.push_back({{"sigma", v.sigma}, {"footprints", v.nx * v.ny}, {"kept_blocks", v.kept_blocks},
                        {"compression_error", v.compression_error},
                        {"distance_to_level_below", v.distance_to_level_below}, {"ndf_seconds", v.ndf_seconds},
                        {"compress_seconds", v.compress_seconds}});
    }
    std::printf("  thread-seconds: NDF images %.1f, CP %.1f\n", ndf_seconds, cp_seconds);
    nlohmann::json entry = {{"material", m.name},
                            {"map", m.normal_map->description},
                            {"width", p.width},
                            {"height", p.height},
                            {"settings", options.settings.describe()},
                            {"rank", p.rank()},
                            {"ndf_resolution", p.grid.resolution},
                            {"block_size", p.settings.block_size},
                            {"pixel_over_sigma_r", p.grid.pixel_size() / p.intrinsic_roughness},
                            {"storage_bytes", p.storage_bytes()},
                            {"box_prefix_tables_bytes", box_prefix_tables_bytes(p)},
                            {"precompute_seconds", p.precompute_seconds},
                            {"ndf_thread_seconds", ndf_seconds},
                            {"compress_thread_seconds", cp_seconds},
                            {"levels", levels}};
    if (options.accuracy_footprints > 0) entry["accuracy"] = accuracy(p, *m.normal_map, options.accuracy_footprints);
    out.push_back(entry);
  }
  if (out.empty()) throw InputError(scene.source + ": the scene has no normal-map-glints material to prefilter; allowed: a scene with one");
  if (!options.json.empty()) write_text_file(options.json, out.dump(2) + "\n");
}

}  // namespace glintlab
