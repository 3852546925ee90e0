#include "scene/lights/environment_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/image_io.hpp"

namespace glintlab {
namespace {

std::string texel_text(int x, int y, const glm::vec3& c) {
  char text[160];
  std::snprintf(text, sizeof text, "texel (%d, %d) is (%g, %g, %g)", x, y, static_cast<double>(c.r),
                static_cast<double>(c.g), static_cast<double>(c.b));
  return text;
}

/// The source texels [first, first + weights.size()) a target texel averages, with their weights
/// (summing to 1).
struct Footprint {
  int first = 0;
  std::vector<double> weights;
};

/// Target texel t of `targets` over source texels of `sources`, both tiling [0, 1]; `measure(a, b)`
/// is the measure of [a, b] (its length in u, or its solid angle's share in v).
template <class Measure>
std::vector<Footprint> footprints(int sources, int targets, Measure measure) {
  std::vector<Footprint> result(static_cast<std::size_t>(targets));
  for (int t = 0; t < targets; ++t) {
    const double a = double(t) / targets, b = double(t + 1) / targets;
    Footprint& f = result[static_cast<std::size_t>(t)];
    f.first = std::clamp(static_cast<int>(std::floor(a * sources)), 0, sources - 1);
    const int last = std::clamp(static_cast<int>(std::ceil(b * sources)) - 1, f.first, sources - 1);
    double total = 0;
    for (int s = f.first; s <= last; ++s) {
      const double w = measure(std::max(a, double(s) / sources), std::min(b, double(s + 1) / sources));
      f.weights.push_back(std::max(w, 0.0));
      total += f.weights.back();
    }
    for (double& w : f.weights) w = total > 0 ? w / total : 1.0 / double(f.weights.size());
  }
  return result;
}

}  // namespace

glm::dvec3 environment_direction_precise(double u, double v) {
  const double theta = std::numbers::pi * v, phi = 2 * std::numbers::pi * (u - 0.5);
  const double sin_theta = std::sin(theta);
  return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

glm::vec3 environment_direction(double u, double v) { return glm::vec3(environment_direction_precise(u, v)); }

glm::dvec2 environment_uv(glm::dvec3 d) {
  d = glm::normalize(d);
  const double theta = std::acos(std::clamp(d.y, -1.0, 1.0));
  const double phi = std::atan2(d.x, -d.z);  // in [-pi, pi]
  return {std::clamp(phi / (2 * std::numbers::pi) + 0.5, 0.0, 1.0), theta / std::numbers::pi};
}

double environment_row_solid_angle(int y, int height) {
  return 2 * std::numbers::pi / (2.0 * height) * (std::cos(std::numbers::pi * y / height) - std::cos(std::numbers::pi * (y + 1) / height));
}

Image downsample_environment(const Image& radiance, int height) {
  const int w = radiance.width(), h = radiance.height();
  const int target_h = std::clamp(height, 1, h), target_w = 2 * target_h;
  // Along u every texel of a row has the same solid angle: plain overlap lengths. Along v a
  // source row's share is the solid angle of its overlap: 2 pi (cos(theta_a) - cos(theta_b)).
  const auto along_u = footprints(w, target_w, [](double a, double b) { return b - a; });
  const auto along_v = footprints(h, target_h, [](double a, double b) { return std::cos(std::numbers::pi * a) - std::cos(std::numbers::pi * b); });

  std::vector<glm::dvec3> rows(static_cast<std::size_t>(target_w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < target_w; ++x) {
      const Footprint& f = along_u[static_cast<std::size_t>(x)];
      glm::dvec3 sum(0.0);
      for (std::size_t k = 0; k < f.weights.size(); ++k)
        sum += f.weights[k] * glm::dvec3(radiance.at(f.first + static_cast<int>(k), y));
      rows[static_cast<std::size_t>(y) * target_w + x] = sum;
    }
  Image result(target_w, target_h);
  for (int y = 0; y < target_h; ++y) {
    const Footprint& f = along_v[static_cast<std::size_t>(y)];
    for (int x = 0; x < target_w; ++x) {
      glm::dvec3 sum(0.0);
      for (std::size_t k = 0; k < f.weights.size(); ++k)
        sum += f.weights[k] * rows[(static_cast<std::size_t>(f.first) + k) * target_w + x];
      result.at(x, y) = glm::vec3(sum);
    }
  }
  return result;
}

EnvironmentMap load_environment_map(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string allowed = "allowed: an OpenEXR lat-long map, twice as wide as it is high, at least " +
                              std::to_string(kMinEnvironmentWidth) + " x " + std::to_string(kMinEnvironmentWidth / 2);
  if (file_kind(path) == FileKind::missing)
    throw InputError(name + ": environment map not found (no such file); " + allowed);
  if (const FileKind kind = file_kind(path); kind != FileKind::regular)
    throw InputError(name + ": environment map is " + std::string(describe(kind)) + "; " + allowed);
  Image image;
  try {
    image = read_exr(path);
  } catch (const InputError& e) {  // read_exr's message names the file and why
    throw InputError(std::string("environment map ") + e.what() + "; " + allowed);
  }
  const int w = image.width(), h = image.height();
  const std::string size = std::to_string(w) + " x " + std::to_string(h);
  if (w != 2 * h)
    throw InputError(name + ": environment map is " + size +
                     ", not 2:1; a lat-long map is twice as wide as it is high (e.g. 2048 x 1024)");
  if (w < kMinEnvironmentWidth)
    throw InputError(name + ": environment map is " + size + "; " + allowed);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::vec3& c = image.at(x, y);
      if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
        throw InputError(name + ": environment map " + texel_text(x, y, c) +
                         ", not finite; allowed: finite radiance >= 0 in every channel");
      if (c.r < 0 || c.g < 0 || c.b < 0)
        throw InputError(name + ": environment map " + texel_text(x, y, c) +
                         ", negative; allowed: radiance >= 0 in every channel");
    }
  // Power-of-two box reduction to at most kMaxEnvironmentWidth: the light is the reduced map.
  int factor = 1;
  while (w / factor > kMaxEnvironmentWidth) factor *= 2;
  if (factor > 1) image = downsample_environment(image, h / factor);
  return {std::move(image), name};
}

EnvironmentMap uniform_environment_map(glm::vec3 radiance) {
  return {Image(kUniformEnvironmentWidth, kUniformEnvironmentWidth / 2, radiance), "uniform"};
}

}  // namespace glintlab
