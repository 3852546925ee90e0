// Yan et al. 2016's P-NDF in GLSL (shaders/glints/normal-map/position_normal.glsl, method yan2016) on the GL
// device: a flat map is the intrinsic Gaussian (closed form, written here); P and the box means agree
// with the CPU's PositionNormalDistribution (src/prefilter/position_normal.hpp) for correlated,
// anisotropic and wrapping footprints, k = 1 and 2; P integrates to 1; past its element budget a
// footprint is summed over a stratified subset that fits the budget and stands for the whole sum.
// Tiny maps; a few thousand evaluations per case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <sstream>
#include <glm/gtc/constants.hpp>

#include "chi_square.hpp"
#include "gl_fixture.hpp"
#include "prefilter/ndf_image.hpp"
#include "prefilter/position_normal.hpp"
#include "prefilter/position_normal_elements.hpp"

using namespace glintlab;
using namespace glintlab::test;
using glintlab::test::chi_square;

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
/// Budget: the elements a footprint may sum before it takes a subset (kEveryElement: all of them).
constexpr double kEveryElement = 1e9;

/// `stored`: the elements read from the buffers the renderer packs (resource position-normal-elements),
/// those of `stored` as material 1 behind another material's, instead of computed from the map.
std::vector<glm::vec2> evaluate(const std::vector<Query>& queries, int k, double sigma_r,
                                double budget = kEveryElement, const PositionNormalDistribution* stored = nullptr) {
  char includes[640];
  std::snprintf(includes, sizeof includes,
                "%s#include \"generated/gpu_contract.glsl\"\n#include \"glints/normal-map/position_normal.glsl\"\n"
                "layout(binding = NORMAL_MAP_UNIT) uniform sampler2D uMap;\n"
                "const int K = %d, MATERIAL = %d;\nconst float SIGMA_R = %.9g, BUDGET = %.9g, FOOTPRINT_RHO = %.9g;\n",
                stored ? "#define POSITION_NORMAL_STORED_ELEMENTS\n" : "", k, stored ? 1 : -1, sigma_r, budget, kRho);
  gl::Buffer normals, jacobians;
  if (stored) {
    const PositionNormalDistribution before(generate_bumps(8, 0.3f, 8, 3, 2), sigma_r, k);
    const std::vector<const PositionNormalDistribution*> materials = {&before, stored};
    const PositionNormalElementBuffers packed = pack_position_normal_elements(materials, kMaxMaterials);
    normals = gl::make_buffer(static_cast<GLsizeiptr>(packed.normals.size() * 4), packed.normals.data());
    jacobians = gl::make_buffer(static_cast<GLsizeiptr>(packed.jacobians.size() * 4), packed.jacobians.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPositionNormalElementNormalsBinding, normals.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPositionNormalElementJacobiansBinding, jacobians.id());
  }
  std::vector<glm::vec4> a, b;
  for (const Query& q : queries) {
    a.emplace_back(glm::vec2(q.centre), glm::vec2(q.variance));
    b.emplace_back(glm::vec2(q.lo), glm::vec2(q.hi));
  }
  const auto r = evaluate_glsl(includes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  float c01 = FOOTPRINT_RHO * sqrt(a.z * a.w);
  PositionNormalFootprint f = positionNormalFootprint(a.xy, mat2(a.z, c01, c01, a.w), textureSize(uMap, 0), K, SIGMA_R, BUDGET);
#ifdef POSITION_NORMAL_STORED_ELEMENTS
  f.firstElement = positionNormalFirstElement[MATERIAL];
#endif
  return vec4(positionNormalDensity(uMap, f, K, b.xy), positionNormalBoxMean(uMap, f, K, b.xy, b.zw), 0.0, 0.0);
})", a, b);
  std::vector<glm::vec2> out;
  for (const auto& v : r) out.emplace_back(v.x, v.y);
  return out;
}

