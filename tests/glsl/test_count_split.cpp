// The split of a reflecting-facet count among a light's cells (shaders/glints/binomial/count_split.glsl,
// kneiphof2024's subdivision; docs/methods.md#kneiphof2024) on the GL device: every split keeps the
// count (0 <= left <= c), its mean c q and the binomial variance c q (1 - q) at every c, fractional
// counts below one facet included; the tree keeps each cell's expectation on equal and unequal
// cells; the cells' shares sum to the undivided share exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = R"(const int LIGHT_CELLS = 16;
#include "glints/binomial/count_split.glsl"
)";

constexpr int kChunks = 64, kDrawsPerChunk = 256;

// Per chunk of draws of one (c, q): (sum of left, sum of left^2, smallest left, largest left - c)
// for the split in count_split.glsl, or for the counting model's own law with n = c and a right
// child clamped at 0 (what the subdivision drew before; `old` = 1; .x is then left + right).
std::vector<glm::vec4> split_moments(const std::vector<glm::vec2>& cases, bool old) {
  std::vector<glm::vec4> a, b;
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (int chunk = 0; chunk < kChunks; ++chunk) {
      a.emplace_back(cases[i], static_cast<float>(chunk), static_cast<float>(i));
      b.emplace_back(old ? 1.0f : 0.0f);
    }
  return evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  float c = a.x, q = a.y;
  vec4 m = vec4(0.0, 0.0, 1e30, -1e30);
  for (int i = 0; i < )" + std::to_string(kDrawsPerChunk) + R"(; ++i) {
    uvec4 r = pcg4d(uvec4(uint(a.z), uint(i), uint(a.w), 0x2545f491u));
    float left;
    if (b.x < 0.5) {
      left = splitCount(c, q, r.xy);
    } else {
      float p1 = probabilityAnyReflects(q, c);
      vec2 law = remainingLaw(q, c, p1, REMAINING_COUNT_LOGNORMAL);
      float drawn = reflectionGate(p1, randomUnit2(r.xy).x) *
                    countGivenAny(law, c, randomNormal(randomUnit2(r.zw)), REMAINING_COUNT_LOGNORMAL);
      left = drawn + max(c - drawn, 0.0);  // left + right
      m.w = max(m.w, drawn - c);
      m.z = min(m.z, drawn);
      m.x += left;
      continue;
    }
    m += vec4(left, left * left, 0.0, 0.0);
    m.z = min(m.z, left);
    m.w = max(m.w, left - c);
  }
  return m;
})",
                       a, b);
}

TEST(CountSplit, KeepsTheCountItsMeanAndTheBinomialVariance) {
  std::vector<glm::vec2> cases;
  for (float c : {0.05f, 0.3f, 0.9f, 1.5f, 3.0f, 26.0f, 1000.0f})
    for (float q : {0.5f, 0.1f, 0.9f, 0.02f}) cases.emplace_back(c, q);
  const auto r = split_moments(cases, false);
  const double n = double(kChunks) * kDrawsPerChunk;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const double c = cases[i].x, q = cases[i].y;
    double sum = 0, sum2 = 0, lowest = 1e30, excess = -1e30;
    for (int k = 0; k < kChunks; ++k) {
      const glm::vec4& m = r[i * kChunks + static_cast<std::size_t>(k)];
      sum += m.x;
      sum2 += m.y;
      lowest = std::min(lowest, double(m.z));
      excess = std::max(excess, double(m.w));
    }
    const double mean = sum / n, variance = sum2 / n - mean * mean;
    // The gates' ramps (reflectionGate: half-width w, E[B^2] = q - w / 3) and the choice of E[W^2]
    // in splitCount, written here from their definitions.
    const double w = 0.1 * std::clamp(10 * q, 0.0, 1.0) * std::clamp(10 * (1 - q), 0.0, 1.0);
    const double variance_b = q * (1 - q) - w / 3, whole = std::min(1.0, q * (1 - q) / (c * variance_b));
    const double expected = c * c * whole * variance_b;  // c q (1 - q), the binomial's, for c >= 1.6
    // Sampling error of the sample mean and variance (the fourth moment bounded by B's as a Bernoulli).
    const double fourth = std::pow(c, 4) * whole * q * (1 - q) * (std::pow(q, 3) + std::pow(1 - q, 3));
    const std::string at = "c " + std::to_string(c) + " q " + std::to_string(q);
    EXPECT_GE(lowest, 0.0) << at;
    EXPECT_LE(excess, 0.0) << at << ": the left child received more than the node holds";
    EXPECT_NEAR(mean, c * q, 4.0 * std::sqrt(expected / n) + 1e-6 * c) << at;
    EXPECT_NEAR(variance, expected, 4.0 * std::sqrt(std::max(fourth - expected * expected, 0.0) / n) + 0.01 * expected) << at;
    if (c >= 1.6) {
      EXPECT_NEAR(expected, c * q * (1 - q), 1e-9 * c) << at << ": the binomial variance";
    }
  }
  // The counting model's own law with n = c (the subdivision's earlier draw) hands a node below
  // one facet a whole facet, and its right child, clamped at 0, adds to the count: the test can fail.
  const auto old = split_moments({{0.3f, 0.5f}}, true);
  double kept = 0, excess = -1e30;
  for (const auto& m : old) {
    kept += m.x;
    excess = std::max(excess, double(m.w));
  }
  kept /= n * 0.3;
  std::printf("the counting model's law as a split at c = 0.3, q = 0.5: left + right = %.3f c, left up to c + %.3f\n",
              kept, excess);
  EXPECT_GT(excess, 0.5);
  EXPECT_GT(kept, 1.2);
}

