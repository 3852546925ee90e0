// kneiphof2024 in the renderer (docs/methods.md#kneiphof2024): dense glints converge to the
// smooth LTC render (method, subdivided method and reference), a tiny light is the method's point
// form, subdivision keeps the mean, the method is closer to the reference than deliot2023's
// point-at-the-centre under area lights, the realisation reference (raster-realisation) against
// the counting model's, and no NaN for random lights across the horizon.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <array>
#include <random>
#include <vector>

#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "glint_convergence.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// A flat binomial-glints patch seen straight down by an orthographic camera (size x size pixels),
// lit by lights with extent above it, whose lobes spread over the patch.
// `shift` moves the plane in its own plane: the same lighting over other uv, another realisation.
TestScene area_lit_patch(double log_density, int size = 64, std::array<double, 2> shift = {0, 0}) {
  TestScene s;
  s.film(size, size)
      .orthographic_camera({0, 3, 0}, {0, 0, 0}, 2.0, {{"up", {0, 0, -1}}})
      .material("glitter", {{"type", "binomial-glints"},
                            {"alpha", 0.2},
                            {"log_density", log_density},
                            {"microfacet_roughness", 0.02},
                            {"slope_grid_scale", 12},
                            {"f0", 0.9}})
      .plane("glitter", {{"size", 4}, {"uv_scale", 2}, {"translate", {shift[0], 0, shift[1]}}})
      .light("quad", {{"position", {0.2, 1.2, 0.1}},
                      {"direction", {0, -1, 0}},
                      {"size", {0.8, 0.4}},
                      {"up", {0, 0, 1}},
                      {"radiance", {2, 1.5, 1}}})
      .disk_light({-0.5, 0.9, -0.3}, {0.3, -1, 0.2}, 0.15, {4, 5, 6});
  return s;
}

TEST(Kneiphof, DenseGlintsConvergeToTheSmoothLtcRender) {
  // ln density 40: ~1e14 facets per grid cell. `conventional` shades the smooth GGX by LTC.
  SceneFixture dense(area_lit_patch(40.0));
  const Image smooth = dense.method("conventional").specular;
  expect_matches_smooth(dense.method("kneiphof2024").specular, smooth, "kneiphof2024");
  expect_matches_smooth(dense.method("kneiphof2024", {{"subdivision", "4x4"}}).specular, smooth, "subdivided 4x4");
  // Sparse glints are not the smooth lobe pixel by pixel (the test can fail).
  SceneFixture sparse(area_lit_patch(10.0));
  EXPECT_GT(rmse(sparse.method("kneiphof2024").specular, smooth),
            5.0 * rmse(dense.method("kneiphof2024").specular, smooth));
}

TEST(Kneiphof, DenseGlintsConvergeToTheSmoothRenderInTheReference) {
  // The reference's model (p integrated over the light) against the smooth material's reference.
  SceneFixture dense(area_lit_patch(40.0, 32));
  const Image glinty = dense.reference(4).specular;
  dense.scene.materials[0].set_kind(default_material_kind());  // its smooth limit
  SceneFixture smooth(dense.scene);
  expect_matches_smooth(glinty, smooth.reference(4).specular, "reference");
}

TEST(Kneiphof, ATinyLightIsThePointFormOfItsSolidAngle) {
  // A sun of 0.05 degrees against a directional light of the same irradiance counted as a cap of
  // the sun's solid angle (pi sin^2 of its radius): the same glints, the same image.
  const double radius = 0.05, solid_angle = M_PI * std::pow(std::sin(radius * M_PI / 180), 2);
  const auto scene = [&](bool sun) {
    TestScene s;
    s.film(48, 48)
        .orthographic_camera({0, 3, 0}, {0, 0, 0}, 2.0, {{"up", {0, 0, -1}}})
        .material("glitter", {{"type", "binomial-glints"}, {"alpha", 0.15}, {"log_density", 12}, {"f0", 0.9}})
        .plane("glitter", {{"size", 4}, {"uv_scale", 2}});
    if (sun)
      s.light("sun", {{"direction", {-0.15, -1.0, -0.1}}, {"irradiance", 1}, {"angular_radius", radius}});
    else
      s.directional_light({-0.15, -1.0, -0.1}, 1);
    return s;
  };
  SceneFixture sun(scene(true)), directional(scene(false));
  const Image a = sun.method("kneiphof2024").total;
  char omega[32];
  std::snprintf(omega, sizeof omega, "%.9g", solid_angle);
  const Image b = directional.method("kneiphof2024", {{"point_light_solid_angle", omega}}).total;
  const double scale = mean_luminance(a);
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(rmse(a, b), 1e-3 * scale);
  // The material's R instead (deliot2023's count) is another image: the comparison can fail.
  EXPECT_GT(rmse(a, directional.method("kneiphof2024").total), 0.1 * scale);
}

