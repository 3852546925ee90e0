#include "scene/normal_maps/normal_map.hpp"

#include <cmath>
#include <fstream>
#include "core/math.hpp"
#include <glm/gtc/constants.hpp>
#include <random>
#include <sstream>

#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/image_io.hpp"
#include "scene/normal_maps/bump_waves.hpp"
#include "scene/normal_maps/parallel_rows.hpp"

namespace glintlab {

namespace {

/// By the file's magic number, not its name: an EXR is raw normals whatever it is called.
bool is_exr(const std::filesystem::path& path) {
  unsigned char magic[4] = {};
  std::ifstream(path, std::ios::binary).read(reinterpret_cast<char*>(magic), sizeof magic);
  return magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

/// Why a raw EXR normal is refused, or nullptr. Renormalising fixes small errors (half floats,
/// filtering); a length far from 1 means the file holds something else (0.5 (n + 1) encoding,
/// heights, colours).
const char* refusal(glm::vec3 n) {
  if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z)) return "not finite";
  if (!(n.z > 0.0f)) return "z <= 0 (below the surface)";
  const float length = glm::length(n);
  if (!(length >= 0.5f && length <= 1.5f)) return "length far from 1";
  return nullptr;
}

/// An EXR whose every x and y is >= 0 and whose 2 v - 1 has unit length holds 0.5 (n + 1), the
/// PNG encoding (a flat texel (0.5, 0.5, 1) has length 1.22, inside the per-texel limits).
bool looks_offset_encoded(const Image& img) {
  double raw_length = 0.0, decoded_length = 0.0;
  for (const glm::vec3& v : img.pixels()) {
    if (v.x < 0.0f || v.y < 0.0f) return false;
    raw_length += glm::length(v);
    decoded_length += glm::length(2.0f * v - 1.0f);
  }
  const double n = static_cast<double>(img.pixel_count());
  return std::abs(decoded_length / n - 1.0) < 0.05 && std::abs(raw_length / n - 1.0) > 0.1;
}

}  // namespace

NormalMap load_normal_map(const std::filesystem::path& path) {
  require_regular_file(path, "normal map");
  const bool raw = is_exr(path);
  int channels = 3;
  const Image img = raw ? read_exr(path) : read_ldr_image(path, &channels);
  if (channels < 3)
    throw InputError(path.string() + ": a greyscale image (" + std::to_string(channels) +
                     (channels == 1 ? " channel" : " channels") + "); allowed: an RGB normal map (x, y, z in R, G, B)");
  if (raw && looks_offset_encoded(img))
    throw InputError(path.string() + ": holds 0.5 (n + 1) (every x and y >= 0, and 2 v - 1 has unit length); "
                     "allowed: an EXR's R, G, B are the normal's raw components (-1 .. 1), or a PNG in 0.5 (n + 1)");
  const int w = img.width(), h = img.height();
  NormalMap map{w, h, {}, "file " + path.filename().string()};
  map.normals.resize(img.pixel_count());
  // The first refused texel of each of the file's rows (-1: none), so the message names the same
  // texel on any thread count: the first in file order.
  std::vector<int> refused(static_cast<std::size_t>(raw ? h : 0), -1);
  for_each_row(
      h, row_workers(h),
      [&](int y, int) {
        // +Y is up in the image (the OpenGL and glTF convention), which is glintlab's +v: the
        // bottom row is v = 0 and comes first.
        glm::vec3* out = map.normals.data() + static_cast<std::size_t>(h - 1 - y) * w;
        for (int x = 0; x < w; ++x) {
          if (raw) {
            const glm::vec3 n = img.at(x, y);
            if (refusal(n) != nullptr) {
              refused[static_cast<std::size_t>(y)] = x;
              return;
            }
            out[x] = glm::normalize(n);
            continue;
          }
          glm::vec3 n = 2.0f * img.at(x, y) - 1.0f;
          n.z = std::max(n.z, 1e-3f);  // never below the surface
          out[x] = glm::normalize(n);
        }
      },
      map.description);
  for (int y = 0; y < static_cast<int>(refused.size()); ++y) {
    const int x = refused[static_cast<std::size_t>(y)];
    if (x < 0) continue;
    const glm::vec3 n = img.at(x, y);
    std::ostringstream m;
    m << path.string() << ": texel (" << x << ", " << y << ") (from the top-left) holds (" << n.x << ", " << n.y
      << ", " << n.z << "): " << refusal(n)
      << "; allowed: an EXR's R, G, B are the normal's raw components, finite, z > 0, length 0.5 .. 1.5";
    throw InputError(m.str());
  }
  return map;
}