const std::vector<glm::dvec2> kVariances = {{0.01, 0.01}, {1.0, 1.0}, {4.0, 0.5}, {9.0, 25.0}};
const std::vector<glm::dvec2> kCentres = {{10.3, 7.6}, {0.2, 31.9}};  // the second wraps on a 32^2 map

TEST(PositionNormalGlsl, TheCheapErfcHasItsStatedAccuracy) {
  // erfcPositive (one exp, a degree-5 polynomial: tools/fit-erfc.cpp's 5.2e-6) against std::erfc
  // over [0, 9]; float's rounding of x^2 inside exp adds up to 81 x 6e-8 relative at x = 9.
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 900; ++i) {
    const double x = 0.01 * i;
    a.emplace_back(x, x + 0.0025, x + 0.005, x + 0.0075);
    b.emplace_back(0.0f);
  }
  const auto r = evaluate_glsl("#include \"glints/normal-map/position_normal.glsl\"\n",
                               "vec4 evaluate(vec4 a, vec4 b) { return erfcPositive(a); }", a, b);
  double worst = 0;
  for (std::size_t i = 0; i < r.size(); ++i)
    for (int c = 0; c < 4; ++c) {
      const double x = a[i][c], exact = std::erfc(x);
      const double bound = 8e-6 + 2 * x * x * 6e-8;
      EXPECT_NEAR(r[i][c], exact, bound * exact) << "x " << x;
      worst = std::max(worst, std::abs(r[i][c] / exact - 1));
    }
  std::printf("erfcPositive: worst relative error over [0, 9] %.2e\n", worst);
}

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
    const auto r = evaluate(queries, k, sr);
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
    // Elements computed from the map's texels, and read from the buffers packed on the CPU (the
    // methods' path): both agree with the CPU's sums.
    for (const PositionNormalDistribution* stored : {static_cast<const PositionNormalDistribution*>(nullptr), &cpu}) {
      const auto r = evaluate(queries, k, sr, kEveryElement, stored);
      double worst_density = 0, worst_box = 0;
      for (std::size_t i = 0; i < queries.size(); ++i) {
        const Footprint f = footprint_of(queries[i]);
        const double density = cpu.density(f, queries[i].lo);
        const double box = cpu.range_mean(f, queries[i].lo, queries[i].hi);
        ASSERT_GT(box, 0) << "query " << i;
        worst_density = std::max(worst_density, std::abs(r[i].x - density) / std::max(density, 1e-3));
        worst_box = std::max(worst_box, std::abs(r[i].y - box) / box);
      }
      const char* elements = stored ? "stored" : "from the map";
      std::printf("k %d, elements %s: %zu queries, worst relative difference: density %.2e, box mean %.2e\n", k,
                  elements, queries.size(), worst_density, worst_box);
      EXPECT_LT(worst_density, 1e-4) << "k " << k << ", elements " << elements;
      EXPECT_LT(worst_box, 1e-4) << "k " << k << ", elements " << elements;
    }
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
      const auto r = evaluate(queries, k, sr);
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

