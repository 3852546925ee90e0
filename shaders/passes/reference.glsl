// Ground truth for one sub-pixel sample: the material's exact BRDF at this sub-pixel, lights with
// extent integrated by multiple importance sampling of the light and the BRDF (power heuristic,
// Veach 1997) with low-discrepancy samples stratified over the pixel's k x k sub-pixels.
// Never uses the approximations of any method. Included in place of a method module; the material
// is its kind's, through the material interface (the forward pass's $MATERIAL: materialPrepare,
// materialSpecularCos, ...; src/render/shader_contract.cpp), so this file names no kind. Lights
// that are not compact (an environment) are integrated here too: their radiance is read per
// direction (lightRadianceFrom), sampled by the light's own density.
#define METHOD_SHADES_ENVIRONMENT
#include "core/brdf.glsl"
#include "core/frame.glsl"
#include "lights/lights.glsl"
#include "core/sampling.glsl"
#include "core/surface.glsl"

// Below this alpha the material is treated as a perfect mirror (a delta BRDF).
const float REFERENCE_MIRROR_ALPHA = 1e-4;

uint gReferenceLightIndex = 0u;

// Ground truth takes the surface as it is; a glinty material's patch-SDF (or binomial grids) is
// that of the sub-pixel's footprint (the papers' protocol).
void prepareSurface(inout Surface s) { materialPrepare(s, materials[uMaterial]); }

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

  int k = frame.target.z;
  ivec2 global = frame.tile.xy + ivec2(gl_FragCoord.xy);
  ivec2 pixel = global / k;
  ivec2 sub = global - pixel * k;
  uint n = uint(max(frame.tile.z, 1));
  uint first = uint(sub.y * k + sub.x) * n;  // this sub-pixel's slice of the pixel's sequence
  uint seed = hash3(uvec3(uvec2(pixel), lightIndex * 9781u + uint(frame.tile.w)));
  vec2 rotLight = hashToUnit2(seed);
  vec2 rotBrdf = hashToUnit2(pcgHash(seed + 1u));
  bool mirror = max(s.alpha.x, s.alpha.y) < REFERENCE_MIRROR_ALPHA;  // no glinty kind allows it

  for (uint j = 0u; j < n; ++j) {
    vec3 dir;
    float dist, pdfLight;
    if (sampleLightDirection(L, s.position, r2Point(first + j, rotLight), dir, dist, pdfLight) && pdfLight > 0.0) {
      vec3 wi = toLocal(s, dir);
      if (wi.z > 0.0) {
        vec3 radiance = lightRadianceFrom(L, dir);
        result.diffuse += materialDiffuseCos(s, wi) * radiance / pdfLight;
        if (!mirror) {
          float w = powerHeuristic(pdfLight, materialSamplePdf(s, wo, wi));
          result.specular += materialLightIntegrand(s, wo, wi) * radiance * (w / pdfLight);
        }
      }
    }
    if (!mirror) {
      vec3 h = materialSampleNormal(s, wo, r2Point(first + j, rotBrdf));
      vec3 wi = reflect(-wo, h);
      vec3 dirWorld = toWorld(s, wi);
      if (wi.z > 0.0 && lightHit(L, s.position, dirWorld, dist)) {
        float pdfBrdf = materialSamplePdf(s, wo, wi);
        float pdfL = lightPdf(L, s.position, dirWorld, dist);
        if (pdfBrdf > 0.0)
          result.specular += materialLightIntegrand(s, wo, wi) * lightRadianceFrom(L, dirWorld) *
                             (powerHeuristic(pdfBrdf, pdfL) / pdfBrdf);
      }
    }
  }
  result.diffuse /= float(n);
  result.specular /= float(n);
  // A kind's per-light factor (binomial glints' count of facets towards a compact light); under an
  // environment the material's BRDF as evaluated (docs/methods.md, "Environment lights").
  if (lightIsCompact(L)) result.specular *= materialLightFactor(s, L, wo, uint(sub.y * k + sub.x), rotLight, rotBrdf);
  if (mirror) {
    float dist;
    vec3 r = reflect(-s.view, s.normal);
    if (lightHit(L, s.position, r, dist)) result.specular = fresnelSchlick(s.f0, wo.z) * lightRadianceFrom(L, r);
  }
  return result;
}
