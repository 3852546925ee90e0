// Point light: intensity I [W/sr] from a point; a delta light (shaders/lights/point.glsl).
#include "scene/lights/light_kind.hpp"
#include "scene/lights/light_keys.hpp"

namespace glintlab {

LightKind point_light_kind() {
  return {
      .id = "point",
      .has_extent = false,
      .distant = false,
      .form = LightForm::None,
      .parse =
          [](TomlReader& r, const std::filesystem::path&) {
            Light l;
            l.position = r.require_vec3("position");
            l.colour = r.get_colour("intensity", glm::vec3(1.0f), 0.0, light_keys::kMaxPower);
            return l;
          },
      .pack =
          [](const Light& l) {
            LightGpu g{};
            g.colour_type = glm::vec4(l.colour, 0.0f);
            g.position_radius = glm::vec4(l.position, 0.0f);
            return g;
          },
      .emitter = nullptr,
  };
}

}  // namespace glintlab