// Pixels' specular luminance spread over its mean: how sparse and bright the glints are.
double glint_contrast(const Image& specular) {
  double sum = 0, sum2 = 0;
  for (int y = 0; y < specular.height(); ++y)
    for (int x = 0; x < specular.width(); ++x) {
      const double l = luminance(specular.at(x, y));
      sum += l;
      sum2 += l * l;
    }
  const double n = double(specular.width()) * specular.height(), mean = sum / n;
  return std::sqrt(std::max(sum2 / n - mean * mean, 0.0)) / mean;
}

TEST(Kneiphof, DeltaLightsAreCountedWithTheMaterialsR) {
  // The default (point_light_solid_angle = 0) counts a directional light's facets with the
  // material's R, as the material (and so the reference) defines its glints under delta lights;
  // the paper's sun-sized cap (6.8e-5 sr) gives a facet another p: glints of the same mean but of
  // another sparsity than the reference's. Glints of independent draws do not match pixel by
  // pixel, so the test compares their contrast (spread over mean) and energy.
  TestScene s;
  s.film(64, 64)
      .orthographic_camera({0, 3, 0}, {0, 0, 0}, 2.0, {{"up", {0, 0, -1}}})
      .material("glitter", {{"type", "binomial-glints"}, {"alpha", 0.2}, {"log_density", 13}, {"microfacet_roughness", 0.02},
                            {"slope_grid_scale", 12}, {"f0", 0.9}})
      .plane("glitter", {{"size", 4}, {"uv_scale", 2}})
      .directional_light({-0.15, -1.0, -0.1}, 3);
  SceneFixture f(s);
  const Image ref = f.reference(16).specular;
  const Image r_count = f.method("kneiphof2024").specular;
  const Image cap = f.method("kneiphof2024", {{"point_light_solid_angle", "6.8e-5"}}).specular;
  const double c_ref = glint_contrast(ref), c_r = glint_contrast(r_count), c_cap = glint_contrast(cap);
  std::printf("glint contrast (spread / mean of specular) under a directional light: reference %.3f, kneiphof2024 (R) "
              "%.3f, kneiphof2024 (6.8e-5 sr cap) %.3f; energy against the reference %.3f, %.3f\n",
              c_ref, c_r, c_cap, mean_luminance(r_count) / mean_luminance(ref), mean_luminance(cap) / mean_luminance(ref));
  // The same count as deliot2023's (the same p and numbers; the glint factor's form differs in rounding).
  EXPECT_LT(rmse(r_count, f.method("deliot2023").specular), 1e-4 * mean_luminance(ref));
  EXPECT_LT(std::abs(std::log(c_r / c_ref)), 0.5 * std::abs(std::log(c_cap / c_ref)));
}

TEST(Kneiphof, SubdivisionKeepsTheMeanAtEveryDensity) {
  // From well below one reflecting facet per pixel (ln density 8) to tens (14), over independent
  // glint realisations (the plane moved in its own plane: the same lighting, other uv): splitting
  // the reflecting facets among the quad's cells keeps their expectation, so the mean is the
  // undivided one's, and both are the dense limit's (conventional's LTC render) within noise.
  // An earlier split added +25% (2x2) and +50% (4x4) at the sparse end.
  const std::vector<std::array<double, 2>> offsets = {{0, 0}, {0.7, 0.3}, {-0.6, 0.5}, {0.4, -0.8}, {-0.3, -0.4}, {0.9, 0.9}};
  for (double log_density : {8.0, 11.0, 14.0}) {
    double whole = 0, smooth = 0, split[2] = {0, 0};
    std::vector<double> ratios;  // undivided over smooth, per realisation
    for (const auto& shift : offsets) {
      SceneFixture f(area_lit_patch(log_density, 64, shift));
      const double w = mean_luminance(f.method("kneiphof2024").specular);
      const double c = mean_luminance(f.method("conventional").specular);
      whole += w;
      smooth += c;
      ratios.push_back(w / c);
      int k = 0;
      for (const char* cells : {"2x2", "4x4"}) split[k++] += mean_luminance(f.method("kneiphof2024", {{"subdivision", cells}}).specular);
    }
    double spread = 0;
    for (double r : ratios) spread += (r - whole / smooth) * (r - whole / smooth);
    const double standard_error = std::sqrt(spread / (ratios.size() - 1) / ratios.size());
    std::printf("ln density %.0f: undivided / smooth %.4f (+- %.4f), 2x2 / undivided %.4f, 4x4 / undivided %.4f\n", log_density,
                whole / smooth, standard_error, split[0] / whole, split[1] / whole);
    EXPECT_NEAR(split[0], whole, 0.03 * whole) << "2x2 at ln density " << log_density;
    EXPECT_NEAR(split[1], whole, 0.03 * whole) << "4x4 at ln density " << log_density;
    EXPECT_NEAR(whole / smooth, 1.0, std::max(0.03, 4 * standard_error)) << "ln density " << log_density;
  }
}

