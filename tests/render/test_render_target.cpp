// The render target's layouts: the renderer's (two RGBA32F colour targets) and the cheaper ones
// `glintlab bench --floor-breakdown` times the unshaded floor with, which must draw the same frame
// into fewer or narrower targets (else the breakdown would time other work).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

TEST(RenderTarget, CheaperLayoutsDrawTheSameFrame) {
  SceneFixture f(TestScene::minimal());
  const auto& method = find_method("conventional");
  const ParamValues params = resolve_params(method, {});
  const int w = f.scene.film.width, h = f.scene.film.height;
  const Frame full = f.renderer->render(method, params, f.scene.camera, w, h);
  const std::string module = method_program_module(shaders(), method, params);
  double peak = 0;
  for (const auto& p : full.total.pixels()) peak = std::max(peak, static_cast<double>(p.r));
  ASSERT_GT(peak, 0.0) << "the scene must light some pixels";

  RenderTarget half(w, h, {GL_RGBA16F, 2}), one(w, h, {GL_RGBA32F, 1}), none(w, h, {GL_RGBA32F, 0});
  for (RenderTarget* target : {&half, &one, &none}) f.renderer->draw_module(module, params, f.scene.camera, *target);
  const Image half_total = RenderTarget::read(half.total(), w, h), half_specular = RenderTarget::read(half.specular(), w, h);
  const Image one_total = RenderTarget::read(one.total(), w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec3 t = full.total.at(x, y), s = full.specular.at(x, y);
      EXPECT_EQ(one_total.at(x, y), t) << "one RGBA32F target, pixel " << x << "," << y;
      for (int c = 0; c < 3; ++c) {  // half floats: 11 significant bits
        EXPECT_NEAR(half_total.at(x, y)[c], t[c], 1e-3 * std::abs(t[c]) + 1e-6) << "RGBA16F total " << x << "," << y;
        EXPECT_NEAR(half_specular.at(x, y)[c], s[c], 1e-3 * std::abs(s[c]) + 1e-6) << "RGBA16F specular " << x << "," << y;
      }
    }
  EXPECT_EQ(one.specular(), 0u) << "one target: no specular texture";
  EXPECT_EQ(none.total(), 0u) << "depth only: no colour texture";
}

TEST(RenderTarget, RejectsAnImpossibleLayout) {
  context();
  EXPECT_THROW(RenderTarget(4, 4, TargetLayout{GL_RGBA32F, 3}), RuntimeFailure);
}
