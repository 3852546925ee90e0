#include "scene/normal_maps/scratches.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <random>
#include <sstream>

#include "scene/normal_maps/parallel_rows.hpp"

namespace glintlab {

namespace {

constexpr float kRadiusInWidths = 4.0f;
constexpr int kBandRows = 32;  // rows of height one thread fills at a time

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

int wrap(int q, int n) { return q >= 0 && q < n ? q : (q % n + n) % n; }

/// The rows [first, last] (not wrapped) of one scratch that fall in one band of rows.
struct BandPiece {
  int scratch, first, last;
};

}  // namespace

float GrooveProfile::operator()(float distance) const {
  if (distance >= radius) return 0.0f;
  const float s2 = 2.0f * width * width;
  return depth * (std::exp(-distance * distance / s2) - std::exp(-radius * radius / s2));
}

GrooveProfile groove_profile(float width, float slope) {
  GrooveProfile p{width, kRadiusInWidths * width, 1.0f};
  // Central differences of the sampled height see less than the profile's steepest slope (about
  // 13% less at w = 1.5 texels): scale the depth so the largest of them across a groove is `slope`.
  float steepest = 0.0f;
  constexpr int kSteps = 4096;
  for (int i = 0; i <= kSteps; ++i) {
    const float x = (p.radius + 1.0f) * static_cast<float>(i) / kSteps;
    steepest = std::max(steepest, 0.5f * std::abs(p(std::abs(x - 1.0f)) - p(x + 1.0f)));
  }
  p.depth = steepest > 0.0f ? slope / steepest : 0.0f;
  return p;
}

std::vector<Scratch> choose_scratches(const ScratchParams& params) {
  std::mt19937 rng(params.seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const auto n = static_cast<float>(params.resolution);
  std::vector<Scratch> scratches;
  scratches.reserve(static_cast<std::size_t>(params.count));
  for (int i = 0; i < params.count; ++i) {
    const float cx = uni(rng), cy = uni(rng), spread = uni(rng), stretch = uni(rng);
    const glm::vec2 centre = n * glm::vec2(cx, cy);
    const float theta = glm::radians(params.angle + params.angle_spread * (spread - 0.5f));
    const glm::vec2 half = 0.5f * params.length * (0.5f + stretch) * n * glm::vec2(std::cos(theta), std::sin(theta));
    scratches.push_back({centre - half, centre + half});
  }
  return scratches;
}

std::vector<float> scratch_heights(const ScratchParams& params, const std::vector<Scratch>& scratches,
                                   const GrooveProfile& profile) {
  const int n = params.resolution;
  const float r = profile.radius;
  // Each scratch's rows (unwrapped: a row beyond the tile is its image inside), cut at band edges.
  const int bands = (n + kBandRows - 1) / kBandRows;
  std::vector<std::vector<BandPiece>> pieces(static_cast<std::size_t>(bands));
  for (int s = 0; s < static_cast<int>(scratches.size()); ++s) {
    const Scratch& sc = scratches[s];
    // Texel centres y + 0.5 within R of the segment's rows.
    const int first = static_cast<int>(std::ceil(std::min(sc.from.y, sc.to.y) - r - 0.5f));
    const int last = static_cast<int>(std::floor(std::max(sc.from.y, sc.to.y) + r - 0.5f));
    for (int y = first; y <= last;) {
      const int in_tile = wrap(y, n), band = in_tile / kBandRows;
      const int band_end = std::min(n, (band + 1) * kBandRows);  // one past the band's last row
      const int piece_last = std::min(last, y + (band_end - 1 - in_tile));
      pieces[static_cast<std::size_t>(band)].push_back({s, y, piece_last});
      y = piece_last + 1;
    }
  }
  std::vector<float> height(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0.0f);
  for_each_row(
      bands, std::min(row_workers(n), bands),
      [&](int band, int) {
        // Pieces in scratch order, so every texel sums its grooves in the same order on any thread count.
        for (const BandPiece& piece : pieces[static_cast<std::size_t>(band)]) {
          const Scratch& sc = scratches[static_cast<std::size_t>(piece.scratch)];
          const glm::vec2 d = sc.to - sc.from;
          for (int y = piece.first; y <= piece.last; ++y) {
            const float py = static_cast<float>(y) + 0.5f;
            // The part of the segment whose y is within R of the row, widened by R: the row's span.
            float t0 = 0.0f, t1 = 1.0f;
            if (std::abs(d.y) > 1e-6f) {
              t0 = std::clamp((py - r - sc.from.y) / d.y, 0.0f, 1.0f);
              t1 = std::clamp((py + r - sc.from.y) / d.y, 0.0f, 1.0f);
            }
            const float xa = sc.from.x + std::min(t0, t1) * d.x, xb = sc.from.x + std::max(t0, t1) * d.x;
            const int x_first = static_cast<int>(std::ceil(std::min(xa, xb) - r - 0.5f));
            const int x_last = static_cast<int>(std::floor(std::max(xa, xb) + r - 0.5f));
            float* row = height.data() + static_cast<std::size_t>(wrap(y, n)) * n;
            for (int x = x_first; x <= x_last; ++x) {
              const float dist = distance_to_segment(glm::vec2(static_cast<float>(x) + 0.5f, py), sc.from, sc.to);
              if (dist < r) row[wrap(x, n)] -= profile(dist);
            }
          }
        }
      },
      describe(params) + " grooves");
  return height;
}

std::string describe(const ScratchParams& p) {
  std::ostringstream d;
  d << "scratches(resolution=" << p.resolution << ", count=" << p.count << ", length=" << p.length
    << ", width=" << p.width << ", slope=" << p.slope << ", angle=" << p.angle << ", angle_spread=" << p.angle_spread
    << ", base_alpha=" << p.base_alpha << ", seed=" << p.seed << ")";
  return d.str();
}

NormalMap generate_scratches(const ScratchParams& params) {
  const int n = params.resolution;
  const std::string what = describe(params);
  const std::vector<float> height =
      scratch_heights(params, choose_scratches(params), groove_profile(params.width, params.slope));
  // An optional `bumps` base (its defaults: 128 waves up to frequency 24): heights add, so slopes do.
  std::vector<glm::vec3> base;
  if (params.base_alpha > 0.0f)
    base = generate_bumps(n, params.base_alpha, 128, std::min(24, n / 2), params.seed).normals;
  NormalMap map{n, n, {}, what};
  map.normals.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  auto h = [&](int x, int y) { return height[static_cast<std::size_t>(wrap(y, n)) * n + wrap(x, n)]; };
  for_each_row(
      n, row_workers(n),
      [&](int y, int) {
        for (int x = 0; x < n; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * n + x;
          // Slopes per texel, the height's unit: dh/du of a map whose tile is n texels wide.
          glm::vec2 slope(0.5f * (h(x + 1, y) - h(x - 1, y)), 0.5f * (h(x, y + 1) - h(x, y - 1)));
          if (!base.empty()) slope -= glm::vec2(base[i]) / base[i].z;
          map.normals[i] = glm::normalize(glm::vec3(-slope, 1.0f));
        }
      },
      what);
  return map;
}

}  // namespace glintlab
