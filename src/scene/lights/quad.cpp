// Quad light: a one-sided rectangle of radiance L [W/(m^2 sr)] (shaders/lights/quad.glsl).
#include <glm/gtc/matrix_transform.hpp>

#include "scene/lights/light_kind.hpp"
#include "scene/lights/light_keys.hpp"

namespace glintlab {

LightKind quad_light_kind() {
  return {
      .id = "quad",
      .has_extent = true,
      .distant = false,
      .form = LightForm::Polygon,
      .parse =
          [](TomlReader& r, const std::filesystem::path&) {
            Light l = light_keys::parse_area_light(r);
            l.size = r.get_vec2("size", glm::vec2(1.0f), 1e-6, light_keys::kMaxLength);
            l.up = r.get_vec3("up", glm::vec3(0, 0, 1));
            l.direction = light_keys::require_direction(r, "direction");
            if (glm::length(glm::cross(l.direction, l.up)) < 1e-6f * glm::length(l.up))
              r.fail("up", "is parallel to direction or zero; it must orient the quad");
            return l;
          },
      .pack =
          [](const Light& l) {
            // Half edges: u = up x normal, v = normal x u (docs/scene-format.md).
            const glm::vec3 u = glm::normalize(glm::cross(l.up, l.direction));
            const glm::vec3 v = glm::cross(l.direction, u);
            LightGpu g{};
            g.colour_type = glm::vec4(l.colour, 0.0f);
            g.position_radius = glm::vec4(l.position, 0.0f);
            g.direction_cos = glm::vec4(l.direction, 1.0f);
            g.axis_u = glm::vec4(0.5f * l.size.x * u, 0.0f);
            g.axis_v = glm::vec4(0.5f * l.size.y * v, 0.0f);
            return g;
          },
      .emitter =
          [](const Light& l) -> std::optional<LightEmitter> {
            if (!l.visible) return std::nullopt;
            return LightEmitter{make_plane(l.size, 1.0f),
                                glm::translate(glm::mat4(1.0f), l.position) * light_keys::orient_y_to(l.direction, l.up),
                                l.colour, false};
          },
  };
}

}  // namespace glintlab
