// The `path` reference backend against the raster reference and a shadow's closed form: where no
// shape stands between a surface and its lights, the path tracer's samples are the raster
// reference's (the same estimator, streams and sub-pixel positions; the surfaces Embree's
// interpolation instead of the rasteriser's); where one does, that light is gone.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

ReferenceFrame render_with(SceneFixture& f, const std::string& backend_id, int spp, int width, int height) {
  const auto backend = make_reference_backend(backend_id, {shaders(), *f.gpu, *f.renderer});
  ReferenceSettings s;
  s.spp = spp;
  return render_reference(*backend, f.scene.camera, width, height, s);
}

// The RMSE between two images, and the ratio of their means.
struct Agreement {
  double rmse = 0;
  double energy_ratio = 0;
  double mean = 0;  // of the second
};

Agreement agreement(const Image& path, const Image& raster) {
  double squares = 0, sum_path = 0, sum_raster = 0;
  const double n = 3.0 * path.width() * path.height();
  for (int y = 0; y < path.height(); ++y)
    for (int x = 0; x < path.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const double a = path.at(x, y)[c], b = raster.at(x, y)[c];
        squares += (a - b) * (a - b);
        sum_path += a;
        sum_raster += b;
      }
  return {std::sqrt(squares / n), sum_path / sum_raster, sum_raster / n};
}

// A built-in scene with only the shapes `keep` accepts (its index, its generator's type).
Scene keeping(const std::string& name, const std::function<bool(std::size_t, const Shape&)>& keep) {
  Scene scene = load_scene("builtin:" + name);
  std::vector<Shape> kept;
  for (std::size_t i = 0; i < scene.shapes.size(); ++i)
    if (keep(i, scene.shapes[i])) kept.push_back(scene.shapes[i]);
  scene.shapes = kept;
  return scene;
}

}  // namespace

// Scenes where nothing casts a shadow (one plane, or one convex shape) under point, directional,
// quad, disk, sphere and environment lights, with microfacet, normal-mapped, binomial-glints and
// normal-map-glints materials: the two backends run one estimator with the same streams at the same
// sub-pixel points, so they differ only by their surfaces' float rounding (Embree's interpolation
// against the rasteriser's), far below the references' own noise, and not in energy.
TEST(PathReference, DrawsWhatTheRasterReferenceDrawsWhereNothingCastsAShadow) {
  const std::vector<std::pair<std::string, Scene>> scenes = {
      {"glint-area-lights without its sphere", keeping("glint-area-lights", [](std::size_t, const Shape& s) { return s.type != "sphere"; })},
      {"environment, its first shape", keeping("environment", [](std::size_t i, const Shape&) { return i == 0; })},
      {"every-family, its first shape", keeping("every-family", [](std::size_t i, const Shape&) { return i == 0; })},
      {"bumpy-plane", load_scene("builtin:bumpy-plane")},
      {"normal-glints-noise", load_scene("builtin:normal-glints-noise")},
  };
  for (const auto& [name, scene] : scenes) {
    SceneFixture f(scene);
    const ReferenceFrame path = render_with(f, "path", 16, 64, 36), raster = render_with(f, "raster", 16, 64, 36);
    for (const bool specular : {false, true}) {
      const Agreement a = agreement(specular ? path.mean.specular : path.mean.total,
                                    specular ? raster.mean.specular : raster.mean.total);
      const std::string what = name + (specular ? ", specular" : ", total");
      std::printf("%s: rmse %.3g (raster noise %.3g), energy %.5f, mean %.4g\n", what.c_str(), a.rmse,
                  raster.noise_rmse(), a.energy_ratio, a.mean);
      EXPECT_GT(a.mean, 1e-3) << what;
      EXPECT_NEAR(a.energy_ratio, 1.0, 2e-3) << what;
      // Binomial glints take their grids from the sub-pixel's footprint: the rasteriser's finite
      // differences within a 2 x 2 quad, the path tracer's ray differentials; a grid's level can
      // differ where the two straddle a level's edge (a third of the noise on glint-area-lights).
      EXPECT_LT(a.rmse, 0.5 * raster.noise_rmse()) << what;
    }
  }
}

// A point light above a plane, a sphere between them: the plane's pixels inside the umbra (the cone
// from the light tangent to the sphere, in closed form) are black in the path tracer's image and lit
// in the raster reference's, which has no shadows; outside it the two are equal.
TEST(PathReference, ASpheresUmbraIsDarkAndEverythingElseIsTheRasterReference) {
  const double light_height = 2.0, centre_height = 1.0, radius = 0.25;
  SceneFixture f(TestScene()
                     .film(32, 32)
                     .top_down_camera()
                     .material("m", {{"diffuse", 0.5}, {"f0", 0.04}, {"alpha", 0.3}})
                     .plane("m", {{"size", 4}})
                     .sphere("m", {{"radius", radius}, {"segments", 96}, {"translate", {0, centre_height, 0}}})
                     .point_light({0, light_height, 0}, 1));
  const ReferenceFrame path = render_with(f, "path", 4, 32, 32), raster = render_with(f, "raster", 4, 32, 32);
  // The umbra's radius on the plane: tan of the cone's half-angle, asin(r / d), times the height.
  const double d = light_height - centre_height, half_angle = std::asin(radius / d);
  const double umbra = light_height * std::tan(half_angle);
  int dark = 0, lit = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      // The pixel's corners on the plane (column -> +x, row -> +z, over [-1, 1]^2).
      double nearest = 1e9, farthest = 0;
      for (int cy = 0; cy <= 1; ++cy)
        for (int cx = 0; cx <= 1; ++cx) {
          const double px = -1.0 + (x + cx) / 16.0, pz = -1.0 + (y + cy) / 16.0, r = std::hypot(px, pz);
          nearest = std::min(nearest, r);
          farthest = std::max(farthest, r);
        }
      const glm::vec3 a = path.mean.total.at(x, y), b = raster.mean.total.at(x, y);
      if (nearest > radius + 0.03 && farthest < umbra - 0.03) {  // the plane, seen beside the sphere, in the umbra
        EXPECT_EQ(a, glm::vec3(0.0f)) << "pixel " << x << ", " << y;
        EXPECT_GT(b.x, 0.01f) << "pixel " << x << ", " << y;
        ++dark;
      } else if (nearest > umbra + 0.03) {
        EXPECT_LT(glm::length(a - b), 1e-4f * (1.0f + glm::length(b))) << "pixel " << x << ", " << y;
        ++lit;
      }
    }
  EXPECT_GT(dark, 40);
  EXPECT_GT(lit, 500);
}
