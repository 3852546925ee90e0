// A normal-map-glints material under an environment light by Deng et al. 2022's sec. 5.4: the
// environment fitted by spherical Gaussian lobes (resource `environment-lobes`,
// src/prefilter/environment_sg_fit.hpp), each lobe answered by one range query of the footprint's
// P over its half-vector box instead of many samples of the map. Lobe k, a exp(lambda (xi . d - 1)),
// is shaded as a uniform cone about xi of the lobe's own solid angle
// Omega = 2 pi (1 - exp(-2 lambda)) / lambda and power a Omega (eq. 8's support at epsilon = a / e,
// for large lambda), exactly as a sphere light of that cone (glints/normal-map/shading.glsl):
// L_o += a Omega F(v.h_c) G2(v, xi) mean_P / (4 v.z). A cone across the horizon is weighted by its
// share above it (linear in the axis's height across +-sin of its half-angle) and shaded at its
// axis lifted just above it. Diffuse: the split sum's irradiance map about the map's filtered
// normal (lobe/environment_shading.glsl), not the lobes. The host packs each lobe's cone (axis,
// sine of the half-angle) and power, so that no pixel recomputes them.
// Needs shading.glsl included before (normalGlintsBoxMean, normalGlintsSpecularCos).
#include "generated/gpu_contract.glsl"
#include "lights/light_shapes.glsl"
#include "lobe/environment_shading.glsl"

layout(std430, binding = ENVIRONMENT_LOBES_BINDING) readonly buffer EnvironmentLobes {
  int environmentLobeCount;
  int environmentLobePadding[3];
  vec4 environmentLobes[];  // per lobe: (axis in map space, sin of the cone's half-angle), (RGB power a Omega, 0)
};

Radiance shadeNormalGlintsEnvironment(Surface s, LightData L, float maskingAlpha, vec3 diffuseNormal) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  result.diffuse = s.diffuse * INV_PI * environmentIrradiance(L, toWorld(s, diffuseNormal));
  for (int k = 0; k < environmentLobeCount; ++k) {
    const vec4 cone = environmentLobes[2 * k], power = environmentLobes[2 * k + 1];
    const float sinHalf = cone.w;
    vec3 lc = toLocal(s, environmentMapToWorld(L, cone.xyz));
    const float above = clamp(0.5 + 0.5 * lc.z / max(sinHalf, 1e-4), 0.0, 1.0);
    if (above <= 0.0) continue;
    lc = normalize(vec3(lc.xy, max(lc.z, 0.02 * sinHalf)));
    vec3 dl1, dl2;
    coneOutline(toWorld(s, lc), sinHalf, dl1, dl2);
    const HalfVectorBox box = halfVectorBox(wo, lc, toLocal(s, dl1), toLocal(s, dl2));
    const float meanP = normalGlintsBoxMean(box.centre - box.halfExtent, box.centre + box.halfExtent);
    result.specular += normalGlintsSpecularCos(wo, lc, box.h, meanP, s.f0, maskingAlpha) *
                       (L.colour_type.rgb * power.rgb * above);
  }
  return result;
}

// Any light on a normal-map-glints material, for a method that includes this module (yan2016,
// deng2022): compact lights by shading.glsl, an environment by its lobes, or as the material's
// smooth lobe by the split sum where the method has none (environment_lobes = 0).
Radiance shadeNormalGlintsLight(Surface s, LightData L, float maskingAlpha, vec3 diffuseNormal) {
  if (lightIsCompact(L)) return shadeNormalGlints(s, L, maskingAlpha, diffuseNormal);
  return environmentLobeCount > 0 ? shadeNormalGlintsEnvironment(s, L, maskingAlpha, diffuseNormal)
                                  : shadeLobeEnvironment(s, L, materialSmoothLobe(s));
}
