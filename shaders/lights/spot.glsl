// Spot light (src/scene/lights/spot.cpp), a delta light: a point light whose intensity falls off
// away from its axis (KHR_lights_punctual). Fields: colour_type.rgb: intensity I [W/sr] on the
// axis; position_radius.xyz: position; direction_cos.xyz: the unit axis it shines along, w: cos of
// the outer angle; axisU.x: 1 / max(0.001, cos inner - cos outer).
#include "lights/light_data.glsl"
#include "lights/light_shapes.glsl"
#include "lights/point.glsl"

vec3 spotLightCentreDirection(LightData L, vec3 p) { return pointLightCentreDirection(L, p); }

// KHR_lights_punctual's falloff of the direction l from p towards the light: with cd the cosine
// between the axis and -l, clamp((cd - cos outer) / (cos inner - cos outer), 0, 1)^2, the
// spec's cd * scale + offset with the subtraction first (exactly 0 outside the outer cone).
float spotLightFalloff(LightData L, vec3 l) {
  float t = clamp((dot(L.direction_cos.xyz, -l) - L.direction_cos.w) * L.axis_u.x, 0.0, 1.0);
  return t * t;
}

// Irradiance at normal incidence: the point light's I / d^2 times the falloff.
void spotLightIncidence(LightData L, vec3 p, out vec3 l, out vec3 irradiance) {
  pointLightIncidence(L, p, l, irradiance);
  irradiance *= spotLightFalloff(L, l);
}
