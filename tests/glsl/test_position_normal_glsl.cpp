// Yan et al. 2016's P-NDF in GLSL (shaders/glints/normal-map/position_normal.glsl, method yan2016) on the GL
// device: a flat map is the intrinsic Gaussian (closed form, written here); P and the box means agree
// with the CPU's PositionNormalDistribution (src/prefilter/position_normal.hpp) for correlated,
// anisotropic and wrapping footprints, k = 1 and 2; P integrates to 1; the max_radius cap is the
// CPU's footprint shrunk as documented. Tiny maps; a few thousand evaluations per case.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/constants.hpp>

#include "gl_fixture.hpp"
#include "prefilter/position_normal.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr double kRho = 0.5;  // the footprints' correlation (the shader's FOOTPRINT_RHO)

/// The map as the renderer uploads it (RGBA32F, level 0), bound to the normal map's unit.
gl::Texture bind_map(const NormalMap& map) {
  context();
  std::vector<glm::vec4> texels;
  for (const glm::vec3& n : map.normals) texels.emplace_back(n, 1.0f);
  gl::Texture tex = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(tex.id(), 1, GL_RGBA32F, map.width, map.height);
  glTextureSubImage2D(tex.id(), 0, 0, 0, map.width, map.height, GL_RGBA, GL_FLOAT, texels.data());
  glBindTextureUnit(kNormalMapUnit, tex.id());
  return tex;
}

struct Query {
  glm::dvec2 centre;    // footprint centre (texels)
  glm::dvec2 variance;  // footprint variances along x and y (texels^2); correlation kRho
  glm::dvec2 lo, hi;    // density at lo; mean over [lo, hi]
};

Footprint footprint_of(const Query& q) {
  const double c01 = kRho * std::sqrt(q.variance.x * q.variance.y);
  return {q.centre, glm::dmat2(q.variance.x, c01, c01, q.variance.y)};
}

/// (density at lo, mean over [lo, hi]) for each query, on the device.
std::vector<glm::vec2> evaluate(const std::vector<Query>& queries, int k, double sigma_r, double max_radius) {
  char includes[512];
  std::snprintf(includes, sizeof includes,
                "#include \"generated/gpu_contract.glsl\"\n#include \"glints/normal-map/position_normal.glsl\"\n"
                "layout(binding = NORMAL_MAP_UNIT) uniform sampler2D uMap;\n"
                "const int K = %d;\nconst float SIGMA_R = %.9g, MAX_RADIUS = %.9g, FOOTPRINT_RHO = %.9g;\n",
                k, sigma_r, max_radius, kRho);
  std::vector<glm::vec4> a, b;
  for (const Query& q : queries) {
    a.emplace_back(glm::vec2(q.centre), glm::vec2(q.variance));
    b.emplace_back(glm::vec2(q.lo), glm::vec2(q.hi));
  }
  const auto r = evaluate_glsl(includes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  float c01 = FOOTPRINT_RHO * sqrt(a.z * a.w);
  PositionNormalFootprint f = positionNormalFootprint(a.xy, mat2(a.z, c01, c01, a.w), textureSize(uMap, 0), K, SIGMA_R, MAX_RADIUS);
  return vec4(positionNormalDensity(uMap, f, K, b.xy), positionNormalBoxMean(uMap, f, K, b.xy, b.zw), 0.0, 0.0);
})", a, b);
  std::vector<glm::vec2> out;
  for (const auto& v : r) out.emplace_back(v.x, v.y);
  return out;
}

const std::vector<glm::dvec2> kVariances = {{0.01, 0.01}, {1.0, 1.0}, {4.0, 0.5}, {9.0, 25.0}};
const std::vector<glm::dvec2> kCentres = {{10.3, 7.6}, {0.2, 31.9}};  // the second wraps on a 32^2 map