NormalMap generate_bumps(int resolution, float slope_sigma, int waves, int max_frequency, std::uint32_t seed,
                         float anisotropy, float angle_degrees) {
  const BumpSpectrum spectrum = choose_bump_waves(slope_sigma, waves, max_frequency, seed, anisotropy, angle_degrees);
  std::ostringstream d;
  d << "bumps(resolution=" << resolution << ", alpha=" << slope_sigma << ", waves=" << waves
    << ", max_frequency=" << max_frequency << ", seed=" << seed << ", anisotropy=" << anisotropy
    << ", angle=" << angle_degrees << ")";
  return {resolution, resolution, bump_normals(spectrum, resolution, d.str()), d.str()};
}

NormalMap generate_brushed(int resolution, float alpha, float along_alpha, float angle_degrees, int waves,
                           int max_frequency, std::uint32_t seed) {
  const BumpSpectrum spectrum = choose_brushed_waves(alpha, along_alpha, angle_degrees, waves, max_frequency, seed);
  std::ostringstream d;
  d << "brushed(resolution=" << resolution << ", alpha=" << alpha << ", along_alpha=" << along_alpha
    << ", angle=" << angle_degrees << ", waves=" << waves << ", max_frequency=" << max_frequency << ", seed=" << seed
    << ")";
  return {resolution, resolution, bump_normals(spectrum, resolution, d.str()), d.str()};
}

NormalMap generate_flakes(int resolution, int cells, float alpha, std::uint32_t seed, float jitter,
                          float flat_fraction) {
  std::ostringstream d;
  d << "flakes(resolution=" << resolution << ", cells=" << cells << ", alpha=" << alpha << ", seed=" << seed
    << ", jitter=" << jitter << ", flat_fraction=" << flat_fraction << ")";
  const std::string what = d.str();
  // The cells in order (their random numbers are one sequence), then the texels on every thread.
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  // Which cells stay flat: a stream of its own, so the sites and normals do not depend on it and a
  // cell flat at one fraction stays flat at every larger one.
  std::mt19937 flat_rng(seed ^ 0x9e3779b9u);
  const auto count = static_cast<std::size_t>(cells) * static_cast<std::size_t>(cells);
  std::vector<glm::vec2> sites(count);
  std::vector<glm::vec3> normals(count);
  report_generation_progress(what + " cells", 0, cells);
  for (int row = 0; row < cells; ++row) {
    for (std::size_t i = static_cast<std::size_t>(row) * cells; i < static_cast<std::size_t>(row + 1) * cells; ++i) {
      // centre + jitter (U - 1/2), written so jitter 1 gives U exactly (the maps before `jitter`).
      // (The same expression as before, so the two draws go to the same axes.)
      sites[i] = jitter * glm::vec2(uni(rng), uni(rng)) + 0.5f * (1.0f - jitter);
      // Beckmann sampling: tan^2(theta) = -alpha^2 ln(1 - u).
      const float tan2 = -alpha * alpha * std::log(1.0f - uni(rng));
      const float phi = glm::two_pi<float>() * uni(rng);
      const float cos_t = 1.0f / std::sqrt(1.0f + tan2);
      const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
      normals[i] = glm::vec3(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
      if (uni(flat_rng) < flat_fraction) normals[i] = glm::vec3(0.0f, 0.0f, 1.0f);
    }
    if ((row + 1) % 64 == 0 || row + 1 == cells) report_generation_progress(what + " cells", row + 1, cells);
  }
  // Toroidal cell index; no division for the cells inside the tile (most of them).
  auto wrap = [cells](int q) { return q >= 0 && q < cells ? q : (q % cells + cells) % cells; };
  NormalMap map{resolution, resolution, {}, what};
  map.normals.resize(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution));
  for_each_row(
      resolution, row_workers(resolution),
      [&](int y, int) {
        for (int x = 0; x < resolution; ++x) {
          const glm::vec2 p = (glm::vec2(x, y) + 0.5f) / static_cast<float>(resolution) * static_cast<float>(cells);
          const glm::ivec2 c = glm::ivec2(glm::floor(p));
          float best = 1e30f;
          std::size_t best_i = 0;
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const glm::ivec2 q = c + glm::ivec2(dx, dy);
              const std::size_t i = static_cast<std::size_t>(wrap(q.y)) * cells + wrap(q.x);
              const glm::vec2 site = glm::vec2(q) + sites[i];
              const float dist = glm::dot(site - p, site - p);
              if (dist < best) {
                best = dist;
                best_i = i;
              }
            }
          map.normals[static_cast<std::size_t>(y) * resolution + x] = normals[best_i];
        }
      },
      what);
  return map;
}

}  // namespace glintlab
