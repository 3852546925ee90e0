// Sphere light: a sphere of radiance L [W/(m^2 sr)] (shaders/lights/sphere.glsl).
#include <glm/gtc/matrix_transform.hpp>

#include "scene/lights/light_kind.hpp"
#include "scene/lights/light_keys.hpp"

namespace glintlab {

LightKind sphere_light_kind() {
  return {
      .id = "sphere",
      .has_extent = true,
      .distant = false,
      .form = LightForm::Disk,
      .parse =
          [](TomlReader& r, const std::filesystem::path&) {
            Light l = light_keys::parse_area_light(r);
            l.radius = static_cast<float>(r.require_number("radius", 1e-6, light_keys::kMaxLength));
            return l;
          },
      .pack =
          [](const Light& l) {
            LightGpu g{};
            g.colour_type = glm::vec4(l.colour, 0.0f);
            g.position_radius = glm::vec4(l.position, l.radius);
            return g;
          },
      .emitter =
          [](const Light& l) -> std::optional<LightEmitter> {
            if (!l.visible) return std::nullopt;
            return LightEmitter{make_sphere(l.radius, 48, 24), glm::translate(glm::mat4(1.0f), l.position), l.colour,
                                true};
          },
  };
}

}  // namespace glintlab
