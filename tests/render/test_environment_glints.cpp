// kneiphof2025 in the renderer (docs/methods.md#kneiphof2025): binomial glints under the studio
// environment. Dense glints are the split sum (conventional) pixel for pixel; sparse ones sparkle
// about it.
#include <gtest/gtest.h>

#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "glint_convergence.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

// A binomial-glints sphere (alpha 0.2) seen from the front under the studio environment, which is
// not drawn (the background stays black): `size` x `size` pixels.
TestScene glitter_sphere(double log_density, int size = 48) {
  TestScene s;
  s.film(size, size)
      .material("glitter", {{"type", "binomial-glints"},
                            {"alpha", 0.2},
                            {"log_density", log_density},
                            {"microfacet_roughness", 0.02},
                            {"f0", 0.9}})
      .sphere("glitter")
      .light("environment", {{"generator", "studio"}, {"visible", false}});
  return s;
}

TEST(EnvironmentGlints, DenseGlintsAreTheSplitSum) {
  SceneFixture dense(glitter_sphere(40.0));
  expect_matches_smooth(dense.method("kneiphof2025").specular, dense.method("conventional").specular, "kneiphof2025");
}

TEST(EnvironmentGlints, SparseGlintsSparkleAboutTheSplitSum) {
  // ln density 10: a few facets a pixel. The image is not the split sum pixel by pixel (the test
  // can fail), while each pixel's expectation is (tests/glsl/test_environment_glint_factor.cpp).
  SceneFixture sparse(glitter_sphere(10.0)), dense(glitter_sphere(40.0));
  const Image smooth = sparse.method("conventional").specular;
  EXPECT_GT(rmse(sparse.method("kneiphof2025").specular, smooth),
            20.0 * rmse(dense.method("kneiphof2025").specular, dense.method("conventional").specular));
}

}  // namespace
