// Disk light: a one-sided disk of radiance L [W/(m^2 sr)] (shaders/lights/disk.glsl).
#include <glm/gtc/matrix_transform.hpp>

#include "scene/lights/light_kind.hpp"
#include "scene/lights/light_keys.hpp"

namespace glintlab {

LightKind disk_light_kind() {
  return {
      .id = "disk",
      .has_extent = true,
      .distant = false,
      .form = LightForm::Disk,
      .parse =
          [](TomlReader& r, const std::filesystem::path&) {
            Light l = light_keys::parse_area_light(r);
            l.radius = static_cast<float>(r.require_number("radius", 1e-6, light_keys::kMaxLength));
            l.direction = light_keys::require_direction(r, "direction");
            return l;
          },
      .pack =
          [](const Light& l) {
            LightGpu g{};
            g.colour_type = glm::vec4(l.colour, 0.0f);
            g.position_radius = glm::vec4(l.position, l.radius);
            g.direction_cos = glm::vec4(l.direction, 1.0f);
            return g;
          },
      .emitter =
          [](const Light& l) -> std::optional<LightEmitter> {
            if (!l.visible) return std::nullopt;
            return LightEmitter{make_disk(l.radius, 96),
                                glm::translate(glm::mat4(1.0f), l.position) * light_keys::orient_y_to(l.direction, l.up),
                                l.colour, false};
          },
  };
}

}  // namespace glintlab
