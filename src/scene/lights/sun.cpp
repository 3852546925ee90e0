// Sun: a distant disk of angular radius theta and irradiance E [W/m^2] at normal incidence, i.e.
// radiance E / (pi sin^2 theta) over a cone of directions (shaders/lights/sun.glsl).
#include <cmath>

#include "scene/lights/light_kind.hpp"
#include "scene/lights/light_keys.hpp"

namespace glintlab {

LightKind sun_light_kind() {
  return {
      .id = "sun",
      .has_extent = true,
      .distant = true,
      .form = LightForm::Disk,
      .parse =
          [](TomlReader& r, const std::filesystem::path&) {
            Light l;
            l.direction = light_keys::require_direction(r, "direction");
            l.colour = r.get_colour("irradiance", glm::vec3(1.0f), 0.0, light_keys::kMaxPower);
            l.angular_radius_degrees = static_cast<float>(r.get_number("angular_radius", 0.27, 1e-6, 45.0));
            return l;
          },
      .pack =
          [](const Light& l) {
            // The cone in double: 1 - cos = 2 sin^2(theta / 2) keeps its precision at small angles,
            // where 1 - cos in float would not (shaders/lights/sun.glsl, sunOneMinusCos).
            const double theta = static_cast<double>(l.angular_radius_degrees) * (3.14159265358979323846 / 180.0);
            const double half_sin = std::sin(0.5 * theta);
            LightGpu g{};
            g.colour_type = glm::vec4(l.colour, 0.0f);
            g.direction_cos = glm::vec4(l.direction, static_cast<float>(std::cos(theta)));
            g.axis_u = glm::vec4(0.0f, 0.0f, 0.0f, static_cast<float>(2.0 * half_sin * half_sin));
            return g;
          },
      .emitter = nullptr,
  };
}

}  // namespace glintlab
