// A normal-map-glints material under an environment light by Deng et al. 2022's sec. 5.4: the
// environment fitted by spherical Gaussian lobes (resource `environment-lobes`,
// src/prefilter/environment_sg_fit.hpp), each lobe answered by one range query of the footprint's
// P over its half-vector box instead of many samples of the map. Lobe k, a exp(lambda (xi . d - 1)),
// is shaded as a uniform cone about xi of the lobe's own solid angle
// Omega = 2 pi (1 - exp(-2 lambda)) / lambda and power a Omega (eq. 8's support at epsilon = a / e,
// for large lambda), exactly as a sphere light of that cone (glints/normal-map/shading.glsl):
// L_o += a Omega F(v.h_c) G2(v, xi) mean_P / (4 v.z). A cone across the horizon is weighted by its
// share above it (linear in the axis's height across +-sin of its half-angle) and shaded at its
// axis lifted just above it. Or (environment_lobe_cones = three) as three nested uniform cones
// whose heights follow the lobe's radial profile. Diffuse: the split sum's irradiance map about
// the map's filtered normal (lobe/environment_shading.glsl), not the lobes. The host packs each
// lobe's cones (axis, sines of the half-angles) and power, so that no pixel recomputes them.
// Needs shading.glsl included before (normalGlintsBoxMean, normalGlintsSpecularCos) and the
// constant ENVIRONMENT_LOBE_CONES.
#include "generated/gpu_contract.glsl"
#include "lights/light_shapes.glsl"
#include "lobe/environment_shading.glsl"

layout(std430, binding = ENVIRONMENT_LOBES_BINDING) readonly buffer EnvironmentLobes {
  int environmentLobeCount;
  int environmentLobePadding[3];
  // Per lobe: (axis in map space, sine of its cone's half-angle), (RGB power a Omega, 0), the three
  // nested cones' sines (xyz) and their shares of the power (xyz).
  vec4 environmentLobes[];
};

// The lobe's cones (environment_lobe_cones): one uniform cone of its solid angle, or three nested
// cones at its power's quantiles (SphericalGaussian::nested_cones: a layer cake of its radial
// profile), each packed by the host as (sine of its half-angle, its share of the lobe's power).
// The including method defines ENVIRONMENT_LOBE_CONES, 1 or 3, from its parameter.

// The footprint NDF's box queries an environment takes beyond one (the element budget's share).
int environmentExtraQueries() { return max(environmentLobeCount * ENVIRONMENT_LOBE_CONES - 1, 0); }

// Lobe k's specular radiance towards wo (local, above the surface) and, in `axis`, the direction
// (world) it is shaded at: its axis, lifted just above the horizon where it crosses it.
vec3 normalGlintsEnvironmentLobe(Surface s, LightData L, int k, vec3 wo, float maskingAlpha, out vec3 axis) {
  const vec4 cone = environmentLobes[4 * k], power = environmentLobes[4 * k + 1];
  const vec4 nestedSines = environmentLobes[4 * k + 2], nestedShares = environmentLobes[4 * k + 3];
  const float sinHalf = cone.w;
  vec3 lc = toLocal(s, environmentMapToWorld(L, cone.xyz));
  const float above = clamp(0.5 + 0.5 * lc.z / max(sinHalf, 1e-4), 0.0, 1.0);
  lc = normalize(vec3(lc.xy, max(lc.z, 0.02 * sinHalf)));
  axis = toWorld(s, lc);
  if (above <= 0.0) return vec3(0.0);
  vec3 specular = vec3(0.0);
  for (int m = 0; m < ENVIRONMENT_LOBE_CONES; ++m) {
    const float sinCone = ENVIRONMENT_LOBE_CONES == 1 ? sinHalf : nestedSines[m];
    const float share = ENVIRONMENT_LOBE_CONES == 1 ? 1.0 : nestedShares[m];
    vec3 dl1, dl2;
    coneOutline(axis, sinCone, dl1, dl2);
    const HalfVectorBox box = halfVectorBox(wo, lc, toLocal(s, dl1), toLocal(s, dl2));
    const float meanP = normalGlintsBoxMean(box.centre - box.halfExtent, box.centre + box.halfExtent);
    specular += normalGlintsSpecularCos(wo, lc, box.h, meanP, s.f0, maskingAlpha) * share;
  }
  return specular * (L.colour_type.rgb * power.rgb * above);
}

Radiance shadeNormalGlintsEnvironment(Surface s, LightData L, float maskingAlpha, vec3 diffuseNormal) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  result.diffuse = s.diffuse * INV_PI * environmentIrradiance(L, toWorld(s, diffuseNormal));
  vec3 axis;
  for (int k = 0; k < environmentLobeCount; ++k) result.specular += normalGlintsEnvironmentLobe(s, L, k, wo, maskingAlpha, axis);
  return result;
}

#ifndef METHOD_AS_FOOTPRINT_NDF  // the path tracer shades each light itself (passes/path_direct.comp)
// Any light on a normal-map-glints material, for a method that includes this module (yan2016,
// deng2022): compact lights by shading.glsl, an environment by its lobes, or as the material's
// smooth lobe by the split sum where the method has none (environment_lobes = 0).
Radiance shadeNormalGlintsLight(Surface s, LightData L, float maskingAlpha, vec3 diffuseNormal) {
  if (lightIsCompact(L)) return shadeNormalGlints(s, L, maskingAlpha, diffuseNormal);
  return environmentLobeCount > 0 ? shadeNormalGlintsEnvironment(s, L, maskingAlpha, diffuseNormal)
                                  : shadeLobeEnvironment(s, L, materialSmoothLobe(s));
}
#endif
