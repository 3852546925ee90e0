// deng2022's GLSL queries (shaders/glints/normal-map/prefiltered_ndf.glsl) against the C++ ones
// (src/prefilter/prefiltered_ndf.cpp) on the same packed pyramid: point and box queries over
// random footprints (inside and outside the pyramid's range of sigma) and half vectors.
#include <gtest/gtest.h>

#include <random>

#include "core/gpu_contract.hpp"
#include "gl_fixture.hpp"
#include "prefilter/ndf_precompute.hpp"
#include "prefilter/prefiltered_ndf_layout.hpp"

using namespace glintlab;
using namespace glintlab::test;

TEST(PrefilteredNdfGlsl, QueriesAgreeWithTheCpu) {
  shaders();  // a current GL context before the buffers below
  PrefilterSettings settings;
  settings.ndf_resolution = 32;
  settings.block_size = 8;
  settings.base_footprints = 32;
  const NormalMap map = generate_bumps(32, 0.3f, 48, 6, 21);
  const PrefilteredNdf p = precompute_prefiltered_ndf(map, 0.03, settings);
  // The pyramid as material 2's (materials 0 and 1 have none), as the renderer packs a scene's.
  const std::vector<const PrefilteredNdf*> materials = {nullptr, nullptr, &p};
  const PrefilteredNdfBuffers packed = pack_prefiltered_ndfs(materials, kMaxMaterials);
  gl::Buffer records = gl::make_buffer(static_cast<GLsizeiptr>(packed.records.size() * 4), packed.records.data());
  gl::Buffer values = gl::make_buffer(static_cast<GLsizeiptr>(packed.values.size() * 4), packed.values.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrefilteredNdfRecordsBinding, records.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrefilteredNdfValuesBinding, values.id());

  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 600; ++i) {
    const float sigma = std::pow(2.0f, 8.0f * u(rng) - 2.0f);  // 0.25 .. 64 texels: below, across and above the levels
    a.emplace_back(64.0f * u(rng) - 16.0f, 64.0f * u(rng) - 16.0f, sigma, 2.0f);
    const float e = static_cast<float>(p.grid.extent);
    b.emplace_back((2 * u(rng) - 1) * 1.1f * e, (2 * u(rng) - 1) * 1.1f * e, 0.3f * e * u(rng) * u(rng), 0.3f * e * u(rng));
  }
  const auto out = evaluate_glsl("#include \"glints/normal-map/prefiltered_ndf.glsl\"", R"(
vec4 evaluate(vec4 a, vec4 b) {
  int m = int(a.w);
  if (!pndfPresent(m) || pndfPresent(0)) return vec4(-1.0);
  return vec4(pndfDensity(m, a.xy, a.z, b.xy), pndfRangeMean(m, a.xy, a.z, b.xy - b.zw, b.xy + b.zw), 0.0, 0.0);
})",
                                 a, b);
  double peak = 0.0;
  for (float v : p.rows) peak = std::max(peak, static_cast<double>(std::abs(v)));
  int nonzero = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const glm::dvec2 centre(a[i].x, a[i].y), s(b[i].x, b[i].y), half(b[i].z, b[i].w);
    const double d = p.density(centre, a[i].z, s), r = p.range_mean(centre, a[i].z, s - half, s + half);
    ASSERT_NE(out[i].x, -1.0f) << "the packed pyramid's material offsets";
    EXPECT_NEAR(out[i].x, d, 2e-4 * d + 1e-4) << "point query " << i;
    // The box query subtracts prefix sums: in float on the device, in double here.
    EXPECT_NEAR(out[i].y, r, 2e-3 * r + 1e-4) << "box query " << i;
    nonzero += d > 0.1 ? 1 : 0;
  }
  EXPECT_GT(nonzero, 50);  // the sweep reaches the NDF's mass, not just empty space
}
