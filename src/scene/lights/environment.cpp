// Environment: radiance arriving from every direction at infinity, a lat-long map of linear
// radiance [W/(m^2 sr)] (`file`) or one radiance (`radiance`), scaled by `intensity` and turned by
// `rotation` degrees about +y, or a procedural map (`generator`) (shaders/lights/environment.glsl; the map's convention:
// src/scene/lights/environment_map.hpp). Not a compact emitter: the reference samples it by its
// luminance (its `environment-map` resource's CDF), the lobe methods read its prefiltered
// mip chain (split sum), and camera rays that miss the scene see it when it is `visible`.
#include <cmath>

#include "core/error.hpp"
#include "scene/lights/environment_glint_levels.hpp"
#include "scene/lights/environment_map.hpp"
#include "scene/lights/environment_studio.hpp"
#include "scene/lights/light_keys.hpp"
#include "scene/lights/light_kind.hpp"

namespace glintlab {

LightKind environment_light_kind() {
  return {
      .id = "environment",
      .has_extent = true,
      .distant = true,
      .form = LightForm::None,
      .compact = false,
      .parse =
          [](TomlReader& r, const std::filesystem::path& base_dir) {
            Light l;
            const int sources = int(r.has("file")) + int(r.has("radiance")) + int(r.has("generator"));
            if (sources != 1)
              r.fail(r.has("file") ? "file" : "radiance",
                     std::string(sources ? "is given with another source" : "is required") +
                         "; allowed: exactly one of radiance = [r, g, b] (uniform), file = \"map.exr\" "
                         "(lat-long, linear radiance) or generator = \"studio\"");
            if (r.has("generator")) {
              r.require_string("generator", {"studio"});
              l.environment = std::make_shared<EnvironmentMap>(studio_environment_map());
            } else if (r.has("file")) {
              const std::string file = r.require_string("file");
              try {
                l.environment = std::make_shared<EnvironmentMap>(load_environment_map(base_dir / file));
              } catch (const InputError& e) {
                r.fail("file", e.what());
              }
            } else {
              l.environment = std::make_shared<EnvironmentMap>(
                  uniform_environment_map(r.get_colour("radiance", glm::vec3(1.0f), 0.0, light_keys::kMaxPower)));
            }
            l.colour = glm::vec3(static_cast<float>(r.get_number("intensity", 1.0, 0.0, light_keys::kMaxPower)));
            l.rotation_degrees = static_cast<float>(r.get_number("rotation", 0.0, -360.0, 360.0));
            l.visible = r.get_bool("visible", true);
            return l;
          },
      .pack =
          [](const Light& l) {
            const double turn = static_cast<double>(l.rotation_degrees) * (3.14159265358979323846 / 180.0);
            const Image& map = l.environment->radiance;
            bool sampleable = false;  // a black map has no luminance to sample by
            for (const glm::vec3& texel : map.pixels()) sampleable = sampleable || luminance(texel) > 0.0f;
            LightGpu g{};
            g.colour_type = glm::vec4(l.colour, 0.0f);
            g.position_radius = glm::vec4(static_cast<float>(std::cos(turn)), static_cast<float>(std::sin(turn)),
                                          static_cast<float>(map.width()), static_cast<float>(map.height()));
            g.direction_cos = glm::vec4(sampleable ? 1.0f : 0.0f, l.visible ? 1.0f : 0.0f, 0.0f, 0.0f);
            // Its luminance levels L_1 .. L_3 for glints under it (environment_glint_levels.hpp).
            const auto levels = environment_glint_luminance_levels(map);
            g.axis_u = glm::vec4(levels[1], levels[2], levels[3], 0.0f);
            return g;
          },
      .emitter = nullptr,  // seen where camera rays miss: the background pass (shaders/passes/background.frag)
      .resources = {"environment-map", "table:dfg"},
  };
}

}  // namespace glintlab
