// The registry of light kinds: one entry per kind, in the order of their GPU codes (which is also
// the order the light loop sums them in: reordering changes images in the last bit).
#include <algorithm>

#include "core/error.hpp"
#include "scene/lights/light_kind.hpp"

namespace glintlab {

LightKind point_light_kind();
LightKind directional_light_kind();
LightKind disk_light_kind();
LightKind sphere_light_kind();
LightKind quad_light_kind();
LightKind sun_light_kind();
LightKind spot_light_kind();
LightKind environment_light_kind();

const std::vector<LightKind>& all_light_kinds() {
  static const std::vector<LightKind> kinds = {point_light_kind(),  directional_light_kind(), disk_light_kind(),
                                               sphere_light_kind(), quad_light_kind(),        sun_light_kind(),
                                               spot_light_kind(),  environment_light_kind()};
  return kinds;
}

int LightKind::code() const {
  const auto& kinds = all_light_kinds();
  return static_cast<int>(this - kinds.data());
}

std::vector<std::string> light_kind_ids() {
  std::vector<std::string> ids;
  for (const auto& k : all_light_kinds()) ids.push_back(k.id);
  return ids;
}

const LightKind& find_light_kind(const std::string& id) {
  const auto& kinds = all_light_kinds();
  auto it = std::find_if(kinds.begin(), kinds.end(), [&](const LightKind& k) { return k.id == id; });
  if (it != kinds.end()) return *it;
  std::string known;
  for (const auto& k : kinds) known += (known.empty() ? "" : ", ") + k.id;
  throw InputError("unknown light type \"" + id + "\"; registered: " + known);
}

}  // namespace glintlab
