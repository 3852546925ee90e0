// Image tests of the specular anti-aliasing family: the limit where there is nothing to filter,
// and the point of the methods, lower error and flicker than `conventional` against ground truth
// on small versions of the built-in aliasing scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/metrics.hpp"
#include "gl_fixture.hpp"
#include "sequence_metrics.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const std::vector<std::string> kFilteringMethods = {"toksvig",       "vlachos",       "kaplanyan-beckmann", "kaplanyan-rect",
                                                    "kaplanyan-ggx", "tokuyoshi",     "lean"};

}  // namespace

TEST(SpecularAA, WithoutAFootprintEveryMethodEqualsConventional) {
  // A flat plane seen by an orthographic camera under a delta directional light and a sun: view,
  // light and normal are the same at every pixel, so every derivative is zero, and there is no
  // normal map. Every filtering method must reproduce `conventional` to float precision.
  SceneFixture f(TestScene()
                     .film(24, 24)
                     .orthographic_camera({0.3, 4, 3}, {0, 0, 0}, 2)
                     .material("glossy", {{"ndf", "ggx"}, {"alpha", {0.05, 0.12}}, {"f0", 0.9}, {"diffuse", 0.1}})
                     .material("beckmann", {{"ndf", "beckmann"}, {"alpha", 0.08}, {"f0", 0.5}})
                     .plane("glossy", {{"size", 8}})
                     .plane("beckmann", {{"size", 8}, {"translate", {0, -0.01, 4}}})
                     .directional_light({-0.1, -0.8, 0.6}, 2)
                     .directional_light({0.05, -0.6, 0.8}, 1, {{"angular_radius", 2}}));
  const Frame base = f.method("conventional");
  ASSERT_GT(base.specular.mean().x, 0.01) << "the test scene must show a highlight";
  for (const auto& id : kFilteringMethods) {
    const Frame m = f.method(id);
    EXPECT_LT(max_abs_error(m.total, base.total), 1e-5 * (1.0 + max_abs_error(base.total, Image(24, 24))))
        << id << " differs from conventional with zero footprint";
  }
}

namespace {

enum class Claim { Better, Equal, RmseOnly };

void check(const std::string& scene, const std::map<std::string, Claim>& claims) {
  std::vector<std::string> ids{"conventional"};
  ids.insert(ids.end(), kFilteringMethods.begin(), kFilteringMethods.end());
  const auto measured = measure_sequence(scene, 6, ids);
  const Measured base = measured.at("conventional");
  for (const auto& [id, claim] : claims) {
    const Measured m = measured.at(id);
    const std::string what = id + " on builtin:" + scene + ": rmse " + std::to_string(m.rmse) + " vs " +
                             std::to_string(base.rmse) + ", flicker " + std::to_string(m.flicker) + " vs " +
                             std::to_string(base.flicker);
    if (claim == Claim::Equal) {
      EXPECT_NEAR(m.rmse, base.rmse, 1e-6 * base.rmse) << what;
      continue;
    }
    EXPECT_LT(m.rmse, base.rmse) << what;
    if (claim == Claim::Better) {
      EXPECT_LT(m.flicker, base.flicker) << what;
    }
  }
}

}  // namespace

// The claims below are the ones docs/results.md reports; where a method is not claimed to win,
// the reason is given there (normal-map methods on scenes without normal maps, geometric methods
// on a flat normal-mapped plane, half-vector derivatives on sub-pixel tubes).
TEST(SpecularAA, FilteringBeatsConventionalOnCurvedSpheres) {
  check("spheres", {{"toksvig", Claim::Equal},
                    {"vlachos", Claim::Better},
                    {"kaplanyan-beckmann", Claim::Better},
                    {"kaplanyan-rect", Claim::Better},
                    {"kaplanyan-ggx", Claim::Better},
                    {"tokuyoshi", Claim::Better},
                    {"lean", Claim::Equal}});
}

TEST(SpecularAA, FilteringBeatsConventionalOnThinTubes) {
  check("tubes", {{"toksvig", Claim::Equal},
                  {"vlachos", Claim::Better},
                  {"kaplanyan-beckmann", Claim::RmseOnly},
                  {"kaplanyan-rect", Claim::Better},
                  {"kaplanyan-ggx", Claim::RmseOnly},
                  {"tokuyoshi", Claim::Better},
                  {"lean", Claim::Equal}});
}

TEST(SpecularAA, FilteringBeatsConventionalOnANormalMappedPlane) {
  check("bumpy-plane", {{"toksvig", Claim::Better},
                        {"vlachos", Claim::Equal},
                        {"kaplanyan-beckmann", Claim::Better},
                        {"kaplanyan-rect", Claim::Better},
                        {"kaplanyan-ggx", Claim::Better},
                        {"tokuyoshi", Claim::Better},
                        {"lean", Claim::Better}});
}