TEST(PositionNormalGlsl, FlatMapIsTheIntrinsicGaussian) {
  // Every element's normal is +z and J = 0: P = N2(s; 0, sigma_r^2 I) whatever the footprint, and a
  // box's mean is the product of the 1D normal's interval means (erf, written here). The box means
  // integrate x by 10-point Gauss-Legendre over the box clipped to +-5 sigma (as the CPU's
  // range_mean): a box holding the whole Gaussian loses up to 9e-4 of it to that rule.
  const NormalMap map{8, 8, std::vector<glm::vec3>(64, glm::vec3(0, 0, 1)), "flat"};
  gl::Texture tex = bind_map(map);
  const double sr = 0.02;
  std::vector<Query> queries;
  for (const auto& v : kVariances)
    for (glm::dvec2 s : {glm::dvec2(0.0), glm::dvec2(0.013, -0.021), glm::dvec2(-0.05, 0.01)})
      for (glm::dvec2 e : {glm::dvec2(0.0), glm::dvec2(0.004, 0.007), glm::dvec2(0.03, 0.02), glm::dvec2(0.5, 0.5)})
        queries.push_back({{3.7, 5.2}, v, s - e, s + e});
  const auto interval_mean = [&](double a, double b) {
    if (b - a < 1e-12) return std::exp(-0.5 * a * a / (sr * sr)) / (std::sqrt(2 * glm::pi<double>()) * sr);
    return 0.5 * (std::erf(b / (std::sqrt(2.0) * sr)) - std::erf(a / (std::sqrt(2.0) * sr))) / (b - a);
  };
  for (int k : {1, 2}) {
    const auto r = evaluate(queries, k, sr, 32);
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Query& q = queries[i];
      const double density = std::exp(-0.5 * glm::dot(q.lo, q.lo) / (sr * sr)) / (2 * glm::pi<double>() * sr * sr);
      const double box = interval_mean(q.lo.x, q.hi.x) * interval_mean(q.lo.y, q.hi.y);
      const double peak = 1 / (2 * glm::pi<double>() * sr * sr);
      EXPECT_NEAR(r[i].x, density, 1e-4 * density + 1e-7 * peak) << "k " << k << " query " << i;
      const double rule = glm::any(glm::greaterThan(q.hi - q.lo, glm::dvec2(2 * sr))) ? 1e-3 : 1e-4;
      EXPECT_NEAR(r[i].y, box, rule * box + 1e-7 * peak) << "k " << k << " query " << i;
    }
  }
}

TEST(PositionNormalGlsl, AgreesWithTheCpu) {
  const NormalMap map = generate_bumps(32, 0.25f, 32, 6, 5);
  gl::Texture tex = bind_map(map);
  const double sr = 0.02;
  for (int k : {1, 2}) {
    const PositionNormalDistribution cpu(map, sr, k);
    // Half vectors where P is at least 5% of its peak over a coarse grid, per footprint; boxes
    // of zero size, of a few sigma_r, and of a large light about them.
    std::vector<Query> queries;
    for (const auto& c : kCentres)
      for (const auto& v : kVariances) {
        const Query base{c, v, {}, {}};
        const Footprint f = footprint_of(base);
        std::vector<std::pair<double, glm::dvec2>> grid;
        double peak = 0;
        for (int j = 0; j < 40; ++j)
          for (int i = 0; i < 40; ++i) {
            const glm::dvec2 s = glm::dvec2(i + 0.5, j + 0.5) / 40.0 - 0.5;
            grid.emplace_back(cpu.density(f, s), s);
            peak = std::max(peak, grid.back().first);
          }
        int taken = 0;
        for (std::size_t g = 0; g < grid.size() && taken < 6; g += 7)
          if (grid[g].first > 0.05 * peak) {
            ++taken;
            for (glm::dvec2 e : {glm::dvec2(0.0), glm::dvec2(0.01, 0.03), glm::dvec2(0.1, 0.06)})
              queries.push_back({c, v, grid[g].second - e, grid[g].second + e});
          }
        EXPECT_GT(taken, 0);
      }
    const auto r = evaluate(queries, k, sr, 128);
    double worst_density = 0, worst_box = 0;
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Footprint f = footprint_of(queries[i]);
      const double density = cpu.density(f, queries[i].lo);
      const double box = cpu.range_mean(f, queries[i].lo, queries[i].hi);
      ASSERT_GT(box, 0) << "query " << i;
      worst_density = std::max(worst_density, std::abs(r[i].x - density) / std::max(density, 1e-3));
      worst_box = std::max(worst_box, std::abs(r[i].y - box) / box);
    }
    std::printf("k %d: %zu queries, worst relative difference: density %.2e, box mean %.2e\n", k, queries.size(),
                worst_density, worst_box);
    EXPECT_LT(worst_density, 1e-4) << "k " << k;
    EXPECT_LT(worst_box, 1e-4) << "k " << k;
  }
}

