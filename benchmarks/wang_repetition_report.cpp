// Not a benchmark: the repetition a surface of Wang tiles shows or hides, against the plain map it
// was cut from repeated over the same surface, as markdown (docs/results.md, "Wang tiles":
// tools/results.py wang-tiles). Deng et al. 2022 (sec. 5.5, figs. 15 and 21) report that a plain map
// repeated shows its period, that Wang tiles hide it, and that the tiles themselves repeat where a
// footprint is smaller than a tile; at footprints of many tiles all of it vanishes, every pixel
// seeing the same mix of normals.
//
// Measured on the exact P-NDF (Yan 2016's sum over the surface's elements, the NDF a pixel's
// footprint sees): the relative L2 between the NDF images of footprints at two places of the
// surface. Against two independent places (the surface's own variation from pixel to pixel):
//   at the input's period, plain map     0: it repeats exactly;
//   at the input's period, Wang tiles    about the variation: no repetition at that period;
//   on another cell of the same tile     0 while the footprint stays inside a tile, rising to the
//                                         variation as it spans several cells (the tiles' repetition).
// Usage: wang_repetition_report [SCENE (builtin:normal-glints-wang)] [FOOTPRINTS (16)]
#include <cmath>
#include <cstdio>
#include <random>
#include <regex>
#include <string>

#include "core/error.hpp"
#include "prefilter/position_normal.hpp"
#include "prefilter/wang_tile_pyramids.hpp"
#include "scene/normal_maps/wang_tiles.hpp"
#include "scene/scene_loader.hpp"

using namespace glintlab;

namespace {

constexpr int kElementsPerTexel = 1;

/// The exact NDF image of a footprint on a map's surface (one element per texel: the study's cost).
NdfImage exact_image(const NormalMap& map, double sigma_r, glm::dvec2 centre, double sigma, const NdfGrid& grid) {
  return exact_surface_image(map, sigma_r, kElementsPerTexel, centre, sigma, grid);
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string spec = argc > 1 ? argv[1] : "builtin:normal-glints-wang";
  const int footprints = argc > 2 ? std::max(1, std::atoi(argv[2])) : 16;
  const std::string text = spec.rfind("builtin:", 0) == 0 ? builtin_scene_toml(spec.substr(8)) : std::string();
  if (text.empty()) throw InputError(spec + ": a built-in scene with a Wang-tiled map; allowed: builtin:NAME");
  const Scene tiled = parse_scene(text, spec, ".");
  // The same scene without the Wang tiles: the input map, repeated.
  const Scene plain = parse_scene(std::regex_replace(text, std::regex(R"(,\s*wang_tiles\s*=\s*\{[^}]*\})"), ""), spec, ".");
  int m = -1;
  for (std::size_t i = 0; i < tiled.materials.size() && m < 0; ++i)
    if (tiled.materials[i].normal_map && tiled.materials[i].normal_map->wang) m = static_cast<int>(i);
  if (m < 0) throw InputError(spec + ": no material has a Wang-tiled normal map");
  const NormalMap& wang = *tiled.materials[static_cast<std::size_t>(m)].normal_map;
  const double sigma_r = tiled.materials[static_cast<std::size_t>(m)].kind_param("intrinsic_roughness");
  const NormalMap& input = *plain.materials[static_cast<std::size_t>(m)].normal_map;
  const int period = input.width, t = wang.wang->tile_size, size = wang.surface_width();
  const NdfGrid grid{32, 1.0};
  const WangLattice lattice(wang.wang->seed, wang.wang->tiles);

  std::printf("Surface %dx%d texels: 16 Wang tiles of %d^2 from a %dx%d map, against that map repeated every %d "
              "texels; %d footprints per size, exact P-NDF (%d element per texel, sigma_r %g, NDF images %dx%d).\n\n",
              size, size, t, input.width, input.height, period, footprints, kElementsPerTexel, sigma_r, grid.resolution,
              grid.resolution);
  std::printf("| footprint sigma (texels) | variation: two independent places | plain map, one period apart | "
              "Wang tiles, the same offset | Wang tiles, another cell of the same tile |\n");
  std::printf("| ---: | ---: | ---: | ---: | ---: |\n");
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const double sigma : {1.0, 4.0, 16.0, 64.0}) {
    double variation = 0.0, plain_period = 0.0, wang_period = 0.0, same_tile = 0.0;
    for (int f = 0; f < footprints; ++f) {
      const glm::dvec2 x(u(rng) * size, u(rng) * size), y(u(rng) * size, u(rng) * size);
      const NdfImage wx = exact_image(wang, sigma_r, x, sigma, grid);
      variation += relative_l2(exact_image(wang, sigma_r, y, sigma, grid), wx);
      const glm::dvec2 shift(period, 0.0);
      plain_period += relative_l2(exact_image(input, sigma_r, x + shift, sigma, grid), exact_image(input, sigma_r, x, sigma, grid));
      wang_period += relative_l2(exact_image(wang, sigma_r, x + shift, sigma, grid), wx);
      // The nearest other cell along the row (then the next rows) that holds x's cell's tile.
      const glm::ivec2 cell = glm::ivec2(glm::floor(x / static_cast<double>(t)));
      const int tile = lattice.cell(cell.x, cell.y).tile();
      glm::ivec2 other = cell;
      for (int step = 1; step < 64 * 64 && other == cell; ++step) {
        const glm::ivec2 c(cell.x + step % 64, cell.y + step / 64);
        if (lattice.cell(c.x, c.y).tile() == tile) other = c;
      }
      same_tile += relative_l2(exact_image(wang, sigma_r, x + glm::dvec2(other - cell) * static_cast<double>(t), sigma, grid), wx);
    }
    const double n = footprints;
    std::printf("| %g | %.3f | %.3f | %.3f | %.3f |\n", sigma, variation / n, plain_period / n, wang_period / n, same_tile / n);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "wang_repetition_report: %s\n", e.what());
  return 2;
}
