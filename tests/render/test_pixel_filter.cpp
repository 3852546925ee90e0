// The reference's pixel filter (render/pixel_filter.hpp, passes/filter_gaussian.comp): the
// Gaussian keeps a constant image constant up to the film's edges, weights each sample by its
// true position (jitter included: an edge's profile equals the filter computed here from the
// pass's sample positions), keeps the image's energy, removes high frequencies as it widens, and
// leaves the reference's own error estimate right.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/metrics.hpp"
#include "core/pixel_filter_width.hpp"
#include "gl_fixture.hpp"
#include "render/raster_reference.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr int kSide = 16;

/// A white Lambertian plane straight below an orthographic camera under a sun overhead: a constant
/// radiance wherever it is seen.
TestScene lit_plane(int width, int height, TomlKeys plane = {{"size", 4}}) {
  return TestScene()
      .film(width, height)
      .top_down_camera()
      .material("white", {{"f0", 0}, {"diffuse", 0.5}})
      .plane("white", plane)
      .directional_light({0, -1, 0}, 2.0);
}

/// The same plane cut on the boundary before film column `edge` (axis 0: lit to its left) or film
/// row `edge` (axis 1: lit above it), black beyond.
TestScene half_lit_plane(int width, int height, int axis, int edge) {
  const double pixel = 2.0 / height;  // top_down_camera: 2 units from top to bottom; column -> +x, row -> +z
  const double at = (edge - (axis == 0 ? width : height) / 2.0) * pixel;
  return lit_plane(width, height,
                   {{"size", 100}, {"translate", axis == 0 ? TomlValue({at - 50, 0, 0}) : TomlValue({0, 0, at - 50})}});
}

ReferenceSettings settings(int spp, PixelFilter filter, int seed = 0) {
  ReferenceSettings s{.spp = spp, .light_samples = 0, .seed = seed};
  s.filter = filter;
  return s;
}

/// Pixel `pixel_gl` (GL coordinates: x as the film's, y up) along `axis` of a film `side` pixels
/// long on that axis, across an edge at `edge` pixels with the lit side above it when `lit_above`:
/// the normalised truncated Gaussian weight of the lit samples, averaged over the passes. The
/// filter of docs/methods.md, computed here independently of the shader.
double lit_fraction(const ReferenceSettings& s, int axis, int side, int pixel_gl, double edge, bool lit_above) {
  const int k = s.subpixels();
  const double sigma = s.filter.sigma;
  const double reach = std::max(3.0 * sigma, 0.5 / k);
  double sum = 0.0;
  for (int p = 0; p < s.passes(); ++p) {
    const double jitter = reference_pass_jitter(s.seed, p)[axis];
    double lit = 0.0, all = 0.0;
    for (int i = 0; i < side * k; ++i) {
      const double x = (i + jitter) / k, d = x - (pixel_gl + 0.5);
      if (std::abs(d) > reach) continue;
      const double w = std::exp(-0.5 * d * d / (sigma * sigma));
      all += w;
      if ((x > edge) == lit_above) lit += w;
    }
    sum += lit / all;
  }
  return sum / s.passes();
}

double laplacian_rms(const Image& image) {
  double sum = 0.0;
  int n = 0;
  for (int y = 1; y + 1 < image.height(); ++y)
    for (int x = 1; x + 1 < image.width(); ++x) {
      const double l = 4.0 * luminance(image.at(x, y)) - luminance(image.at(x - 1, y)) - luminance(image.at(x + 1, y)) -
                       luminance(image.at(x, y - 1)) - luminance(image.at(x, y + 1));
      sum += l * l;
      ++n;
    }
  return std::sqrt(sum / n);
}

/// A glossy bumpy plane and sphere under a small sun: highlights of a few pixels.
TestScene glossy_bumps() {
  return TestScene()
      .film(32, 24)
      .camera({0, 1.2, 3}, {0, 0.2, 0}, 35)
      .material("glossy", {{"alpha", 0.08},
                           {"f0", {0.9, 0.9, 0.9}},
                           {"diffuse", 0.1},
                           {"normal_map", TomlKeys{{"generator", "bumps"}, {"alpha", 0.15}, {"resolution", 128}}},
                           {"normal_map_tiling", 3}})
      .plane("glossy", {{"size", 4}})
      .sphere("glossy", {{"radius", 0.4}, {"translate", {0, 0.4, 0}}})
      .directional_light({0.3, -1, -0.4}, 1, {{"angular_radius", 1}});
}

}  // namespace

