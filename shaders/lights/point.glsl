// Point light (src/scene/lights/point.cpp), a delta light. Fields: colour_type.rgb: intensity
// I [W/sr]; position_radius.xyz: position.
#include "lights/light_data.glsl"
#include "lights/light_shapes.glsl"

vec3 pointLightCentreDirection(LightData L, vec3 p) { return directionTowards(L.position_radius.xyz, p); }

// Irradiance at normal incidence: I / d^2.
void pointLightIncidence(LightData L, vec3 p, out vec3 l, out vec3 irradiance) {
  vec3 d = L.position_radius.xyz - p;
  float d2 = max(dot(d, d), 1e-12);
  l = d * inversesqrt(d2);
  irradiance = L.colour_type.rgb / d2;
}
