// Method `yan2016`: Yan et al. 2016's position-normal distribution of the pixel's Gaussian footprint,
// by brute force over the normal map's elements (glints/normal-map/position_normal.glsl), on
// `normal-map-glints` materials: the baseline whose cost grows with the footprint, up to
// `max_elements`, past which a stratified subset of the elements stands for them all. Delta lights
// take P at the half vector; lights with extent its mean over their half-vector box. Other
// materials are shaded as by `conventional` (lights with extent by LTC).
// Descriptor: src/shading/methods/yan2016.cpp; docs/methods.md#yan2016.
#define METHOD_LOBES_KEEP_ISOTROPY  // its lobes are the material's own (lobe/lobe_shading.glsl)
#define METHOD_SHADES_ENVIRONMENT   // normal-map-glints by the environment's lobes; others as conventional
#include "lobe/lobe.glsl"
#include "lobe/lobe_shading.glsl"


#if MATERIAL_KIND == MATERIAL_KIND_NORMAL_MAP_GLINTS
const int ELEMENTS_PER_TEXEL = param_elements_per_texel == ELEMENTS_PER_TEXEL_2 ? 2 : 1;
#if !MATERIAL_WANG_TILES  // a Wang-tiled surface's elements are made from its texels (no storage per texel)
#define POSITION_NORMAL_STORED_ELEMENTS  // the material's elements, computed once (resource position-normal-elements)
#endif
#include "glints/normal-map/position_normal.glsl"

PositionNormalFootprint gFootprint;
float gMaskingAlpha;
vec3 gDiffuseNormal;  // the map's filtered normal in the macro frame, for Lambert

float normalGlintsDensity(vec2 s) { return positionNormalDensity(uNormalMap, gFootprint, ELEMENTS_PER_TEXEL, s); }
float normalGlintsBoxMean(vec2 lo, vec2 hi) {
  return positionNormalBoxMean(uNormalMap, gFootprint, ELEMENTS_PER_TEXEL, lo, hi);
}
#include "glints/normal-map/shading.glsl"
const int ENVIRONMENT_LOBE_CONES = param_environment_lobe_cones == ENVIRONMENT_LOBE_CONES_THREE ? 3 : 1;
#include "glints/normal-map/environment_lobes.glsl"
// The footprint NDF's queries per pixel beyond one per light, which share the element budget: the
// environment's lobes (the path tracer's footprint material counts its samples instead).
#ifndef NORMAL_GLINTS_EXTRA_QUERIES
#define NORMAL_GLINTS_EXTRA_QUERIES environmentExtraQueries()
#endif

// The pixel footprint's P-NDF at this point: its elements (the budget's subset past max_elements).
void normalGlintsPrepareFootprint(inout Surface s) {
  gDiffuseNormal = normalGlintsMacroFrame(s);
  ivec2 size = normalMapSize();
  mat2 sigmaP = footprintTexelCovariance(s.footprint, size, param_footprint_sigma);
  MaterialData m = materials[uMaterial];
  gFootprint = positionNormalFootprint(fract(s.uv) * vec2(size), sigmaP, size, ELEMENTS_PER_TEXEL,
                                       normalMapGlintsIntrinsicRoughness(m),
                                       positionNormalElementBudget(param_max_elements, NORMAL_GLINTS_EXTRA_QUERIES));
#ifdef POSITION_NORMAL_STORED_ELEMENTS
  gFootprint.firstElement = positionNormalFirstElement[uMaterial];
#endif
  gMaskingAlpha = normalMapGlintsMaskingAlpha(m);
}

#ifdef METHOD_AS_FOOTPRINT_NDF
// Importance sampling of the footprint's P-NDF, for the path tracer (`path:yan2016`): an element by
// its weight, then its Gaussian (glints/normal-map/ndf_sampling.glsl); the mixture is normalised.
#include "glints/normal-map/ndf_sampling.glsl"
float normalGlintsSamplePdf(vec2 s) { return normalGlintsDensity(s); }
NdfSample normalGlintsSampleNdf(uint seed, vec2 u) {
  return positionNormalSample(uNormalMap, gFootprint, ELEMENTS_PER_TEXEL, seed, u);
}
#endif

#endif

#include "glints/normal-map/method_entry_points.glsl"
