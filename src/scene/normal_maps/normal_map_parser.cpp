#include "scene/normal_maps/normal_map_parser.hpp"

#include <algorithm>
#include <optional>

#include <glm/vec3.hpp>

#include "core/available_memory.hpp"
#include "core/error.hpp"
#include "scene/normal_maps/wang_tiles.hpp"

namespace glintlab {

namespace {

/// A generator's map is built while the scene is parsed, before the run's memory estimate
/// (eval/memory_budget.hpp): one larger than the memory there is is refused before it is built.
void require_memory_for_map(const TomlReader& r, int resolution) {
  const auto available = available_memory();
  const std::uint64_t texels = static_cast<std::uint64_t>(resolution) * static_cast<std::uint64_t>(resolution);
  const std::uint64_t need = texels * (sizeof(glm::vec3) + kNormalMapTexelUploadBytes);
  if (available && need > *available)
    r.fail("resolution", "a " + std::to_string(resolution) + " x " + std::to_string(resolution) + " map needs ~" +
                             format_bytes(need) + " to build and upload; available: " + format_bytes(*available) +
                             "; allowed: a lower resolution (GLINTLAB_MEMORY_MIB sets what may be used)");
}

/// `wang_tiles = { tile_size = T, tiles = P, seed = s }`: the surface synthesised from the map's Wang tiles.
std::optional<WangTiling> parse_wang_tiling(TomlReader& r) {
  const toml::table* table = r.get_table("wang_tiles");
  if (!table) return std::nullopt;
  TomlReader w(*table, r.file(), r.context() + " wang_tiles");
  WangTiling tiling;
  tiling.tile_size = w.get_int("tile_size", 64, 2, 4096);
  tiling.tiles = w.get_int("tiles", 16, 1, 4096);
  // The seed reaches the shaders as a float (the material's parameters): exact below 2^24.
  tiling.seed = static_cast<std::uint32_t>(w.get_int("seed", 1, 0, (1 << 24) - 1));
  w.finish();
  if (static_cast<std::int64_t>(tiling.tiles) * tiling.tile_size > (1 << 23))
    w.fail("tiles", "a surface of " + std::to_string(tiling.tiles) + " x " + std::to_string(tiling.tile_size) +
                        " texels a side; allowed: at most 2^23 (texel positions exact in float)");
  return tiling;
}

/// The map the table describes: a file or a generator's.
std::shared_ptr<const NormalMap> parse_input_map(TomlReader& r, const std::filesystem::path& base_dir) {
  if (r.has("file")) {
    const auto file = r.require_string("file");
    r.finish();
    try {
      return std::make_shared<NormalMap>(load_normal_map(base_dir / file));
    } catch (const InputError& e) {
      r.fail("file", e.what());
    }
  }
  // `noise` is another name for `bumps` (isotropic random-phase noise): the same map.
  const auto generator = r.require_string("generator", {"bumps", "noise", "brushed", "scratches", "flakes"});
  const int resolution = r.get_int("resolution", 512, 4, 8192);
  require_memory_for_map(r, resolution);
  const auto seed = static_cast<std::uint32_t>(r.get_int("seed", 1, 0, 1 << 30));
  if (generator == "bumps" || generator == "noise") {
    const auto alpha = static_cast<float>(r.get_number("alpha", 0.3, 0.0, 2.0));
    const int waves = r.get_int("waves", 128, 1, 4096);
    const int max_frequency = r.get_int("max_frequency", 24, 1, resolution / 2);
    const auto anisotropy = static_cast<float>(r.get_number("anisotropy", 1.0, 1.0, 64.0));
    const auto angle = static_cast<float>(r.get_number("angle", 0.0, -360.0, 360.0));
    r.finish();
    return std::make_shared<NormalMap>(
        generate_bumps(resolution, alpha, waves, max_frequency, seed, anisotropy, angle));
  }
  if (generator == "brushed") {
    const auto alpha = static_cast<float>(r.get_number("alpha", 0.2, 0.0, 2.0));
    const auto along_alpha = static_cast<float>(r.get_number("along_alpha", 0.01, 0.0, 2.0));
    const auto angle = static_cast<float>(r.get_number("angle", 0.0, -360.0, 360.0));
    const int waves = r.get_int("waves", 512, 1, 4096);
    const int max_frequency = r.get_int("max_frequency", std::max(1, resolution / 4), 1, resolution / 2);
    r.finish();
    return std::make_shared<NormalMap>(
        generate_brushed(resolution, alpha, along_alpha, angle, waves, max_frequency, seed));
  }
  if (generator == "scratches") {
    ScratchParams p;
    p.resolution = resolution;
    p.seed = seed;
    p.count = r.get_int("count", p.count, 0, 10000);
    p.length = static_cast<float>(r.get_number("length", p.length, 0.001, 1.0));
    p.width = static_cast<float>(r.get_number("width", p.width, 0.3, 16.0));
    p.slope = static_cast<float>(r.get_number("slope", p.slope, 0.0, 5.0));
    p.angle = static_cast<float>(r.get_number("angle", p.angle, -360.0, 360.0));
    p.angle_spread = static_cast<float>(r.get_number("angle_spread", p.angle_spread, 0.0, 180.0));
    p.base_alpha = static_cast<float>(r.get_number("base_alpha", p.base_alpha, 0.0, 2.0));
    r.finish();
    return std::make_shared<NormalMap>(generate_scratches(p));
  }
  const int cells = r.get_int("cells", 32, 1, resolution);
  const auto alpha = static_cast<float>(r.get_number("alpha", 0.2, 0.0, 2.0));
  const auto jitter = static_cast<float>(r.get_number("jitter", 1.0, 0.0, 1.0));
  const auto flat_fraction = static_cast<float>(r.get_number("flat_fraction", 0.0, 0.0, 1.0));
  r.finish();
  return std::make_shared<NormalMap>(generate_flakes(resolution, cells, alpha, seed, jitter, flat_fraction));
}

}  // namespace

std::shared_ptr<const NormalMap> parse_normal_map(TomlReader r, const std::filesystem::path& base_dir) {
  const std::optional<WangTiling> wang = parse_wang_tiling(r);
  std::shared_ptr<const NormalMap> input = parse_input_map(r, base_dir);
  if (!wang) return input;
  try {
    return std::make_shared<NormalMap>(make_wang_tiled_map(*input, *wang));
  } catch (const InputError& e) {
    r.fail("wang_tiles", e.what());
  }
}

}  // namespace glintlab