TEST(PixelFilter, ParsesBoxAndGaussianAndRejectsAnythingElse) {
  EXPECT_TRUE(PixelFilter::parse("box").is_box());
  const PixelFilter g = PixelFilter::parse("gaussian:0.5");
  EXPECT_EQ(g.kind, PixelFilter::Kind::gaussian);
  EXPECT_EQ(g.sigma, 0.5f);
  EXPECT_EQ(PixelFilter::parse(g.text()), g);
  EXPECT_EQ(PixelFilter::parse("gaussian:0.3").text(), "gaussian:0.3");
  EXPECT_EQ(PixelFilter().support_pixels(), 0);
  EXPECT_EQ(PixelFilter::gaussian(0.1f).support_pixels(), 1);
  EXPECT_EQ(PixelFilter::gaussian(0.5f).support_pixels(), 2);
  EXPECT_EQ(PixelFilter::gaussian(4.0f).support_pixels(), 12);
  for (const char* bad : {"gaussian:0", "gaussian:abc", "tent", "gaussian:", "gaussian:5", "gaussian:0.5px", "Box",
                          "gaussian:nan", "gaussian:-1"}) {
    try {
      (void)PixelFilter::parse(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      const std::string m = e.what();
      for (const std::string& f : {std::string("--reference-filter"), std::string(bad), std::string("box"),
                                   std::string("gaussian:S"), std::string("0.1 .. 4")})
        EXPECT_NE(m.find(f), std::string::npos) << "'" << f << "' not in: " << m;
    }
  }
}

TEST(PixelFilter, OneWidthIsTheReferencesGaussianAndTheMethodsDefaults) {
  // kPixelFilterSigma (src/core/pixel_filter_width.hpp): `gaussian` without a width, tokuyoshi's
  // sigma2 (its square) and the footprint_sigma of the normal-map glint methods; kaplanyan-beckmann
  // reads it in GLSL (PIXEL_FILTER_SIGMA: tests/glsl/test_gpu_contract.cpp, test_footprint_kernels.cpp).
  EXPECT_EQ(PixelFilter::parse("gaussian"), PixelFilter::gaussian(kPixelFilterSigma));
  EXPECT_EQ(PixelFilter::parse("gaussian").text(), "gaussian:" + pixel_filter_sigma_text());
  const auto default_of = [](const std::string& method, const std::string& param) {
    for (const ParamDecl& p : find_method(method).params)
      if (p.name == param) return p.default_value;
    ADD_FAILURE() << method << " has no parameter " << param;
    return -1.0f;
  };
  EXPECT_EQ(default_of("tokuyoshi", "sigma2"), kPixelFilterSigma * kPixelFilterSigma);
  EXPECT_EQ(default_of("yan2016", "footprint_sigma"), kPixelFilterSigma);
  EXPECT_EQ(default_of("deng2022", "footprint_sigma"), kPixelFilterSigma);
}

TEST(PixelFilter, GaussianKeepsAConstantImageConstantUpToTheFilmsEdges) {
  SceneFixture f(lit_plane(kSide, kSide));
  const Frame box = f.reference_at(f.scene.camera, kSide, kSide, settings(64, {})).mean;
  const float l = luminance(box.total.at(kSide / 2, kSide / 2));
  ASSERT_GT(l, 0.1f);
  for (const float sigma : {0.3f, 1.5f}) {  // supports of 1 and 5 pixels on a 16-pixel film
    const Frame g = f.reference_at(f.scene.camera, kSide, kSide, settings(64, PixelFilter::gaussian(sigma))).mean;
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        EXPECT_NEAR(luminance(box.total.at(x, y)), l, 1e-5f * l) << x << "," << y;
        ASSERT_NEAR(luminance(g.total.at(x, y)), l, 1e-5f * l) << "sigma " << sigma << " at " << x << "," << y;
      }
  }
}