TEST(PositionNormalGlsl, ASubsetFitsTheBudgetWithTheSmallestStride) {
  // Stride, cells and box of random footprints and budgets, on the device; the cells each
  // footprint meets at stride s and s - 1 counted here: within the budget at s, over it at s - 1.
  const NormalMap map = generate_bumps(32, 0.25f, 32, 6, 5);
  gl::Texture tex = bind_map(map);
  std::vector<glm::vec4> a, b;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 400; ++i) {
    const double sx = std::exp(unit(rng) * 5), sy = std::exp(unit(rng) * 5);
    a.emplace_back(32 * unit(rng), 32 * unit(rng), sx * sx, sy * sy);
    b.emplace_back(std::floor(std::exp(3 + unit(rng) * 8)), i % 2 ? 1 : 2, 0, 0);
  }
  const auto r = evaluate_glsl("#include \"generated/gpu_contract.glsl\"\n#include \"glints/normal-map/position_normal.glsl\"\n"
                               "layout(binding = NORMAL_MAP_UNIT) uniform sampler2D uMap;\n", R"(
vec4 evaluate(vec4 a, vec4 b) {
  PositionNormalFootprint f = b.y == 1.0 ? positionNormalFootprint(a.xy, mat2(a.z, 0.0, 0.0, a.w), textureSize(uMap, 0), 1, 0.02, b.x)
                                         : positionNormalFootprint(a.xy, mat2(a.z, 0.0, 0.0, a.w), textureSize(uMap, 0), 2, 0.02, b.x);
  return vec4(f.stride, f.cells.x, f.cells.y, f.boxElements);
})", a, b);
  int subsets = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const int k = static_cast<int>(b[i].y), stride = static_cast<int>(r[i].x);
    const double budget = b[i].x, sh2 = 0.1875 / (k * k);
    // The box as the shader bounds it, and the cells it meets at a stride.
    const glm::dvec2 c(a[i].x, a[i].y), radius = 3.0 * glm::sqrt(glm::dvec2(a[i].z, a[i].w) + sh2);
    const glm::dvec2 first = glm::ceil(double(k) * (c - radius) - 0.5), last = glm::floor(double(k) * (c + radius) - 0.5);
    const auto cells = [&](int s) {
      const glm::dvec2 n = glm::floor(last / double(s)) - glm::floor(first / double(s)) + 1.0;
      return n.x * n.y;
    };
    ASSERT_NEAR(r[i].w, cells(1), 1e-3 * cells(1)) << "footprint " << i;
    EXPECT_DOUBLE_EQ(double(r[i].y) * r[i].z, cells(stride)) << "footprint " << i;
    EXPECT_LE(cells(stride), budget) << "footprint " << i << ": stride " << stride;
    if (stride == 1) {
      EXPECT_LE(cells(1), budget) << "footprint " << i;
    } else {
      ++subsets;
      EXPECT_GT(cells(1), budget) << "footprint " << i;
      EXPECT_GT(cells(stride - 1), budget) << "footprint " << i << ": stride " << stride;
    }
  }
  EXPECT_GT(subsets, 100);
}

