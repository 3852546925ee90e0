#pragma once
// Inputs of a randomized sweep of a BRDF evaluated by test::evaluate_glsl: per case,
// a = (wo, footprint scale) and b = (wi, the case's index), from which the GLSL draws the rest.
// Directions are uniform in a box reaching a little below the horizon (z from -0.2), so that
// grazing and back-facing pairs occur; the scale is 0 in a tenth of the cases and otherwise
// log-uniform from 1e-9 to 10^max_log10.
#include <cmath>
#include <glm/glm.hpp>
#include <random>
#include <vector>

namespace glintlab::test {

struct BrdfSweepInputs {
  std::vector<glm::vec4> a, b;
};

inline BrdfSweepInputs brdf_sweep_inputs(unsigned seed, int count, float max_log10) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  auto dir = [&] {
    glm::vec3 v(2 * u(rng) - 1, 2 * u(rng) - 1, 2.2f * u(rng) - 0.2f);
    return glm::length(v) > 1e-3f ? glm::normalize(v) : glm::vec3(0, 0, 1);
  };
  auto magnitude = [&] { return u(rng) < 0.1f ? 0.0f : std::pow(10.0f, -9.0f + (9.0f + max_log10) * u(rng)); };
  BrdfSweepInputs in;
  for (int i = 0; i < count; ++i) {
    const glm::vec3 wo = dir(), wi = dir();
    in.a.emplace_back(wo, magnitude());
    in.b.emplace_back(wi, static_cast<float>(i));
  }
  return in;
}

}  // namespace glintlab::test