// The leaves' probabilities over their sum: 16 equal cells or cells growing as 1.25^i.
std::string tree_probabilities(bool equal) {
  return std::string(R"(
  float pNode[LIGHT_TREE_NODES];
  for (int i = 0; i < LIGHT_CELLS; ++i) pNode[LIGHT_FIRST_LEAF + i] = )") +
         (equal ? "1.0" : "pow(1.25, float(i))") + R"(;
  for (int j = LIGHT_FIRST_LEAF - 1; j >= 0; --j) pNode[j] = pNode[2 * j + 1] + pNode[2 * j + 2];
  for (int j = LIGHT_TREE_NODES - 1; j >= 0; --j) pNode[j] /= pNode[0];
)";
}

TEST(CountSplit, TheTreeKeepsEachCellsExpectation) {
  // A root count c split down the 4 x 4 tree, N draws: each leaf's mean is c p_i / p, the first
  // leaf's as the last's (an earlier split gave the first of 16 equal cells a third of the last's).
  constexpr int kTreeChunks = 256, kTreeDraws = 64;
  const double n = double(kTreeChunks) * kTreeDraws;
  for (bool equal : {true, false})
    for (float c : {0.05f, 0.7f, 2.5f, 40.0f}) {
      std::vector<glm::vec4> a, b;
      for (int quarter = 0; quarter < 5; ++quarter)
        for (int chunk = 0; chunk < kTreeChunks; ++chunk) {
          a.emplace_back(c, static_cast<float>(chunk), 0, 0);
          b.emplace_back(static_cast<float>(quarter));
        }
      const auto r = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {)" + tree_probabilities(equal) + R"(
  vec4 sum = vec4(0.0);
  for (int i = 0; i < )" + std::to_string(kTreeDraws) + R"(; ++i) {
    float count[LIGHT_TREE_NODES];
    count[0] = a.x;
    splitDownTheTree(count, pNode, uvec2(uint(a.y), uint(i)), uvec2(0x68e31da4u, 0xb5297a4du));
    int quarter = int(b.x);
    if (quarter < 4) {
      sum += vec4(count[LIGHT_FIRST_LEAF + 4 * quarter], count[LIGHT_FIRST_LEAF + 4 * quarter + 1],
                  count[LIGHT_FIRST_LEAF + 4 * quarter + 2], count[LIGHT_FIRST_LEAF + 4 * quarter + 3]);
    } else {  // the leaves' sum against the root, and the smallest leaf
      float total = 0.0, lowest = 1e30;
      for (int l = 0; l < LIGHT_CELLS; ++l) {
        total += count[LIGHT_FIRST_LEAF + l];
        lowest = min(lowest, count[LIGHT_FIRST_LEAF + l]);
      }
      sum.x = max(sum.x, abs(total - a.x) / a.x);
      sum.y = min(sum.y, lowest);
    }
  }
  return sum;
})",
                                   a, b);
      double weights[16], total_weight = 0;
      for (int i = 0; i < 16; ++i) total_weight += weights[i] = equal ? 1.0 : std::pow(1.25, i);
      for (int leaf = 0; leaf < 16; ++leaf) {
        double mean = 0;
        for (int chunk = 0; chunk < kTreeChunks; ++chunk)
          mean += r[static_cast<std::size_t>((leaf / 4) * kTreeChunks + chunk)][leaf % 4];
        mean /= n;
        const double q = weights[leaf] / total_weight;
        // The all-or-nothing variance bounds each leaf's.
        EXPECT_NEAR(mean, c * q, 4.0 * c * std::sqrt(q * (1 - q) / n)) << (equal ? "equal" : "unequal") << " cells, c " << c
                                                                        << ", leaf " << leaf;
      }
      for (int chunk = 0; chunk < kTreeChunks; ++chunk) {
        const glm::vec4& m = r[static_cast<std::size_t>(4 * kTreeChunks + chunk)];
        EXPECT_LT(m.x, 1e-5) << "the leaves sum to the root, c " << c;
        EXPECT_GE(m.y, 0.0) << "c " << c;
      }
    }
}