TEST(PositionNormalGlsl, AStratifiedSubsetIsAnUnbiasedSampleOfTheWholeSum) {
  // A footprint of 12 texels (a 73^2-element box at k = 1) with budgets for strides 2 and 4: the
  // box means of P over a 40^2 grid of half vectors, where the whole sum's is at least 5% of its
  // peak. One subset is a sample of the map's normals (relative L2 to the whole sum's P, measured
  // 0.14 and 0.34); the mean over 16 seeds of the hash is a quarter of that (0.035, 0.078: unbiased
  // up to the ratio's O(1 / n)); every subset's P still integrates to the whole sum's mass.
  const NormalMap map = generate_bumps(32, 0.25f, 32, 6, 5);
  gl::Texture tex = bind_map(map);
  const double sr = 0.02;
  const PositionNormalDistribution cpu(map, sr, 1);
  const Footprint footprint{{10.3, 7.6}, glm::dmat2(144.0)};
  constexpr int kSeeds = 16, kGrid = 40;
  std::vector<double> whole;
  std::vector<glm::dvec2> cells;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      cells.push_back(glm::dvec2(i, j) / double(kGrid) - 0.5);
      whole.push_back(cpu.range_mean(footprint, cells.back(), cells.back() + 1.0 / kGrid));
    }
  const double peak = *std::max_element(whole.begin(), whole.end());
  const double whole_mass = std::accumulate(whole.begin(), whole.end(), 0.0) / (kGrid * kGrid);
  for (double budget : {1500.0, 400.0}) {
    std::vector<glm::vec4> a, b;
    for (int seed = 0; seed < kSeeds; ++seed)
      for (const glm::dvec2& lo : cells) {
        a.emplace_back(glm::vec2(lo), glm::vec2(lo + 1.0 / kGrid));
        b.emplace_back(float(seed), float(budget), 0.0f, 0.0f);
      }
    const auto r = evaluate_glsl("#include \"generated/gpu_contract.glsl\"\n"
                                 "#include \"glints/normal-map/position_normal.glsl\"\n"
                                 "layout(binding = NORMAL_MAP_UNIT) uniform sampler2D uMap;\n", R"(
vec4 evaluate(vec4 a, vec4 b) {
  PositionNormalFootprint f = positionNormalFootprint(vec2(10.3, 7.6), mat2(144.0), textureSize(uMap, 0), 1, 0.02, b.y);
  f.seed = uint(b.x);
  return vec4(positionNormalBoxMean(uMap, f, 1, a.xy, a.zw), f.stride, 0.0, 0.0);
})", a, b);
    const auto relative_l2 = [&](const std::vector<double>& p) {
      double diff2 = 0, norm2 = 0;
      for (std::size_t i = 0; i < whole.size(); ++i)
        if (whole[i] >= 0.05 * peak) {
          diff2 += (p[i] - whole[i]) * (p[i] - whole[i]);
          norm2 += whole[i] * whole[i];
        }
      return std::sqrt(diff2 / norm2);
    };
    std::vector<double> mean(whole.size(), 0.0);
    double single = 0;
    for (int seed = 0; seed < kSeeds; ++seed) {
      std::vector<double> p(whole.size());
      for (std::size_t i = 0; i < whole.size(); ++i) p[i] = r[seed * whole.size() + i].x;
      for (std::size_t i = 0; i < whole.size(); ++i) mean[i] += p[i] / kSeeds;
      single += relative_l2(p) / kSeeds;
      const double mass = std::accumulate(p.begin(), p.end(), 0.0) / (kGrid * kGrid);
      EXPECT_NEAR(mass, whole_mass, 2e-3) << "budget " << budget << " seed " << seed;
    }
    const double averaged = relative_l2(mean);
    std::printf("budget %.0f (stride %.0f): relative L2 to the whole sum's P: one subset %.4f, mean of %d %.4f\n",
                budget, r[0].y, single, kSeeds, averaged);
    EXPECT_GT(r[0].y, 1.5) << "budget " << budget << ": the subset must be one";
    EXPECT_LT(single, 0.5) << "budget " << budget;
    EXPECT_LT(averaged, 0.4 * single) << "budget " << budget;  // 1 / sqrt(16) = 0.25 if unbiased
  }
}

