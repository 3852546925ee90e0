// The `path` reference backend against the raster reference and a shadow's closed form: where no
// shape stands between a surface and its lights, the path tracer's samples are the raster
// reference's (the same estimator, streams and sub-pixel positions; the surfaces Embree's
// interpolation instead of the rasteriser's); where one does, that light is gone.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <Eigen/Dense>
#include <glm/gtc/matrix_transform.hpp>

#include "gl_fixture.hpp"
#include "tables/dfg/dfg.hpp"
#include "tables/ltc/ltc_targets.hpp"

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
// quad, disk, sphere and environment lights, with microfacet, normal-mapped, glinty, binomial-glints
// and normal-map-glints materials: the two backends run one estimator with the same streams at the same
// sub-pixel points, so they differ only by their surfaces' float rounding (Embree's interpolation
// against the rasteriser's), far below the references' own noise, and not in energy.
TEST(PathReference, DrawsWhatTheRasterReferenceDrawsWhereNothingCastsAShadow) {
  const std::vector<std::pair<std::string, Scene>> scenes = {
      {"glint-area-lights without its sphere", keeping("glint-area-lights", [](std::size_t, const Shape& s) { return s.type != "sphere"; })},
      {"environment, its first shape", keeping("environment", [](std::size_t i, const Shape&) { return i == 0; })},
      {"every-family, its first shape", keeping("every-family", [](std::size_t i, const Shape&) { return i == 0; })},
      {"glint-sphere without its backdrop", keeping("glint-sphere", [](std::size_t, const Shape& s) { return s.type == "sphere"; })},
      {"bumpy-plane", load_scene("builtin:bumpy-plane")},
      {"normal-glints-noise", load_scene("builtin:normal-glints-noise")},
  };
  for (const auto& [name, scene] : scenes) {
    SceneFixture f(scene);
    const ReferenceFrame path = render_with(f, "path", 16, 48, 27), raster = render_with(f, "raster", 16, 48, 27);
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

namespace {

ReferenceFrame render_path(SceneFixture& f, int spp, int max_depth) {
  const auto backend = make_reference_backend("path", {shaders(), *f.gpu, *f.renderer});
  ReferenceSettings s;
  s.spp = spp;
  s.max_depth = max_depth;
  return render_reference(*backend, f.scene.camera, f.scene.film.width, f.scene.film.height, s);
}

// glintlab's microfacet BRDF (shaders/core/brdf.glsl's model) written here from its formulas: Lambert
// of albedo `a` plus GGX with the height-correlated Smith G2 and Schlick's F of f0 = 0.
double microfacet_brdf(const glm::dvec3& wo, const glm::dvec3& wi, double a, double alpha) {
  const glm::dvec3 h = glm::normalize(wo + wi);
  const double g2 = 1.0 / (1.0 + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
  return a / 3.14159265358979 + ggx_ndf(h, alpha) * g2 * std::pow(1.0 - glm::dot(wo, h), 5.0) / (4.0 * wo.z * wi.z);
}

}  // namespace

// A sphere of Lambert albedo a and f0 = 0 under a uniform environment of radiance 1: with direct
// light alone each point shows its directional albedo, a + B(n.v) (B: the specular lobe's, from
// the dfg table's own quadrature), and the background 1; a convex shape sends no light to itself,
// so more bounces change nothing at all.
TEST(PathReference, AConvexFurnaceShowsTheMaterialsAlbedo) {
  const double a = 0.6, alpha = 0.5;
  Scene scene = TestScene()
                    .film(24, 24)
                    .orthographic_camera({0, 0, 5}, {0, 0, 0}, 2.4)
                    .material("m", {{"diffuse", a}, {"f0", 0.0}, {"alpha", alpha}})
                    .sphere("m", {{"radius", 1}, {"segments", 128}})
                    .light("environment", {{"radiance", 1}})
                    .scene();
  SceneFixture f(std::move(scene));
  const ReferenceFrame direct = render_path(f, 64, 1), bounced = render_path(f, 64, 4);
  const Image stated = direct.stated_error();
  const double pixel = 2.4 / 24.0;
  int inside = 0, outside = 0;
  double sum_difference = 0, sum_variance = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      // The pixel's expected value: a + B(mu) averaged over 4 x 4 points of it (mu = n.v on the sphere).
      double expected = 0, nearest = 1e9, farthest = 0;
      for (int sy = 0; sy < 4; ++sy)
        for (int sx = 0; sx < 4; ++sx) {
          const double px = -1.2 + (x + (sx + 0.5) / 4.0) * pixel, py = 1.2 - (y + (sy + 0.5) / 4.0) * pixel;
          const double r2 = px * px + py * py;
          expected += r2 < 1.0 ? a + dfg_terms(DfgNdf::Ggx, std::sqrt(1.0 - r2), alpha).b : 0.0;
        }
      for (int cy = 0; cy <= 1; ++cy)
        for (int cx = 0; cx <= 1; ++cx) {
          const double r = std::hypot(-1.2 + (x + cx) * pixel, 1.2 - (y + cy) * pixel);
          nearest = std::min(nearest, r);
          farthest = std::max(farthest, r);
        }
      const glm::vec3 value = direct.mean.total.at(x, y);
      EXPECT_EQ(value, glm::vec3(bounced.mean.total.at(x, y))) << "a bounce off a convex shape found light, pixel " << x << ", " << y;
      if (farthest < 0.97) {  // on the sphere, away from its silhouette
        const double sigma = direct.standard_error.at(x, y).x;
        EXPECT_NEAR(value.x, expected / 16.0, 3.0 * stated.at(x, y).x + 0.01) << "pixel " << x << ", " << y;
        sum_difference += value.x - expected / 16.0;
        sum_variance += sigma * sigma;
        ++inside;
      } else if (nearest > 1.03) {
        EXPECT_NEAR(value.x, 1.0, 1e-5) << "the background, pixel " << x << ", " << y;
        ++outside;
      }
    }
  ASSERT_GT(inside, 250);
  ASSERT_GT(outside, 100);
  // The mean over the sphere's pixels, within 3 of its standard errors and the tessellation's 0.3%.
  EXPECT_LT(std::abs(sum_difference / inside), 3.0 * std::sqrt(sum_variance) / inside + 3e-3);
}

// The white furnace with interreflection: a corridor of two facing mirrors (f0 = 1, alpha 0: albedo
// exactly 1 at every angle, the only material of glintlab's whose albedo is 1) under a uniform
// environment of radiance 1. Light bouncing between the mirrors loses nothing, so a pixel is 1 once
// the path is long enough to leave the corridor and less before: with direct light alone, the
// pixels whose reflection meets the other mirror are dark; as the depth grows, every pixel is 1.
TEST(PathReference, AWhiteFurnaceOfFacingMirrorsIsOneEverywhereAsThePathsGrow) {
  Scene scene = TestScene()
                    .film(32, 18)
                    .camera({0, 0, 3}, {0, 0, -4}, 60)
                    .material("mirror", {{"diffuse", 0}, {"f0", 1}, {"alpha", 0}})
                    .plane("mirror", {{"size", 8}, {"rotate", {0, 0, -90}}, {"translate", {-0.4, 0, 0}}})
                    .plane("mirror", {{"size", 8}, {"rotate", {0, 0, 90}}, {"translate", {0.4, 0, 0}}})
                    .light("environment", {{"radiance", 1}})
                    .scene();
  SceneFixture f(std::move(scene));
  int previous_white = -1;
  for (const int depth : {1, 2, 4, 16}) {
    const ReferenceFrame frame = render_path(f, 4, depth);
    int white = 0;
    float darkest = 1, brightest = 0;
    for (int y = 0; y < 18; ++y)
      for (int x = 0; x < 32; ++x) {
        const glm::vec3 v = frame.mean.total.at(x, y);
        darkest = std::min({darkest, v.x, v.y, v.z});
        brightest = std::max({brightest, v.x, v.y, v.z});
        white += glm::all(glm::lessThan(glm::abs(v - 1.0f), glm::vec3(1e-4f)));
      }
    std::printf("white furnace, %d vertices: %d of 576 pixels 1, darkest %.4f, brightest %.6f\n", depth, white, darkest, brightest);
    EXPECT_LT(brightest, 1.0f + 1e-4f) << depth << " vertices: light from nowhere";
    EXPECT_GE(white, previous_white) << depth << " vertices";
    if (depth == 1) {
      EXPECT_LT(white, 400) << "direct light alone must miss the light that bounces between the mirrors";
      EXPECT_LT(darkest, 0.1f);
    }
    if (depth == 16) {
      EXPECT_EQ(white, 576) << "darkest " << darkest;
    }
    previous_white = white;
  }
}

// The camera at the centre of a closed sphere whose wall has Lambert albedo a, f0 = 0 and emits
// radiance E: by symmetry the radiance leaving the wall depends only on its angle to the normal,
// and light from the wall at incidence mu left the other end of the chord at the same angle, so
//   L(mu_o) = E + int_0^1 K(mu_o, mu_i) L(mu_i) mu_i dmu_i,  K = int_0^2pi f(wo, wi) dphi,
// solved here on its own grid; every camera ray meets the wall at mu_o = 1. The path tracer's
// image is that solution once its paths are long enough, and E alone without bounces.
TEST(PathReference, InsideAGlowingSphereTheRadianceIsTheInterreflectionsSolution) {
  const double a = 0.5, alpha = 0.5, emission = 1.0;
  Scene scene = TestScene()
                    .film(8, 8)
                    .camera({0, 0, 0}, {0, 0, -1}, 60)
                    .material("wall", {{"diffuse", a}, {"f0", 0.0}, {"alpha", alpha}})
                    .sphere("wall", {{"radius", 2}, {"segments", 128}})
                    .point_light({0, 10, 0})  // outside: behind every point of the wall, and shadowed by it
                    .scene();
  scene.materials[0].emission = glm::vec3(static_cast<float>(emission));

  // The integral equation by the Nystrom method: midpoints in mu and in phi.
  constexpr int kMu = 128, kPhi = 256;
  const double pi = 3.14159265358979;
  auto kernel = [&](double mu_o, double mu_i) {
    const glm::dvec3 wo(std::sqrt(1.0 - mu_o * mu_o), 0.0, mu_o);
    double sum = 0;
    for (int k = 0; k < kPhi; ++k) {
      const double phi = 2.0 * pi * (k + 0.5) / kPhi, s = std::sqrt(1.0 - mu_i * mu_i);
      sum += microfacet_brdf(wo, {s * std::cos(phi), s * std::sin(phi), mu_i}, a, alpha);
    }
    return sum * 2.0 * pi / kPhi;
  };
  Eigen::MatrixXd system = Eigen::MatrixXd::Identity(kMu, kMu);
  std::vector<double> mu(kMu);
  for (int i = 0; i < kMu; ++i) mu[static_cast<std::size_t>(i)] = (i + 0.5) / kMu;
  for (int i = 0; i < kMu; ++i)
    for (int j = 0; j < kMu; ++j) system(i, j) -= kernel(mu[i], mu[j]) * mu[j] / kMu;
  const Eigen::VectorXd wall = system.partialPivLu().solve(Eigen::VectorXd::Constant(kMu, emission));
  double truth = emission;
  for (int j = 0; j < kMu; ++j) truth += kernel(1.0, mu[j]) * mu[j] / kMu * wall(j);
  ASSERT_GT(truth, 1.5 * emission) << "the interreflections must matter";

  SceneFixture f(std::move(scene));
  const ReferenceFrame none = render_path(f, 16, 1), converged = render_path(f, 256, 24);
  double sum = 0, variance = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      EXPECT_NEAR(none.mean.total.at(x, y).x, emission, 1e-5) << "no bounce: the wall's own emission";
      sum += converged.mean.total.at(x, y).x;
      variance += std::pow(converged.standard_error.at(x, y).x, 2);
    }
  const double mean = sum / 64.0, error = std::sqrt(variance) / 64.0;
  std::printf("integrating sphere: path %.4f +- %.4f, solution %.4f\n", mean, error, truth);
  EXPECT_NEAR(mean, truth, 3.0 * error + 0.005 * truth);
}

// A glinty plane seen through a flat mirror is the same plane seen directly from the camera's
// mirror image: the ray differentials that reach it after the mirror (Igehy's reflection) are that
// camera's, so the glints (defined by the footprint) are the same glints. A footprint taken from
// the camera's distance to the point instead (the rule after rough bounces) would be half as large.
TEST(PathReference, GlintsSeenInAMirrorAreTheGlintsSeenFromTheMirroredCamera) {
  const auto base = [] {
    return TestScene()
        .film(40, 40)
        .camera({0, 0, 0}, {0, 0, -1}, 30)
        .glinty_material("glitter", {{"sigma", 0.15}, {"log_density", 12}});
  };
  // Directly: the plane 4 m away, lit by a point light beside the camera's view.
  SceneFixture direct(base()
                          .plane("glitter", {{"size", 6}, {"uv_scale", 3}, {"rotate", {90, 0, 0}}, {"translate", {0, 0, -4}}})
                          .point_light({3, 0, -2}, 100)
                          .scene());
  // Through a mirror at z = -1: the same plane and light reflected in it (z -> -2 - z), behind the camera.
  Scene mirrored = base()
                       .material("mirror", {{"diffuse", 0}, {"f0", 1}, {"alpha", 0}})
                       .plane("mirror", {{"size", 20}, {"rotate", {90, 0, 0}}, {"translate", {0, 0, -1}}})
                       .plane("glitter", {{"size", 6}, {"uv_scale", 3}, {"rotate", {90, 0, 0}}, {"translate", {0, 0, -4}}})
                       .point_light({3, 0, 0}, 100)
                       .scene();
  const glm::mat4 mirror = glm::translate(glm::mat4(1.0f), {0, 0, -1}) * glm::scale(glm::mat4(1.0f), {1, 1, -1}) *
                           glm::translate(glm::mat4(1.0f), {0, 0, 1});
  mirrored.shapes[1].transform = mirror * mirrored.shapes[1].transform;
  SceneFixture through(std::move(mirrored));
  const ReferenceFrame a = render_path(direct, 16, 1), b = render_path(through, 16, 2);
  const Agreement agree = agreement(b.mean.specular, a.mean.specular);
  std::printf("mirror: rmse %.3g of mean %.3g, energy %.4f\n", agree.rmse, agree.mean, agree.energy_ratio);
  EXPECT_GT(agree.mean, 1e-3);
  EXPECT_LT(agree.rmse, 0.05 * agree.mean);
  EXPECT_NEAR(agree.energy_ratio, 1.0, 0.01);
}

// With every shadow ray taken as unblocked (`path-unshadowed`) the path tracer runs the raster
// reference's light transport, so it draws the raster reference's samples on any scene, shadows or
// not: the two backends' physics is one.
TEST(PathReference, UnshadowedItIsTheRasterReferenceOnScenesWithShadows) {
  for (const char* name : {"spheres", "glint-area-lights"}) {
    SceneFixture f(load_scene(std::string("builtin:") + name));
    const ReferenceFrame path = render_with(f, "path-unshadowed", 16, 48, 27), raster = render_with(f, "raster", 16, 48, 27);
    const ReferenceFrame shadowed = render_with(f, "path", 16, 48, 27);
    const Agreement a = agreement(path.mean.total, raster.mean.total);
    const Agreement shadows = agreement(shadowed.mean.total, raster.mean.total);
    std::printf("%s: unshadowed rmse %.3g, energy %.5f; with shadows rmse %.3g, energy %.4f (raster noise %.3g)\n", name,
                a.rmse, a.energy_ratio, shadows.rmse, shadows.energy_ratio, raster.noise_rmse());
    EXPECT_NEAR(a.energy_ratio, 1.0, 2e-3) << name;
    EXPECT_LT(a.rmse, 0.5 * raster.noise_rmse()) << name;
    EXPECT_LT(shadows.energy_ratio, 0.99) << name << ": the scene's shadows take light away";
  }
}