TEST(CountSplit, TheCellsSharesSumToTheUndividedShare) {
  // Footprints at random places and sizes, ln density 8 to 14 (well below one facet to tens per
  // vertex), unequal cells: the split shares' sum is binomialReflectingShare's for the same numbers.
  std::vector<glm::vec4> a, b;
  for (float log_density : {8.0f, 10.0f, 12.0f, 14.0f})
    for (int k = 0; k < 64; ++k) {
      a.emplace_back(log_density, static_cast<float>(k), 0, 0);
      b.emplace_back(0.0f);
    }
  const auto r = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {)" + tree_probabilities(false) + R"(
  float p = 0.05;
  for (int j = 0; j < LIGHT_TREE_NODES; ++j) pNode[j] *= p;
  vec4 result = vec4(0.0);
  for (int i = 0; i < 16; ++i) {
    float k = float(i + 16 * int(a.y));
    vec2 uv = vec2(fract(k * 0.7548777), fract(k * 0.5698403)) * 5.0;
    float angle = 6.2831853 * fract(k * 0.618034);
    vec2 dx = exp2(-9.0) * vec2(cos(angle), sin(angle)), dy = exp2(-9.0) * (1.0 + 3.0 * fract(k * 0.41421356)) * vec2(-sin(angle), cos(angle));
    BinomialSurface s = binomialSurface(uv, binomialFootprint(uvFootprint(dx, dy), 1.5), a.x, 0.5, 0.05, 8.0);
    vec2 slope = vec2(fract(k * 0.318), fract(k * 0.871)) * 16.0;
    float share[LIGHT_CELLS];
    binomialReflectingSharesSplit(s, slope, pNode, BINOMIAL_VERTICES, REMAINING_COUNT_LOGNORMAL, share);
    float total = 0.0;
    for (int l = 0; l < LIGHT_CELLS; ++l) total += share[l];
    float whole = binomialReflectingShare(s, slope, p, REMAINING_COUNT_LOGNORMAL);
    result.x = max(result.x, abs(total - whole) / max(whole, 1e-30));
    result.y += whole;
    result.z += whole > 0.0 ? 1.0 : 0.0;
  }
  return result;
})",
                               a, b);
  for (std::size_t i = 0; i < r.size(); ++i) EXPECT_LT(r[i].x, 1e-5) << "ln density " << a[i].x << ", chunk " << a[i].y;
  // Some footprints reflect at every density (the test sees counts).
  for (int d = 0; d < 4; ++d) {
    double reflecting = 0;
    for (int k = 0; k < 64; ++k) reflecting += r[static_cast<std::size_t>(64 * d + k)].z;
    EXPECT_GT(reflecting, 0.0) << "ln density " << 8 + 2 * d;
  }
}

}  // namespace