TEST(PositionNormalGlsl, SamplesFollowTheElementMixture) {
  // The GLSL sampler (glints/normal-map/ndf_sampling.glsl) on the device, as the CPU's
  // (tests/prefilter/test_ndf_sampling.cpp): its pdf is the GLSL density, which is the CPU's, and
  // a chi-square test of 20000 samples against the CPU's box means over a 24^2 grid (and the mass
  // outside it) passes; the mixture of a footprint twice as wide is told apart. Then a footprint
  // past its budget: the samples follow the subset's own density (the GLSL box means).
  const NormalMap map = generate_bumps(32, 0.3f, 48, 6, 17);
  gl::Texture tex = bind_map(map);
  const double sr = 0.03;
  const PositionNormalDistribution cpu(map, sr, 2);
  const NdfGrid grid{24, cpu.suggested_extent()};
  constexpr int kSamples = 20000;
  std::mt19937 rng(43);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const std::string includes = "#include \"generated/gpu_contract.glsl\"\n"
                               "#include \"glints/normal-map/ndf_sampling.glsl\"\n"
                               "layout(binding = NORMAL_MAP_UNIT) uniform sampler2D uMap;\n";
  for (const auto& [variance, budget] : {std::pair{glm::vec2(4.0f, 2.0f), 1e9f}, {glm::vec2(64.0f, 49.0f), 300.0f}}) {
    std::vector<glm::vec4> a, b;
    for (int i = 0; i < kSamples; ++i) {
      a.emplace_back(9.2f, 17.7f, variance);
      b.emplace_back(static_cast<float>(i), u(rng), u(rng), budget);
    }
    const auto out = evaluate_glsl(includes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  float c01 = 0.5 * sqrt(a.z * a.w);
  PositionNormalFootprint f = positionNormalFootprint(a.xy, mat2(a.z, c01, c01, a.w), textureSize(uMap, 0), 2, 0.03, b.w);
  NdfSample x = positionNormalSample(uMap, f, 2, uint(b.x), b.yz);
  return vec4(x.s, x.pdf, f.stride);
})",
                                   a, b);
    const double c01 = 0.5 * std::sqrt(double(variance.x) * variance.y);
    const Footprint footprint{{9.2, 17.7}, glm::dmat2(variance.x, c01, c01, variance.y)};
    const bool subset = out[0].w > 1.5f;
    // The bins' expected mass: the CPU's box means for the whole sum; the device's for a subset.
    std::vector<glm::vec4> qa, qb;
    for (int j = 0; j < grid.resolution; ++j)
      for (int i = 0; i < grid.resolution; ++i) {
        const glm::dvec2 lo = grid.pixel_centre(i, j) - 0.5 * grid.pixel_size(), hi = lo + grid.pixel_size();
        qa.emplace_back(glm::vec2(lo), glm::vec2(hi));
        qb.emplace_back(variance, budget, 0.0f);
      }
    const auto device_means = evaluate_glsl(includes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  float c01 = 0.5 * sqrt(b.x * b.y);
  PositionNormalFootprint f = positionNormalFootprint(vec2(9.2, 17.7), mat2(b.x, c01, c01, b.y), textureSize(uMap, 0), 2, 0.03, b.z);
  return vec4(positionNormalBoxMean(uMap, f, 2, a.xy, a.zw), 0.0, 0.0, 0.0);
})",
                                            qa, qb);
    std::vector<double> observed(grid.pixel_count() + 1, 0.0), expected(grid.pixel_count() + 1, 0.0),
        wrong(grid.pixel_count() + 1, 0.0);
    double expected_outside = kSamples, wrong_outside = kSamples;
    Footprint wide = footprint;
    wide.covariance *= 4.0;
    for (std::size_t c = 0; c < grid.pixel_count(); ++c) {
      const glm::dvec2 lo(qa[c].x, qa[c].y), hi(qa[c].z, qa[c].w);
      const double mean = subset ? device_means[c].x : cpu.range_mean(footprint, lo, hi);
      expected[c] = mean * grid.pixel_area() * kSamples;
      wrong[c] = cpu.range_mean(wide, lo, hi) * grid.pixel_area() * kSamples;
      expected_outside -= expected[c];
      wrong_outside -= wrong[c];
    }
    expected.back() = std::max(expected_outside, 0.0);
    wrong.back() = std::max(wrong_outside, 0.0);
    for (const glm::vec4& x : out) {
      ASSERT_GT(x.z, 0.0f) << "a sample";
      if (!subset) {
        ASSERT_NEAR(x.z, cpu.density(footprint, glm::dvec2(x.x, x.y)), 1e-4 * x.z + 1e-3) << "the CPU's density";
      }
      const glm::dvec2 g = grid.to_pixels(glm::dvec2(x.x, x.y));
      const int i = static_cast<int>(std::floor(g.x)), j = static_cast<int>(std::floor(g.y));
      const bool inside = i >= 0 && j >= 0 && i < grid.resolution && j < grid.resolution;
      observed[inside ? static_cast<std::size_t>(j * grid.resolution + i) : grid.pixel_count()] += 1;
    }
    const auto chi = chi_square(observed, expected);
    std::printf("GLSL yan2016 sampler (stride %.0f): %s\n", out[0].w, (std::ostringstream() << chi).str().c_str());
    EXPECT_EQ(subset, budget < 1e6f);
    EXPECT_TRUE(chi.passes(2)) << chi;
    EXPECT_LT(chi_square(observed, wrong).p, 1e-6);
  }
}

}  // namespace