TEST(Kneiphof, CloserToTheReferenceThanAPointAtTheLightsCentre) {
  // At ln density 13 a few facets reflect per cell: glints, not a lobe. The method's energy is the
  // smooth LTC render's (conventional: the LTC fit's own error) within 3%.
  SceneFixture f(area_lit_patch(13.0, 48));
  const ReferenceFrame truth = f.reference_estimate(16);
  const Image& ref = truth.mean.specular;
  const Image ours = f.method("kneiphof2024").specular;
  const double error = rmse(ours, ref), deliot = rmse(f.method("deliot2023").specular, ref);
  const double energy = mean_luminance(ours) / mean_luminance(ref);
  const double smooth = mean_luminance(f.method("conventional").specular) / mean_luminance(ref);
  std::printf("specular rmse: kneiphof2024 %.5f, deliot2023 %.5f (reference noise %.5f); energy: kneiphof2024 %.4f, "
              "conventional %.4f\n",
              error, deliot, truth.noise_rmse(), energy, smooth);
  // A ranking only if the gap is beyond twice the reference's own noise.
  EXPECT_GT(deliot - error, 2.0 * truth.noise_rmse());
  EXPECT_NEAR(energy, smooth, 0.03);
}

// The scene's reference with the raster-realisation backend: binomial-glints materials as one
// fixed microfacet realisation integrated over the lights.
Frame realisation_reference(SceneFixture& f, int spp) {
  auto backend = make_reference_backend("raster-realisation", {shaders(), *f.gpu, *f.renderer});
  ReferenceSettings settings;
  settings.spp = spp;
  return render_reference(*backend, f.scene.camera, f.scene.film.width, f.scene.film.height, settings).mean;
}

TEST(Kneiphof, TheRealisationReferenceConvergesToTheSmoothRenderAndMatchesTheCountingModelsMean) {
  // Dense: one realisation of ~1e14 facets per cell is the smooth NDF.
  SceneFixture dense(area_lit_patch(40.0, 32));
  const Image real_dense = realisation_reference(dense, 4).specular;
  dense.scene.materials[0].set_kind(default_material_kind());  // its smooth limit
  SceneFixture smooth(dense.scene);
  expect_matches_smooth(real_dense, smooth.reference(4).specular, "realisation reference");
  // Sparse: the two references are two models of the same surface; same mean, other glints.
  SceneFixture f(area_lit_patch(13.0, 48));
  const Image counting = f.reference(16).specular, real = realisation_reference(f, 16).specular;
  const Image ours = f.method("kneiphof2024").specular;
  const double mean = mean_luminance(counting);
  std::printf("references at ln density 13: mean realisation / counting %.4f; rmse between them %.5f (%.1f%% of "
              "the mean); kneiphof2024 rmse against counting %.5f, against realisation %.5f\n",
              mean_luminance(real) / mean, rmse(real, counting), 100 * rmse(real, counting) / mean, rmse(ours, counting),
              rmse(ours, real));
  EXPECT_NEAR(mean_luminance(real), mean, 0.05 * mean);
  EXPECT_GT(rmse(real, counting), 0.0);
}

TEST(Kneiphof, FiniteForRandomLightsAcrossTheHorizon) {
  // Lights of every kind with extent, random sizes and places, many crossing the plane's horizon
  // or behind it; random roughness and density; the method (each subdivision) and the reference.
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 4; ++trial) {
    TestScene s;
    s.film(24, 24)
        .camera({0.3, 1.0 + u(rng), 2.0}, {0, 0, 0}, 50)
        .material("glitter", {{"type", "binomial-glints"},
                              {"alpha", 0.01 + 0.9 * u(rng)},
                              {"log_density", 30 * u(rng)},
                              {"density_randomization", 2 * u(rng)}})
        .plane("glitter", {{"size", 6}, {"uv_scale", 3}})
        .sphere("glitter", {{"radius", 0.4}, {"translate", {0, 0.3, 0}}});
    const auto place = [&] { return TomlValue{4 * u(rng) - 2, 0.6 * u(rng) - 0.2, 4 * u(rng) - 2}; };
    s.light("quad", {{"position", place()}, {"direction", {u(rng) - 0.5, -u(rng), u(rng) - 0.5}}, {"size", {3 * u(rng), 2 * u(rng)}}})
        .disk_light(place(), {u(rng) - 0.5, u(rng) - 0.8, u(rng) - 0.5}, 1.5 * u(rng) + 1e-3, 3)
        .sphere_light(place(), 0.8 * u(rng) + 1e-3, 3)
        .light("sun", {{"direction", {u(rng) - 0.5, 0.2 * u(rng) - 0.15, u(rng) - 0.5}}, {"angular_radius", 20 * u(rng)}});
    SceneFixture f(s);
    for (const char* cells : {"none", "4x4"})
      EXPECT_EQ(f.method("kneiphof2024", {{"subdivision", cells}}).total.count_non_finite(), 0u) << trial << " " << cells;
    EXPECT_EQ(f.reference(4).total.count_non_finite(), 0u) << trial;
  }
}

}  // namespace
