// One fixed realisation of a binomial-glints surface's microfacets: the reference of the physical
// question (docs/methods.md#kneiphof2024, "Two references"), independent of any light. Per surface
// vertex, each lattice point c of its slope grid stands for the facets whose normals fall in the
// unit cell around it in slope-grid units: A_c = 1 / (scale^2 h_c.z) of solid angle about its
// half vector h_c (dh = d(h.xy) / h.z). It holds k_c of the vertex's n facets, drawn by the
// counting model's law with p_c = D(h_c) A_c / T and the point's own random numbers (the same as
// the counting model's); the realisation's NDF blends the points' densities k_c T / (n A_c)
// bilinearly, so E[D_real(h)] is D interpolated between the points. A light integrates it like
// any NDF; no glint factor, no p of the light.
#include "glints/binomial/ndf.glsl"
#include "core/brdf.glsl"
#include "glints/binomial/light_probability.glsl"

float binomialRealisationNdf(BinomialSurface b, vec3 h, vec2 alpha, int model) {
  if (h.z <= 0.0) return 0.0;
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  float totalNdf = ggxTotalNdf(glintIsotropicAlpha(alpha));
  float scale = b.slopeGridScale;
  float sum = 0.0;
  for (int i = 0; i < BINOMIAL_VERTICES; ++i) {
    BinomialVertex v = b.vertices[i];
    vec2 s = h.xy * scale + v.slopeOffset;
    vec2 c = floor(s), f = s - c;
    float density = 0.0;
    for (int k = 0; k < 4; ++k) {
      ivec2 corner = ivec2(k & 1, k >> 1);
      ivec2 cell = ivec2(c) + corner;
      vec2 centre = (vec2(cell) - v.slopeOffset) / scale;  // h_c.xy
      float r2 = dot(centre, centre);
      if (r2 >= 1.0) continue;  // below the horizon: no facets
      float hz = sqrt(1.0 - r2);
      float area = 1.0 / (scale * scale * hz);
      float p = min(ndfGGX(vec3(centre, hz), a) * area / totalNdf, 1.0);
      float p1 = probabilityAnyReflects(p, v.facets);
      vec2 law = remainingLaw(p, v.facets, p1, model);
      uvec4 r = pcg4d(uvec4(uvec2(cell), v.key));
      vec2 bilinear = mix(1.0 - f, f, vec2(corner));
      float count = reflectionGate(p1, randomUnit2(r.xy).x) *
                    countGivenAny(law, v.facets, randomNormal(randomUnit2(r.zw)), model);
      density += bilinear.x * bilinear.y * count / area;
    }
    sum += v.perFacet * density;
  }
  return sum * totalNdf;
}

// f cos of the realisation for local directions: the material's GGX BRDF with D_real.
vec3 binomialRealisationSpecularCos(BinomialSurface b, vec3 wo, vec3 wi, vec3 f0, vec2 alpha) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  float d = binomialRealisationNdf(b, h, alpha, REMAINING_COUNT_LOGNORMAL);
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * d * smithG2OverCos(NDF_GGX, wo, wi, alpha));
}
