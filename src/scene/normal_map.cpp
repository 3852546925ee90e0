#include "scene/normal_map.hpp"

#include <cmath>
#include "core/math.hpp"
#include <glm/gtc/constants.hpp>
#include <random>
#include <sstream>

#include "core/image_io.hpp"

namespace glintlab {

NormalMap load_normal_map(const std::filesystem::path& path) {
  const Image img = read_ldr_image(path);
  NormalMap map{img.width(), img.height(), {}, "file " + path.filename().string()};
  map.normals.reserve(img.pixel_count());
  // +Y is up in the image (the OpenGL and glTF convention), which is glintlab's +v: the bottom
  // row is v = 0 and comes first.
  for (int y = img.height() - 1; y >= 0; --y)
    for (int x = 0; x < img.width(); ++x) {
      glm::vec3 n = 2.0f * img.at(x, y) - 1.0f;
      n.z = std::max(n.z, 1e-3f);  // never below the surface
      map.normals.push_back(glm::normalize(n));
    }
  return map;
}

NormalMap generate_bumps(int resolution, float slope_sigma, int waves, int max_frequency, std::uint32_t seed,
                         float anisotropy, float angle_degrees) {
  const float axis = glm::radians(angle_degrees);
  struct Wave {
    glm::vec2 k;  // integer cycles per tile
    float phase;
  };
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  std::vector<Wave> ws;
  ws.reserve(static_cast<std::size_t>(waves));
  double k2_sum = 0.0;
  for (int i = 0; i < waves; ++i) {
    // Distinct integer frequencies (k and -k are the same wave), so the waves stay orthogonal
    // over the tile and the slope variance is exactly the sum of theirs.
    glm::vec2 k(0.0f);
    auto taken = [&](glm::vec2 q) {
      return std::any_of(ws.begin(), ws.end(), [&](const Wave& w) { return w.k == q || w.k == -q; });
    };
    for (int attempt = 0; attempt < 1000 && (k == glm::vec2(0.0f) || taken(k)); ++attempt) {
      const float r = 1.0f + (static_cast<float>(max_frequency) - 1.0f) * std::sqrt(uni(rng));
      // Isotropic: any direction. Anisotropic: a deviation from the axis in [-pi/2, pi/2) (k and
      // -k are one wave) narrowed by the anisotropy.
      const float u = uni(rng);
      const float theta = anisotropy == 1.0f ? glm::two_pi<float>() * u
                                             : axis + glm::pi<float>() * (u - 0.5f) / anisotropy;
      k = glm::round(glm::vec2(r * std::cos(theta), r * std::sin(theta)));
    }
    if (k == glm::vec2(0.0f) || taken(k)) break;  // fewer distinct frequencies than waves asked for
    ws.push_back({k, glm::two_pi<float>() * uni(rng)});
    k2_sum += glm::dot(k, k);
  }
  // height = a * sum cos(2 pi k.x + phase); over a tile the slope variance of both axes together
  // is a^2 (2 pi)^2 sum(|k|^2) / 2. Make it slope_sigma^2 (Beckmann: alpha^2 = <slope^2>).
  const double a = slope_sigma * std::sqrt(2.0) / (glm::two_pi<double>() * std::sqrt(k2_sum));
  NormalMap map{resolution, resolution, {}, {}};
  map.normals.resize(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution));
  for (int y = 0; y < resolution; ++y)
    for (int x = 0; x < resolution; ++x) {
      const glm::vec2 p((static_cast<float>(x) + 0.5f) / static_cast<float>(resolution),
                        (static_cast<float>(y) + 0.5f) / static_cast<float>(resolution));
      glm::dvec2 slope(0.0);
      for (const auto& w : ws) {
        const double s = -std::sin(glm::two_pi<double>() * glm::dot(glm::dvec2(w.k), glm::dvec2(p)) + w.phase);
        slope += a * glm::two_pi<double>() * s * glm::dvec2(w.k);
      }
      map.normals[static_cast<std::size_t>(y) * resolution + x] =
          glm::normalize(glm::vec3(-static_cast<float>(slope.x), -static_cast<float>(slope.y), 1.0f));
    }
  std::ostringstream d;
  d << "bumps(resolution=" << resolution << ", alpha=" << slope_sigma << ", waves=" << waves
    << ", max_frequency=" << max_frequency << ", seed=" << seed << ")";
  map.description = d.str();
  return map;
}

NormalMap generate_flakes(int resolution, int cells, float alpha, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const auto count = static_cast<std::size_t>(cells) * static_cast<std::size_t>(cells);
  std::vector<glm::vec2> sites(count);
  std::vector<glm::vec3> normals(count);
  for (std::size_t i = 0; i < count; ++i) {
    sites[i] = glm::vec2(uni(rng), uni(rng));
    // Beckmann sampling: tan^2(theta) = -alpha^2 ln(1 - u).
    const float tan2 = -alpha * alpha * std::log(1.0f - uni(rng));
    const float phi = glm::two_pi<float>() * uni(rng);
    const float cos_t = 1.0f / std::sqrt(1.0f + tan2);
    const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
    normals[i] = glm::vec3(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
  }
  NormalMap map{resolution, resolution, {}, {}};
  map.normals.resize(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution));
  for (int y = 0; y < resolution; ++y)
    for (int x = 0; x < resolution; ++x) {
      const glm::vec2 p = (glm::vec2(x, y) + 0.5f) / static_cast<float>(resolution) * static_cast<float>(cells);
      const glm::ivec2 c = glm::ivec2(glm::floor(p));
      float best = 1e30f;
      std::size_t best_i = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const glm::ivec2 q = c + glm::ivec2(dx, dy);
          const glm::ivec2 w = (q % cells + cells) % cells;  // toroidal
          const std::size_t i = static_cast<std::size_t>(w.y) * cells + w.x;
          const glm::vec2 site = glm::vec2(q) + sites[i];
          const float d = glm::dot(site - p, site - p);
          if (d < best) {
            best = d;
            best_i = i;
          }
        }
      map.normals[static_cast<std::size_t>(y) * resolution + x] = normals[best_i];
    }
  std::ostringstream d;
  d << "flakes(resolution=" << resolution << ", cells=" << cells << ", alpha=" << alpha << ", seed=" << seed << ")";
  map.description = d.str();
  return map;
}

}  // namespace glintlab
