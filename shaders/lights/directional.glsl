// Directional light (src/scene/lights/directional.cpp), a delta light at infinity. Fields:
// colour_type.rgb: irradiance E at normal incidence [W/m^2]; direction_cos.xyz: travel direction.
#include "lights/light_data.glsl"
#include "lights/light_shapes.glsl"

vec3 directionalLightCentreDirection(LightData L, vec3 p) { return -L.direction_cos.xyz; }

void directionalLightIncidence(LightData L, vec3 p, out vec3 l, out vec3 irradiance) {
  l = -L.direction_cos.xyz;
  irradiance = L.colour_type.rgb;
}
