#include "scene/lights/environment_studio.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace glintlab {

namespace {

glm::dvec3 direction_of(double elevation_degrees, double azimuth_degrees) {
  // Azimuth about +y from -z (the map's centre) towards +x.
  const double e = elevation_degrees * std::numbers::pi / 180.0, a = azimuth_degrees * std::numbers::pi / 180.0;
  return {std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a)};
}

}  // namespace

EnvironmentMap studio_environment_map(int width) {
  const int height = width / 2;
  const glm::dvec3 sun = direction_of(35.0, 40.0);
  const double sun_cos = std::cos(1.5 * std::numbers::pi / 180.0);
  // Soft boxes: centre direction, angular half sizes (elevation, azimuth) in degrees, radiance.
  struct Box {
    double elevation, azimuth, half_elevation, half_azimuth;
    glm::vec3 radiance;
  };
  const Box boxes[] = {{20.0, -60.0, 12.0, 8.0, {6.0f, 6.0f, 6.2f}}, {50.0, 150.0, 6.0, 20.0, {3.0f, 3.2f, 3.6f}}};
  Image map(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double u = (x + 0.5) / width, v = (y + 0.5) / height;
      const glm::dvec3 d = environment_direction_precise(u, v);
      const double elevation = 90.0 - 180.0 * v, azimuth = 360.0 * (u - 0.5);
      glm::vec3 radiance;
      if (d.y >= 0.0) {
        const auto t = static_cast<float>(std::pow(1.0 - d.y, 3.0));  // 1 at the horizon
        radiance = glm::mix(glm::vec3(0.25f, 0.38f, 0.7f), glm::vec3(0.9f, 0.85f, 0.8f), t);
      } else {
        radiance = glm::vec3(0.08f, 0.07f, 0.06f);
      }
      for (const Box& b : boxes) {
        double da = std::remainder(azimuth - b.azimuth, 360.0);
        if (std::abs(elevation - b.elevation) < b.half_elevation && std::abs(da) < b.half_azimuth) radiance = b.radiance;
      }
      if (glm::dot(d, sun) > sun_cos) radiance = glm::vec3(2000.0f, 1900.0f, 1700.0f);
      map.at(x, y) = radiance;
    }
  return {std::move(map), "studio"};
}

}  // namespace glintlab
