// The GGX NDF's mass over a light's half-vector image, integral over the light (above the
// surface's horizon) of D(h) / (4 |l.h|) dl, by multiple importance sampling of the light and of
// the visible normals (power heuristic): `count` samples of each, points first .. first + count - 1
// of the R2 sequence rotated by rotLight and rotBrdf. The numerical integral the binomial-glints
// reference counts facets with, and what tests hold the LTC and small-cap estimates against.
#include "core/brdf.glsl"
#include "lights/lights.glsl"
#include "core/sampling.glsl"
#include "core/surface.glsl"

float lightNdfIntegral(Surface s, LightData L, vec3 wo, uint first, uint count, vec2 rotLight, vec2 rotBrdf) {
  float sum = 0.0;
  for (uint j = 0u; j < count; ++j) {
    vec3 dir;
    float dist, pdfLight;
    if (sampleLightDirection(L, s.position, r2Point(first + j, rotLight), dir, dist, pdfLight) && pdfLight > 0.0) {
      vec3 wi = toLocal(s, dir);
      if (wi.z > 0.0) {
        vec3 h = normalize(wo + wi);
        float f = ndfGGX(h, s.alpha) / (4.0 * abs(dot(wi, h)));
        sum += f * powerHeuristic(pdfLight, ggxVisibleReflectionPdf(wo, wi, s.alpha)) / pdfLight;
      }
    }
    vec3 h = sampleGGXVisibleNormal(wo, s.alpha, r2Point(first + j, rotBrdf));
    vec3 wi = reflect(-wo, h);
    vec3 dirWorld = toWorld(s, wi);
    if (wi.z > 0.0 && lightHit(L, s.position, dirWorld, dist)) {
      float pdfBrdf = ggxVisibleReflectionPdf(wo, wi, s.alpha);
      float f = ndfGGX(h, s.alpha) / (4.0 * abs(dot(wi, h)));
      if (pdfBrdf > 0.0) sum += f * powerHeuristic(pdfBrdf, lightPdf(L, s.position, dirWorld, dist)) / pdfBrdf;
    }
  }
  return sum / float(count);
}
