// Point and delta directional lights: exact for every method and for the reference, since a
// delta light has nothing to filter at the light's end. The lobe carries any filtering of the
// NDF at the surface's end (common/lobe.glsl).
#include "common/brdf.glsl"
#include "common/lights.glsl"
#include "common/lobe.glsl"
#include "common/surface.glsl"

// Unit direction from p to a point or delta directional light, and its irradiance at normal incidence.
void deltaLightIncidence(LightData L, vec3 p, out vec3 l, out vec3 irradiance) {
  if (lightType(L) == LIGHT_POINT) {
    vec3 d = L.position_radius.xyz - p;
    float d2 = max(dot(d, d), 1e-12);
    l = d * inversesqrt(d2);
    irradiance = L.colour_type.rgb / d2;
  } else {
    l = -L.direction_cos.xyz;
    irradiance = L.colour_type.rgb;
  }
}

Radiance shadeDeltaLight(Surface s, Lobe lobe, LightData L, vec3 wo) {
  vec3 l, irradiance;
  deltaLightIncidence(L, s.position, l, irradiance);
  vec3 wi = toLocal(s, l);
  return Radiance(diffuseCos(s.diffuse, wi) * irradiance, lobeSpecularCos(lobe, wo, wi, s.f0) * irradiance);
}
