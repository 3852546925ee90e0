// Directional light: irradiance E [W/m^2] at normal incidence from one direction; a delta light
// (shaders/lights/directional.glsl). With an angular radius it is a sun (sun.cpp): scenes written
// before the sun kind existed keep their meaning.
#include "scene/lights/light_kind.hpp"
#include "scene/lights/light_keys.hpp"

namespace glintlab {

LightKind directional_light_kind() {
  return {
      .id = "directional",
      .has_extent = false,
      .distant = true,
      .form = LightForm::None,
      .parse =
          [](TomlReader& r, const std::filesystem::path&) {
            Light l;
            l.direction = light_keys::require_direction(r, "direction");
            l.colour = r.get_colour("irradiance", glm::vec3(1.0f), 0.0, light_keys::kMaxPower);
            l.angular_radius_degrees = static_cast<float>(r.get_number("angular_radius", 0.0, 0.0, 45.0));
            if (l.angular_radius_degrees > 0.0f) l.kind = &find_light_kind("sun");
            return l;
          },
      .pack =
          [](const Light& l) {
            LightGpu g{};
            g.colour_type = glm::vec4(l.colour, 0.0f);
            g.direction_cos = glm::vec4(l.direction, 1.0f);
            return g;
          },
      .emitter = nullptr,
  };
}

}  // namespace glintlab
