// A normal map of Wang tiles in the renderer (docs/methods.md#wang-tiles): the implicit surface the
// shaders read through the hashed lattice is the explicit surface written out texel by texel (Deng
// et al. 2022's fig. 14: "identical"). The same floor rendered with the two maps gives the same
// reference and the same yan2016 image, near (texels of pixels) and far (many texels a pixel);
// what differs is only the arithmetic of the texel reads (the explicit map's bilinear is the
// texture unit's, the implicit one's the shader's own). deng2022 on the tiles' pyramids is as
// close to that yan2016 image as deng2022 on the explicit map's pyramid is. Tiny images and maps.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/image_io.hpp"
#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "normal_glints_floor.hpp"
#include "scene/normal_maps/wang_tiles.hpp"
#include "scratch_directory.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const TomlKeys kInput{{"generator", "bumps"}, {"resolution", 64}, {"alpha", 0.25}, {"waves", 48}, {"max_frequency", 8}, {"seed", 3}};
const TomlKeys kTiling{{"tile_size", 16}, {"tiles", 8}, {"seed", 5}};
// A small pyramid (the tests' precompute time), the same for the tiles and the explicit map.
const std::map<std::string, std::string> kPyramid = {{"rank", "8"}, {"ndf_resolution", "32"}, {"block_size", "8"}};

TomlKeys steel(TomlKeys normal_map, double tiling) {
  return {{"type", "normal-map-glints"}, {"intrinsic_roughness", 0.02}, {"f0", 0.9}, {"normal_map", std::move(normal_map)},
          {"normal_map_tiling", tiling}};
}

TestScene floor_of(TomlKeys normal_map, double tiling, int width, int height) {
  TestScene s;
  s.film(width, height)
      .camera({0, 0.6, 1.6}, {0, 0, -0.8}, 40)
      .material("steel", steel(std::move(normal_map), tiling))
      .plane("steel", {{"size", 4}})
      .point_light({0.3, 1.0, -1.8}, 3)
      .sphere_light({-0.5, 0.8, -1.4}, 0.06, {300, 300, 300}, {{"visible", false}});
  return s;
}

/// The Wang-tiled surface of kInput and kTiling written out texel by texel: a plain EXR map
/// (row 0 of the file is the surface's top row, v = 1).
std::filesystem::path write_explicit_surface(const std::filesystem::path& dir) {
  const Scene scene = floor_of(TomlKeys{{"generator", "bumps"}, {"resolution", 64}, {"alpha", 0.25}, {"waves", 48},
                                        {"max_frequency", 8}, {"seed", 3}, {"wang_tiles", kTiling}},
                               1, 8, 8)
                          .scene();
  const NormalMap& map = *scene.materials[0].normal_map;
  const int size = map.surface_width();
  Image image(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) image.at(x, size - 1 - y) = surface_texel(map, x, y);
  const auto file = dir / "explicit.exr";
  write_exr(file, {{"", &image}});
  return file;
}

}  // namespace

TEST(WangTilesRender, TheImplicitSurfaceRendersAsItsExplicitMap) {
  const ScratchDirectory scratch;
  const auto file = write_explicit_surface(scratch.path());
  TomlKeys implicit_map = kInput;
  implicit_map.emplace_back("wang_tiles", kTiling);
  for (const double tiling : {1.0, 6.0}) {  // about 1 texel a pixel near the camera; about 20
    SceneFixture implicit(floor_of(implicit_map, tiling, 48, 32));
    SceneFixture explicit_(floor_of(TomlKeys{{"file", file.string()}}, tiling, 48, 32));
    ASSERT_EQ(explicit_.scene.materials[0].normal_map->width, 128);
    const ReferenceFrame a = footprint_filtered_reference(implicit, 16), b = footprint_filtered_reference(explicit_, 16);
    const double scale = rmse(Image(a.mean.total.width(), a.mean.total.height()), b.mean.total);  // the image's RMS
    const double references = rmse(a.mean.total, b.mean.total);
    const std::map<std::string, std::string> k2{{"elements_per_texel", "2"}};
    const double yan = rmse(implicit.method("yan2016", k2).total, explicit_.method("yan2016", k2).total);
    const double lean = rmse(implicit.method("lean").total, explicit_.method("lean").total);
    const Image yan_image = explicit_.method("yan2016", k2).total;
    const double deng_tiles = rmse(implicit.method("deng2022", kPyramid).total, yan_image);
    const double deng_map = rmse(explicit_.method("deng2022", kPyramid).total, yan_image);
    std::printf("tiling %g: image RMS %.4f; implicit - explicit RMSE: reference %.2e (its noise %.2e), yan2016 %.2e, "
                "lean %.2e (the atlas's filtering); deng2022 - yan2016 RMSE: the tiles' pyramids %.4f, the explicit "
                "map's %.4f\n",
                tiling, scale, references, b.noise_rmse(), yan, lean, deng_tiles, deng_map);
    ASSERT_GT(scale, 0.01);
    EXPECT_LT(references, 1e-3 * scale);
    EXPECT_LT(references, 0.01 * b.noise_rmse());
    EXPECT_LT(yan, 1e-3 * scale);
    EXPECT_LT(deng_tiles, 1.3 * deng_map + 0.01 * scale);
  }
}
