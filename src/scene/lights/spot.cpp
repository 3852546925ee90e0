// Spot light: a point light whose intensity I [W/sr] (on its axis) falls off between an inner and
// an outer cone about the axis, as KHR_lights_punctual defines it; a delta light
// (shaders/lights/spot.glsl).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "scene/lights/light_kind.hpp"
#include "scene/lights/light_keys.hpp"

namespace glintlab {

namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

/// KHR_lights_punctual's reference code: the falloff is linear in cos over [cos outer, cos inner],
/// a transition at least 0.001 wide in cos (inner and outer angles that nearly coincide).
double falloff_scale(double cos_inner, double cos_outer) { return 1.0 / std::max(0.001, cos_inner - cos_outer); }

}  // namespace

LightKind spot_light_kind() {
  return {
      .id = "spot",
      .has_extent = false,
      .distant = false,
      .form = LightForm::None,
      .parse =
          [](TomlReader& r, const std::filesystem::path&) {
            Light l;
            l.position = r.require_vec3("position");
            l.direction = light_keys::require_direction(r, "direction");
            l.colour = r.get_colour("intensity", glm::vec3(1.0f), 0.0, light_keys::kMaxPower);
            const double inner = r.get_number("inner_angle", 0.0, 0.0, 90.0);
            const double outer = r.get_number("outer_angle", 45.0, 0.0, 90.0);
            if (inner >= outer) {
              std::ostringstream s;
              s << "value " << inner << " is not below outer_angle (" << outer
                << "); allowed: 0 <= inner_angle < outer_angle <= 90 degrees";
              r.fail("inner_angle", s.str());
            }
            l.inner_angle_degrees = static_cast<float>(inner);
            l.outer_angle_degrees = static_cast<float>(outer);
            return l;
          },
      .pack =
          [](const Light& l) {
            // The cones' cosines in double; the shader evaluates (cos - cos outer) * scale, so that
            // everything outside the outer cone gets exactly 0.
            const double cos_inner = std::cos(static_cast<double>(l.inner_angle_degrees) * kDegrees);
            const double cos_outer = std::cos(static_cast<double>(l.outer_angle_degrees) * kDegrees);
            LightGpu g{};
            g.colour_type = glm::vec4(l.colour, 0.0f);
            g.position_radius = glm::vec4(l.position, 0.0f);
            g.direction_cos = glm::vec4(l.direction, static_cast<float>(cos_outer));
            g.axis_u = glm::vec4(static_cast<float>(falloff_scale(cos_inner, cos_outer)), 0.0f, 0.0f, 0.0f);
            return g;
          },
      .emitter = nullptr,
  };
}

}  // namespace glintlab
