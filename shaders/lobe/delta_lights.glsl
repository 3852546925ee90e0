// Point and delta directional lights shaded with a lobe: exact for every method, since a delta
// light has nothing to filter at the light's end. The lobe carries any filtering of the NDF at
// the surface's end (lobe/lobe.glsl); the light's incidence is lights/lights.glsl's.
#include "core/brdf.glsl"
#include "lights/lights.glsl"
#include "lobe/lobe.glsl"
#include "core/surface.glsl"

Radiance shadeDeltaLight(Surface s, Lobe lobe, LightData L, vec3 wo) {
  vec3 l, irradiance;
  deltaLightIncidence(L, s.position, l, irradiance);
  vec3 wi = toLocal(s, l);
  return Radiance(diffuseCos(s.diffuse, wi) * irradiance, lobeSpecularCos(lobe, wo, wi, s.f0) * irradiance);
}
