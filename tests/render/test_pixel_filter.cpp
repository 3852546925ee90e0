// The reference's pixel filter (render/pixel_filter.hpp, passes/filter_gaussian.comp): the
// Gaussian keeps a constant image constant up to the film's edges, weights each sample by its
// true position (jitter included: an edge's profile equals the filter computed here from the
// pass's sample positions), keeps the image's energy, removes high frequencies as it widens, and
// leaves the reference's own error estimate right.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "core/metrics.hpp"
#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr int kSide = 16;

/// A white Lambertian plane straight below an orthographic camera under a sun overhead: a constant
/// radiance L wherever it is seen, and black elsewhere. `half` cuts it at x = 0 ("x", the film's
/// column 8 boundary: lit on the left) or at z = 0 ("z", film row 8 boundary: lit at the top).
TestScene lit_plane(const std::string& half = "") {
  const TomlValue translate = half == "x" ? TomlValue({-2, 0, 0}) : half == "z" ? TomlValue({0, 0, -2}) : TomlValue({0, 0, 0});
  return TestScene()
      .film(kSide, kSide)
      .top_down_camera()
      .material("white", {{"f0", 0}, {"diffuse", 0.5}})
      .plane("white", {{"size", 4}, {"translate", translate}})
      .directional_light({0, -1, 0}, 2.0);
}

ReferenceSettings settings(int spp, PixelFilter filter, int seed = 0) {
  ReferenceSettings s{.spp = spp, .light_samples = 0, .seed = seed};
  s.filter = filter;
  return s;
}

/// The normalised truncated Gaussian weight of the samples on the lit side (GL coordinates along
/// the axis across the edge, the lit side above `edge` when `lit_above`), averaged over the passes:
/// the filter of docs/methods.md computed independently of the shader.
double lit_fraction(const ReferenceSettings& s, int axis, int pixel_gl, double edge, bool lit_above) {
  const int k = s.subpixels();
  const double sigma = s.filter.sigma;
  const double reach = std::max(3.0 * sigma, 0.5 / k);
  double sum = 0.0;
  for (int p = 0; p < s.passes(); ++p) {
    const double jitter = reference_pass_jitter(s.seed, p)[axis];
    double lit = 0.0, all = 0.0;
    for (int i = 0; i < kSide * k; ++i) {
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

/// A glossy bumpy plane and sphere under a small light: highlights of a few pixels.
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

TEST(PixelFilter, GaussianKeepsAConstantImageConstantUpToTheFilmsEdges) {
  SceneFixture f(lit_plane());
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
TEST(PixelFilter, AnEdgeIsBlurredExactlyByTheWeightsOfTheSamplePositions) {
  for (const char* axis : {"x", "z"}) {
    SceneFixture f(lit_plane(axis));
    for (const float sigma : {0.5f, 1.2f}) {
      const ReferenceSettings s = settings(256, PixelFilter::gaussian(sigma), 3);  // 4 passes of 8 x 8
      const Frame g = f.reference_at(f.scene.camera, kSide, kSide, s).mean;
      const float l = luminance(g.total.at(0, 0));
      ASSERT_GT(l, 0.1f);
      for (int i = 0; i < kSide; ++i) {
        // "x": lit on the left of column 8 (GL x as the film's); "z": lit above row 8, which is
        // above GL row 8 (GL rows go up).
        const bool along_x = axis[0] == 'x';
        const double expected = along_x ? lit_fraction(s, 0, i, kSide / 2, false)
                                        : lit_fraction(s, 1, kSide - 1 - i, kSide / 2, true);
        const glm::vec3 c = along_x ? g.total.at(i, kSide / 2) : g.total.at(kSide / 2, i);
        EXPECT_NEAR(luminance(c) / l, expected, 2e-4) << axis << " sigma " << sigma << " pixel " << i;
      }
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
// passes' mean predicts the difference of two independent Gaussian-filtered references.
TEST(PixelFilter, NoiseEstimateOfAFilteredReferencePredictsItsError) {
  SceneFixture f(glossy_bumps());
  const ReferenceFrame a = f.reference_at(f.scene.camera, 32, 24, settings(256, PixelFilter::gaussian(0.5f), 1));
  const ReferenceFrame b = f.reference_at(f.scene.camera, 32, 24, settings(256, PixelFilter::gaussian(0.5f), 2));
  ASSERT_EQ(a.passes, 4);
  const double measured = rmse(a.mean.total, b.mean.total), predicted = std::hypot(a.noise_rmse(), b.noise_rmse());
  EXPECT_GT(predicted, 0.0);
  EXPECT_NEAR(measured / predicted, 1.0, 0.3) << measured << " vs predicted " << predicted;
}
