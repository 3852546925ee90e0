// The reference's estimator of one light with extent at one surface point, sample by sample: multiple
// importance sampling of the light and of the material (power heuristic, Veach 1997) with
// low-discrepancy samples stratified over the pixel's k x k sub-pixels. Each sample is a direction,
// the distance to the light along it and its weighted contribution; whether the light is visible
// there is the caller's: the raster reference (passes/reference.glsl) takes every sample as
// visible (it has no shadows), the path tracer (passes/path_direct.comp) traces a shadow ray for
// each. The material is its kind's, through the material interface (materialSpecularCos, ...).
#include "core/brdf.glsl"
#include "core/frame.glsl"
#include "lights/lights.glsl"
#include "core/sampling.glsl"
#include "core/surface.glsl"

// Below this alpha the material is treated as a perfect mirror (a delta BRDF).
const float REFERENCE_MIRROR_ALPHA = 1e-4;

// Where a sub-pixel's samples of one light come from: its slice of its pixel's sequence, and the
// sequence's rotations for the light's and the material's samples (Cranley-Patterson).
struct ReferenceStream {
  uint first;
  uint count;     // samples per light and sub-pixel (frame.tile.z)
  uint subpixel;  // the sub-pixel's index in its pixel
  vec2 rotLight;
  vec2 rotBrdf;
};

// The stream of light `lightIndex` (its place in the light loop) at sub-pixel `global`: the
// sub-pixel's coordinates in the film's grid of k x k sub-pixels per pixel (k = frame.target.z,
// GL's y up); frame.tile.w is the pass's seed.
ReferenceStream referenceStream(ivec2 global, uint lightIndex) {
  int k = frame.target.z;
  ivec2 pixel = global / k;
  ivec2 sub = global - pixel * k;
  uint n = uint(max(frame.tile.z, 1));
  uint seed = hash3(uvec3(uvec2(pixel), lightIndex * 9781u + uint(frame.tile.w)));
  ReferenceStream st;
  st.subpixel = uint(sub.y * k + sub.x);
  st.first = st.subpixel * n;
  st.count = n;
  st.rotLight = hashToUnit2(seed);
  st.rotBrdf = hashToUnit2(pcgHash(seed + 1u));
  return st;
}

// Whether the reference takes the surface as a perfect mirror (no glinty kind allows it).
bool referenceMirror(Surface s) { return max(s.alpha.x, s.alpha.y) < REFERENCE_MIRROR_ALPHA; }

// One sample: towards `dir` (world space), the light `dist` away; its contribution if the light is
// visible there. dist = 0: no sample (nothing to add).
struct ReferenceSample {
  vec3 dir;
  float dist;
  vec3 diffuse;
  vec3 specular;
};

const ReferenceSample NO_REFERENCE_SAMPLE = ReferenceSample(vec3(0.0, 0.0, 1.0), 0.0, vec3(0.0), vec3(0.0));

// Sample j of the light's own density: the diffuse term, and the specular one weighted against the
// material's density (none for a mirror).
ReferenceSample referenceLightSample(Surface s, LightData L, vec3 wo, bool mirror, ReferenceStream st, uint j) {
  vec3 dir;
  float dist, pdfLight;
  if (!sampleLightDirection(L, s.position, r2Point(st.first + j, st.rotLight), dir, dist, pdfLight) || pdfLight <= 0.0)
    return NO_REFERENCE_SAMPLE;
  vec3 wi = toLocal(s, dir);
  if (wi.z <= 0.0) return NO_REFERENCE_SAMPLE;
  vec3 radiance = lightRadianceFrom(L, dir);
  ReferenceSample r = ReferenceSample(dir, dist, materialDiffuseCos(s, wi) * radiance / pdfLight, vec3(0.0));
  if (!mirror) {
    float w = powerHeuristic(pdfLight, materialSamplePdf(s, wo, wi));
    r.specular = materialLightIntegrand(s, wo, wi) * radiance * (w / pdfLight);
  }
  return r;
}

// Sample j of the material's density that reaches the light, weighted against the light's density.
ReferenceSample referenceBrdfSample(Surface s, LightData L, vec3 wo, bool mirror, ReferenceStream st, uint j) {
  if (mirror) return NO_REFERENCE_SAMPLE;
  vec3 h = materialSampleNormal(s, wo, r2Point(st.first + j, st.rotBrdf));
  vec3 wi = reflect(-wo, h);
  vec3 dirWorld = toWorld(s, wi);
  float dist;
  if (wi.z <= 0.0 || !lightHit(L, s.position, dirWorld, dist)) return NO_REFERENCE_SAMPLE;
  float pdfBrdf = materialSamplePdf(s, wo, wi);
  if (pdfBrdf <= 0.0) return NO_REFERENCE_SAMPLE;
  float pdfL = lightPdf(L, s.position, dirWorld, dist);
  return ReferenceSample(dirWorld, dist, vec3(0.0),
                         materialLightIntegrand(s, wo, wi) * lightRadianceFrom(L, dirWorld) *
                             (powerHeuristic(pdfBrdf, pdfL) / pdfBrdf));
}

// A mirror's one reflected ray, if it reaches the light: the whole specular term.
ReferenceSample referenceMirrorSample(Surface s, LightData L, vec3 wo) {
  float dist;
  vec3 r = reflect(-s.view, s.normal);
  if (!lightHit(L, s.position, r, dist)) return NO_REFERENCE_SAMPLE;
  return ReferenceSample(r, dist, vec3(0.0), fresnelSchlick(s.f0, wo.z) * lightRadianceFrom(L, r));
}

// A kind's per-light factor on the specular term (binomial glints' count of facets towards a
// compact light); under an environment the material's BRDF as evaluated (docs/methods.md,
// "Environment lights").
float referenceSpecularFactor(Surface s, LightData L, vec3 wo, ReferenceStream st) {
  return lightIsCompact(L) ? materialLightFactor(s, L, wo, st.subpixel, st.rotLight, st.rotBrdf) : 1.0;
}