// Across an edge the image is the filter's own profile: each pixel is the normalised weight of
// the samples on the lit side, computed here from the passes' sample positions (cell corner plus
// jitter). Wrong positions, a flipped axis or a width in sub-pixels instead of pixels all differ.
// With 32 x 32 sub-pixels a pass renders tiles of under 64 pixels: an edge on the tiles' boundary
// shows whether each tile sees its neighbour's samples.
TEST(PixelFilter, AnEdgeIsBlurredExactlyByTheWeightsOfTheSamplePositions) {
  struct Case {
    int long_side, short_side, spp, edge;
    float sigma;
  };
  // 4 passes of 8 x 8 sub-pixels on a film of one tile, or of 32 x 32 on two tiles.
  const int tile = RasterReference::tile_side(32, PixelFilter::gaussian(1.2f));
  for (const Case c : {Case{16, 2, 256, 8, 0.5f}, Case{tile + 6, 2, 4096, tile, 1.2f}})
    for (const int axis : {0, 1}) {
      const int width = axis == 0 ? c.long_side : c.short_side, height = axis == 0 ? c.short_side : c.long_side;
      SceneFixture f(half_lit_plane(width, height, axis, c.edge));
      const ReferenceSettings s = settings(c.spp, PixelFilter::gaussian(c.sigma), 3);
      const Frame g = f.reference_at(f.scene.camera, width, height, s).mean;
      const float l = luminance(g.total.at(0, 0));  // lit: left column or top row
      ASSERT_GT(l, 0.1f);
      for (int i = 0; i < c.long_side; ++i) {
        // Axis 0: lit left of the edge, GL x as the film's. Axis 1: lit above film row `edge`, which
        // is above GL row long_side - edge (GL rows go up).
        const double expected = axis == 0 ? lit_fraction(s, 0, c.long_side, i, c.edge, false)
                                          : lit_fraction(s, 1, c.long_side, c.long_side - 1 - i, c.long_side - c.edge, true);
        const glm::vec3 v = axis == 0 ? g.total.at(i, c.short_side / 2) : g.total.at(c.short_side / 2, i);
        EXPECT_NEAR(luminance(v) / l, expected, 2e-4) << "axis " << axis << " sigma " << c.sigma << " pixel " << i;
      }
    }
}

TEST(PixelFilter, GaussianKeepsTheEnergyAndRemovesHighFrequencies) {
  SceneFixture f(glossy_bumps());
  const auto reference = [&](PixelFilter filter) { return f.reference_at(f.scene.camera, 32, 24, settings(64, filter)); };
  const ReferenceFrame box = reference({});
  const auto energy = [](const ReferenceFrame& r) { return luminance(glm::vec3(r.mean.total.mean())); };
  double previous = laplacian_rms(box.mean.total);  // the box's standard deviation: 0.29 pixels
  for (const float sigma : {0.1f, 0.5f, 1.0f}) {
    const ReferenceFrame g = reference(PixelFilter::gaussian(sigma));
    // With sigma = 0.1 the filter takes the samples nearest each pixel's centre, and its image's
    // mean is the box's within their noise; wider ones average more of the same samples. (Film
    // edges weigh their samples a little differently: a margin of their noise.)
    EXPECT_NEAR(energy(g) / energy(box), 1.0, 4.0 * std::hypot(g.relative_energy_error(), box.relative_energy_error()) + 0.01)
        << "sigma " << sigma;
    if (sigma < 0.5f) continue;
    const double lap = laplacian_rms(g.mean.total);
    EXPECT_LT(lap, 0.9 * previous) << "sigma " << sigma;
    previous = lap;
  }
}

// Filtered passes are still independent and identically distributed: the standard error of the
// passes' mean predicts the difference of two independent Gaussian-filtered references. (A diffuse
// plane under a disk light sampled once per sub-pixel: noise in every pixel, none dominating.)
TEST(PixelFilter, NoiseEstimateOfAFilteredReferencePredictsItsError) {
  SceneFixture f(TestScene()
                     .film(24, 24)
                     .top_down_camera()
                     .material("white", {{"f0", 0}, {"diffuse", 0.5}})
                     .plane("white", {{"size", 4}})
                     .disk_light({0.3, 1.5, 0}, {0, -1, 0}, 1.0, 5, {{"visible", false}}));
  const auto reference = [&](PixelFilter filter, int seed) {
    ReferenceSettings s = settings(64, filter, seed);  // 4 passes of 4 x 4
    s.light_samples = 1;
    return f.reference_at(f.scene.camera, 24, 24, s);
  };
  const ReferenceFrame a = reference(PixelFilter::gaussian(0.5f), 1), b = reference(PixelFilter::gaussian(0.5f), 2);
  ASSERT_EQ(a.passes, 4);
  const double measured = rmse(a.mean.total, b.mean.total), predicted = std::hypot(a.noise_rmse(), b.noise_rmse());
  EXPECT_GT(predicted, 0.0);
  EXPECT_NEAR(measured / predicted, 1.0, 0.2) << measured << " vs predicted " << predicted;
  // It averages more samples per pixel than the box: less noise.
  EXPECT_LT(a.noise_rmse(), 0.9 * reference({}, 1).noise_rmse());
}
