// Method `chermain2021`: Chermain et al. 2021, geometric glint anti-aliasing (each cell's
// marginals filtered by the pixel's half-vector footprint, eq. 19) and the slope correlation rho
// (eq. 18) on the glinty BRDF of 2020. With rho = 0 and kernel = 0 it equals `chermain2020`.
// Lights with extent: the pixel's kernel widened by the light's half-vector region, or the light
// as a point at its centre (parameter light_extent).
// Descriptor: src/shading/methods/chermain2021.cpp; docs/methods.md#chermain2021.
#include "glints/chermain/light_kernel.glsl"

#if MATERIAL_KIND == MATERIAL_KIND_GLINTY
GlintSurface gGlint;
#endif

// The screen-space derivatives of the half vector towards light direction l (2021, sec. 6.1):
// of its projection h.xy (eq. 21, after Tokuyoshi & Kaplanyan 2019) or of its slope (eq. 20).
// Call in uniform control flow. (From the pixel footprint alone, without the quad: core/footprint.glsl,
// halfVectorProjectedDerivatives, and halfVectorSlopeDerivatives negated.)
void halfVectorDerivatives(Surface s, vec3 l, bool ofSlopes, out vec2 dx, out vec2 dy) {
  vec3 h = normalize(toLocal(s, s.view) + toLocal(s, l));
  vec2 v = ofSlopes ? -h.xy / max(h.z, 1e-3) : h.xy;
  dx = dFdxFine(v);
  dy = dFdyFine(v);
}

void prepareSurface(inout Surface s) {
#if MATERIAL_KIND == MATERIAL_KIND_GLINTY
  gGlint = prepareGlints(s, materials[uMaterial], param_lean == LEAN_ON, true);
#endif
}

Radiance shadeLight(Surface s, LightData L) {
#if MATERIAL_KIND == MATERIAL_KIND_GLINTY
  vec3 l, irradiance;
  centreLightIncidence(L, s.position, l, irradiance);
  vec2 dx, dy;
  halfVectorDerivatives(s, l, param_derivatives == DERIVATIVES_SLOPES, dx, dy);  // first: uniform control flow
  dx *= param_kernel;
  dy *= param_kernel;
  // Lights with extent: the pixel's kernel widened by the light's half-vector region
  // (glints/chermain/light_kernel.glsl); a constant condition.
  if (param_light_extent == LIGHT_EXTENT_HALF_VECTOR_KERNEL && lightHasExtent(L)) addLightRegionToKernel(s, L, l, dx, dy);
  return shadeGlints(s, gGlint, l, irradiance, dx, dy, true);
#else
  return shadeLobe(s, L, materialSmoothLobe(s));
#endif
}
