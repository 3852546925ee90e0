// Ground truth for one sub-pixel sample: the material's exact BRDF at this sub-pixel, lights with
// extent integrated by multiple importance sampling of the light and the BRDF (power heuristic,
// Veach 1997) with low-discrepancy samples stratified over the pixel's k x k sub-pixels.
// Never uses the approximations of any method. Included in place of a method module; the material
// is its kind's, through the material interface (the forward pass's $MATERIAL: materialPrepare,
// materialSpecularCos, ...; src/render/shader_contract.cpp), so this file names no kind. Lights
// that are not compact (an environment) are integrated here too: their radiance is read per
// direction (lightRadianceFrom), sampled by the light's own density.
#define METHOD_SHADES_ENVIRONMENT
#include "passes/reference_estimator.glsl"

uint gReferenceLightIndex = 0u;

// Ground truth takes the surface as it is; a glinty material's patch-SDF (or binomial grids) is
// that of the sub-pixel's footprint (the papers' protocol).
void prepareSurface(inout Surface s) { materialPrepare(s, materials[uMaterial]); }

// Every sample counts: the raster reference has no shadows.
Radiance shadeLight(Surface s, LightData L) {
  uint lightIndex = gReferenceLightIndex++;
  Radiance result = Radiance(vec3(0.0), vec3(0.0));
  vec3 wo = toLocal(s, s.view);
  if (wo.z <= 0.0) return result;

  if (!lightHasExtent(L)) {
    vec3 l, irradiance;
    deltaLightIncidence(L, s.position, l, irradiance);
    vec3 wi = toLocal(s, l);
    return Radiance(materialDiffuseCos(s, wi) * irradiance, materialSpecularCos(s, wo, wi) * irradiance);
  }

  ReferenceStream st = referenceStream(frame.tile.xy + ivec2(gl_FragCoord.xy), lightIndex);
  bool mirror = referenceMirror(s);
  for (uint j = 0u; j < st.count; ++j) {
    ReferenceSample a = referenceLightSample(s, L, wo, mirror, st, j);
    result.diffuse += a.diffuse;
    result.specular += a.specular;
    result.specular += referenceBrdfSample(s, L, wo, mirror, st, j).specular;
  }
  result.diffuse /= float(st.count);
  result.specular /= float(st.count);
  result.specular *= referenceSpecularFactor(s, L, wo, st);
  if (mirror) {
    ReferenceSample m = referenceMirrorSample(s, L, wo);
    if (m.dist > 0.0) result.specular = m.specular;
  }
  return result;
}
