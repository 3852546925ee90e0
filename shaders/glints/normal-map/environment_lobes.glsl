// A normal-map-glints material under an environment light by Deng et al. 2022's sec. 5.4: the
// environment fitted by spherical Gaussian lobes (resource `environment-lobes`,
// src/prefilter/environment_sg_fit.hpp), each lobe answered by one range query of the footprint's
// P over its half-vector box instead of many samples of the map. Lobe k, a exp(lambda (xi . d - 1)),
// is shaded as a uniform cone of radiance a about xi with the lobe's own solid angle
// Omega = 2 pi (1 - exp(-2 lambda)) / lambda (so its power a Omega is the lobe's; eq. 8's support
// at epsilon = a / e for large lambda), exactly as a sphere light of that cone
// (glints/normal-map/shading.glsl): L_o += a Omega F(v.h_c) G2(v, xi) mean_P / (4 v.z). Lobes whose
// axis is below the horizon are skipped (their part above it is lost; a lobe across it is counted
// whole, Fresnel and masking at its axis). Diffuse: the split sum's irradiance map about the map's
// filtered normal (lobe/environment_shading.glsl), not the lobes.
// Needs shading.glsl included before (normalGlintsBoxMean, normalGlintsSpecularCos).
#include "generated/gpu_contract.glsl"
#include "lights/light_shapes.glsl"
#include "lobe/environment_shading.glsl"

layout(std430, binding = ENVIRONMENT_LOBES_BINDING) readonly buffer EnvironmentLobes {
  int environmentLobeCount;
  int environmentLobePadding[3];
  vec4 environmentLobes[];  // per lobe: (axis in map space, sharpness), (RGB amplitude, 0)
};

// The map's space to the world's: the environment's turn about +y (lights/environment.glsl).
vec3 environmentMapToWorld(LightData L, vec3 d) {
  float c = L.position_radius.x, s = L.position_radius.y;
  return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

Radiance shadeNormalGlintsEnvironment(Surface s, LightData L, float maskingAlpha, vec3 diffuseNormal) {
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;
  result.diffuse = s.diffuse * INV_PI * environmentIrradiance(L, toWorld(s, diffuseNormal));
  for (int k = 0; k < environmentLobeCount; ++k) {
    const vec4 shape = environmentLobes[2 * k], amplitude = environmentLobes[2 * k + 1];
    const float lambda = shape.w;
    const float solidAngle = TWO_PI * (1.0 - exp(-2.0 * lambda)) / lambda;
    // The cone of that solid angle: 2 pi (1 - cos) = Omega, its outline's radius the half-angle's sine.
    const float cosHalf = max(1.0 - solidAngle * (0.5 * INV_PI), -1.0);
    const float sinHalf = sqrt(max(1.0 - cosHalf * cosHalf, 0.0));
    // The share of the cone above the horizon, linear in the axis's height across +-sinHalf; a cone
    // across it is shaded at its axis lifted to just above it.
    vec3 lc = toLocal(s, environmentMapToWorld(L, shape.xyz));
    const float above = clamp(0.5 + 0.5 * lc.z / max(sinHalf, 1e-4), 0.0, 1.0);
    if (above <= 0.0) continue;
    lc = normalize(vec3(lc.xy, max(lc.z, 0.02 * sinHalf)));
    const vec3 axis = toWorld(s, lc);
    vec3 dl1, dl2;
    coneOutline(axis, sinHalf, dl1, dl2);
    const HalfVectorBox box = halfVectorBox(wo, lc, toLocal(s, dl1), toLocal(s, dl2));
    const float meanP = normalGlintsBoxMean(box.centre - box.halfExtent, box.centre + box.halfExtent);
    result.specular += normalGlintsSpecularCos(wo, lc, box.h, meanP, s.f0, maskingAlpha) *
                       (L.colour_type.rgb * amplitude.rgb * (solidAngle * above));
  }
  return result;
}
