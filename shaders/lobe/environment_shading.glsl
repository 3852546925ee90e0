// An environment light shaded with a lobe by the split sum (Karis 2013, "Real Shading in Unreal
// Engine 4"): the integral of f cos L over the sphere taken as the product of (1) the radiance
// prefiltered by a GGX lobe about the reflected direction (n = v = r; the environment-map
// resource's mip chain, level by the lobe's roughness) and (2) the BRDF's directional albedo,
// f0 A + B (the `dfg` table). Diffuse: the Lambert albedo over pi times the irradiance at the
// shading normal (the resource's irradiance map). A method passes the lobe it filters to
// (toksvig, lean, vlachos, tokuyoshi, kaplanyan-*: their widened roughness then filters
// environment reflections too); methods that do not (glint methods, podee) are given the
// material's smooth lobe (lights/light_loop.glsl). Errors of the split sum (docs/methods.md): the
// n = v = r lobe shape, a GGX chain for Beckmann lobes, the lobe's isotropic equivalent.
#include "core/brdf.glsl"
#include "core/surface.glsl"
#include "lights/environment.glsl"
#include "lobe/dfg.glsl"
#include "lobe/lobe.glsl"

layout(binding = ENVIRONMENT_SPECULAR_UNIT) uniform sampler2D uEnvironmentSpecular;
layout(binding = ENVIRONMENT_IRRADIANCE_UNIT) uniform sampler2D uEnvironmentIrradiance;

// The isotropic roughness of a lobe for the prefiltered chain: of the isotropic lobe whose
// slope-space matrix has the same determinant (the same spread of slopes), with a footprint box
// of half sides b adding its variance b^2 / 3 per axis (A = 2 Sigma; lobe/lobe.glsl).
float lobeEquivalentAlpha(Lobe lobe) {
  mat2 A = lobe.A;
  A[0][0] += 2.0 / 3.0 * lobe.footprint.x * lobe.footprint.x;
  A[1][1] += 2.0 / 3.0 * lobe.footprint.y * lobe.footprint.y;
  return sqrt(sqrt(max(determinant(A), 0.0)));
}

// The chain's level m holds alpha_m = (m / (levels - 1))^2: perceptual roughness is linear in lod.
vec3 environmentPrefilteredRadiance(LightData L, vec3 dir, float alpha) {
  float levels = float(textureQueryLevels(uEnvironmentSpecular));
  float lod = sqrt(clamp(alpha, 0.0, 1.0)) * (levels - 1.0);
  return L.colour_type.rgb * textureLod(uEnvironmentSpecular, environmentUv(L, dir), lod).rgb;
}

vec3 environmentIrradiance(LightData L, vec3 n) {
  return L.colour_type.rgb * textureLod(uEnvironmentIrradiance, environmentUv(L, n), 0.0).rgb;
}

Radiance shadeLobeEnvironment(Surface s, LightData L, Lobe lobe) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  float alpha = lobeEquivalentAlpha(lobe);
  vec3 r = reflect(-s.view, s.normal);
  result.diffuse = s.diffuse * INV_PI * environmentIrradiance(L, s.normal);
  result.specular = environmentPrefilteredRadiance(L, r, alpha) * splitSumSpecularAlbedo(lobe.ndf, s.f0, wo.z, alpha);
  return result;
}