TEST(PositionNormalGlsl, IntegratesToOne) {
  // The box means over a partition of a square holding all of P, times the cells' area, sum to its
  // mass (1: nothing falls outside); the midpoint sum of the density agrees within its rule's error.
  const NormalMap map = generate_bumps(32, 0.25f, 32, 6, 5);
  gl::Texture tex = bind_map(map);
  const double sr = 0.04;
  for (int k : {1, 2}) {
    const double extent = PositionNormalDistribution(map, sr, k).suggested_extent();
    const int n = 64;
    const double h = 2 * extent / n;  // at most 0.8 sigma_r: the midpoint rule is exact to ~1e-10
    for (const auto& v : {glm::dvec2(0.3, 0.3), glm::dvec2(2.0, 3.0)}) {
      std::vector<Query> queries;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const glm::dvec2 lo = glm::dvec2(i, j) * h - extent;
          queries.push_back({{10.3, 7.6}, v, lo + 0.5 * h, lo + 0.5 * h});  // density at the cell's centre
          queries.push_back({{10.3, 7.6}, v, lo, lo + h});                  // mean over the cell
        }
      const auto r = evaluate(queries, k, sr, 128);
      double midpoint = 0, boxes = 0;
      for (std::size_t i = 0; i < r.size(); i += 2) {
        midpoint += r[i].x * h * h;
        boxes += r[i + 1].y * h * h;
      }
      EXPECT_NEAR(boxes, 1.0, 2e-4) << "k " << k << " variance " << v.x;
      EXPECT_NEAR(midpoint, 1.0, 3e-3) << "k " << k << " variance " << v.x;
    }
  }
}

TEST(PositionNormalGlsl, MaxRadiusShrinksTheFootprintToFit) {
  // A footprint of 10 texels with max_radius 8: Sigma_p scaled by t so that 3 sqrt(Sigma_h + t
  // Sigma_p) = 8 along its wider axis, which the CPU reproduces with the scaled footprint.
  const NormalMap map = generate_bumps(32, 0.25f, 32, 6, 5);
  gl::Texture tex = bind_map(map);
  const double sr = 0.02, radius = 8;
  const PositionNormalDistribution cpu(map, sr, 1);
  const double sh2 = cpu.element_sigma() * cpu.element_sigma();
  std::vector<Query> queries;
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) queries.push_back({{10.3, 7.6}, {100.0, 64.0}, glm::dvec2(i - 2, j - 2) * 0.06, {}});
  const auto r = evaluate(queries, 1, sr, radius);
  double largest_change = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    Footprint f = footprint_of(queries[i]);
    const double t = (radius * radius / 9 - sh2) / 100.0;
    f.covariance *= t;
    const double unscaled = cpu.density(footprint_of(queries[i]), queries[i].lo);
    const double density = cpu.density(f, queries[i].lo);
    EXPECT_NEAR(r[i].x, density, 1e-4 * density + 1e-6) << "query " << i;
    largest_change = std::max(largest_change, std::abs(density - unscaled) / std::max(unscaled, 0.1));
  }
  EXPECT_GT(largest_change, 0.05) << "the cap must change P somewhere";
}

}  // namespace
