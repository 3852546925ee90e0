// Deng et al. 2022's pyramids on a surface of Wang tiles (src/prefilter/wang_tile_pyramids.hpp):
// the partial images of the tiles a footprint reaches add up to the footprint's image on the
// explicit surface (uncompressed: only the texels diagonal to a tile's corner differ), and the
// compressed tile pyramids answer the surface's NDF as closely as a pyramid of the explicit surface
// does, within the stored levels and past them; their mass is the footprint's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "prefilter/ndf_precompute.hpp"
#include "small_pyramid_settings.hpp"
#include "prefilter/position_normal.hpp"
#include "prefilter/wang_tile_pyramids.hpp"
#include "scene/normal_maps/wang_tiles.hpp"

namespace glintlab {
namespace {

PrefilterSettings small_settings() { return test::small_pyramid_settings(); }

constexpr double kSigmaR = 0.03;

const NormalMap& tiled() {
  static const NormalMap map = make_wang_tiled_map(generate_bumps(32, 0.25f, 48, 6, 9), {.tile_size = 8, .tiles = 4, .seed = 3});
  return map;
}

/// The surface of tiled() written out texel by texel: a plain map of the same period.
const NormalMap& explicit_surface() {
  static const NormalMap map = [] {
    const int size = tiled().surface_width();
    NormalMap m{.width = size, .height = size, .normals = {}, .description = "explicit"};
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) m.normals.push_back(surface_texel(tiled(), x, y));
    return m;
  }();
  return map;
}

const std::vector<PrefilteredNdf>& tile_pyramids() {
  static const std::vector<PrefilteredNdf> tiles = [] {
    std::vector<PrefilteredNdf> out;
    for (int t = 0; t < 16; ++t) out.push_back(precompute_wang_tile_pyramid(tiled(), t, kSigmaR, small_settings()));
    return out;
  }();
  return tiles;
}

double relative_l2(const std::vector<double>& a, const std::vector<double>& b) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    num += (a[i] - b[i]) * (a[i] - b[i]);
    den += b[i] * b[i];
  }
  return std::sqrt(num / den);
}

}  // namespace

TEST(WangTilePyramids, PartialImagesOfTheReachedTilesAddUpToTheSurfaces) {
  // Each tile's elements from its skirt where the lattice first puts it, summed over the weight of
  // the whole plane's elements: the cells' images sum to the explicit surface's image.
  const int k = 2, t = 8;
  const PositionNormalDistribution surface(explicit_surface(), kSigmaR, k);
  const NdfGrid grid{32, surface.suggested_extent()};
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int f = 0; f < 12; ++f) {
    const glm::dvec2 centre(32.0 * u(rng), 32.0 * u(rng));
    const double sigma = 0.5 + 6.0 * u(rng);
    const NdfImage truth = surface.image(Footprint::isotropic(centre, sigma), grid);
    std::vector<float> sum(grid.pixel_count(), 0.0f);
    for_each_reached_tile(tiled(), centre, sigma, k, [&](std::array<std::int64_t, 2> cell, int, glm::dvec2 local) {
      // The cell's own texels and skirt, as the pyramid of its tile reads them where it first lies.
      const NormalMap region = surface_window(tiled(), cell[0] * t - 2, cell[1] * t - 2, t + 4, t + 4);
      const PositionNormalDistribution part(region, kSigmaR, k);
      const ElementWindow window{.lo = glm::ivec2(2 * k), .hi = glm::ivec2((2 + t) * k)};
      part.accumulate_image(Footprint::isotropic(local + 2.0, sigma), grid, 1.0, sum.data(), &window);
    });
    std::vector<double> a(sum.begin(), sum.end()), b(truth.values.begin(), truth.values.end());
    worst = std::max(worst, relative_l2(a, b));
  }
  std::printf("sum of the reached cells' partial images against the surface's: worst relative L2 %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);
}

TEST(WangTilePyramids, AnswerTheSurfacesNdfAsAPyramidOfTheExplicitSurfaceDoes) {
  const PositionNormalDistribution exact(explicit_surface(), kSigmaR, 2);
  const PrefilteredNdf plain = precompute_prefiltered_ndf(explicit_surface(), kSigmaR, small_settings());
  const auto& tiles = tile_pyramids();
  const double last = tiles.front().levels.back().sigma;
  EXPECT_GE(last, 8.0);
  std::size_t bytes = 0;
  for (const PrefilteredNdf& p : tiles) {
    EXPECT_TRUE(p.partial);
    bytes += p.storage_bytes();
  }
  std::printf("16 tile pyramids %zu bytes (last level sigma %g); the explicit surface's pyramid %zu bytes\n", bytes, last,
              plain.storage_bytes());
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double e = plain.grid.extent;
  // Within the stored levels, and past the last one (a footprint wider than the tiles).
  for (const auto& [lo, hi] : {std::pair{1.0, last}, std::pair{1.5 * last, 3.0 * last}}) {
    std::vector<double> truth, ours, theirs;
    double mass = 0.0;
    for (int f = 0; f < 24; ++f) {
      const glm::dvec2 centre(32.0 * u(rng) - 16.0, 32.0 * u(rng) + 100.0);  // anywhere: the surface repeats
      const double sigma = lo * std::pow(hi / lo, u(rng));
      for (int q = 0; q < 24; ++q) {
        const glm::dvec2 s(e * (1.2 * u(rng) - 0.6), e * (1.2 * u(rng) - 0.6));
        truth.push_back(exact.density(Footprint::isotropic(centre, sigma), s));
        ours.push_back(wang_tiles_density(tiled(), tiles, centre, sigma, s));
        theirs.push_back(plain.density(centre, sigma, s));
      }
      if (f < 4) {  // the mass, by the midpoint rule over the image
        double m = 0.0;
        const int n = 48;
        const double h = 2.0 * e / n;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
            m += wang_tiles_density(tiled(), tiles, centre, sigma, glm::dvec2(-e + (i + 0.5) * h, -e + (j + 0.5) * h)) * h * h;
        mass = std::max(mass, std::abs(m - 1.0));
      }
    }
    const double wang = relative_l2(ours, truth), reference = relative_l2(theirs, truth);
    std::printf("sigma %.1f .. %.1f: relative L2 to the exact P-NDF: tile pyramids %.4f, explicit surface's pyramid %.4f; "
                "worst mass error %.4f\n",
                lo, hi, wang, reference, mass);
    EXPECT_LT(wang, 1.3 * reference + 0.02);
    EXPECT_LT(mass, 0.03);
  }
}

TEST(WangTilePyramids, RefuseAPlainMapAndATileOutOfRange) {
  EXPECT_THROW(precompute_wang_tile_pyramid(explicit_surface(), 0, kSigmaR, small_settings()), InputError);
  EXPECT_THROW(precompute_wang_tile_pyramid(tiled(), 16, kSigmaR, small_settings()), InputError);
  EXPECT_THROW(precompute_prefiltered_ndf(tiled(), kSigmaR, small_settings()), InputError);
}

}  // namespace glintlab
