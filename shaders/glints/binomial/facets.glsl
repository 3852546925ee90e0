// A binomial-glints surface as one fixed field of mirror facets: the ground truth of the binomial
// glint methods that shares none of their approximations (docs/methods.md#kneiphof2024, "A surface
// of facets"; the reference backend `raster-facets`). The surface is cut into square uv cells of
// area e^-log_density, one facet each (the material's facets per unit of uv area); a facet's slope
// is drawn from the material's GGX slope density P22 by its cell's own hash (a stream no method
// reads), so a facet's normal m has the density D(m) m.z, the projected-area law of a heightfield's
// facets. Nothing depends on a pixel, its footprint or a light: every sample that lands in a cell
// sees the same facet, and the number of a region's facets that reflect a light is binomial by
// construction (the facets are independent draws), not by a sampled law.
//
// Lights with extent: each facet a mirror, blurred by a GGX lobe of roughness
// BINOMIAL_FACET_ROUGHNESS about m, so that the reference's MIS can integrate it. Per facet,
// f cos = F(wo.h) G2(wo, wi) D_b(h; m) (h.m) / (4 wo.z h.z) (wo, wi, h in the macro frame, G2 the
// material's Smith term), whose integral over a light is F G2 (wo.m) / (wo.z m.z) L(reflect(wo, m))
// as b -> 0; its mean over facets of density D(m) m.z is the smooth microfacet BRDF's integral
// exactly, for every alpha, so dense facets converge to the smooth material.
// Delta lights reflect off no mirror. As in the counting model (p = R D(h) / D(0)), a facet
// reflects a delta light when its slope lies within sqrt(R) / h.z^2 (in units of alpha, about the
// half vector's slope: a slope-space disk of the counting model's mass R D(h) / D(0) to first
// order), and it then returns the smooth BRDF divided by the disk's exact mass under P22: the mean
// over facets is the smooth BRDF, and the count of reflecting facets in a pixel is binomial.
#include "core/brdf.glsl"
#include "core/random.glsl"
#include "lobe/light_image.glsl"

// The facets' own roughness under lights with extent: mirrors to within a milliradian, so their
// mean is the smooth material's to (b / alpha)^2 (4e-4 at alpha 0.05).
const float BINOMIAL_FACET_ROUGHNESS = 1e-3;
// Salt of the facets' stream (the first 32 bits of sqrt(2)'s fraction): no method hashes with it.
const uint BINOMIAL_FACET_STREAM = 0x6a09e667u;

struct BinomialFacet {
  vec3 normal;         // m, in the macro (shading) frame
  vec2 unitSlope;      // its slope over alpha (P22 is 1 / (pi (1 + |u|^2)^2) in these units)
  float microfacetRoughness;  // the material's R (delta lights)
};

// A slope of the GGX density of alpha from u in [0, 1)^2: in units of alpha the radius's CDF is
// q^2 / (1 + q^2) and the angle uniform.
vec2 sampleGgxUnitSlope(vec2 u) {
  float q = sqrt(u.x / (1.0 - u.x));
  float phi = 6.28318530717959 * u.y;
  return q * vec2(cos(phi), sin(phi));
}

// The facet at uv (the material's, its tiling divided out) of a surface of e^logDensity facets
// per unit of uv area. The cell's corner (floor, as float bits) names it, so cells stay distinct
// (up to float resolution) where their integer index would overflow.
BinomialFacet binomialFacetAt(vec2 uv, float logDensity, vec2 alpha, float microfacetRoughness) {
  vec2 cell = floor(uv * exp(0.5 * logDensity));
  uvec4 r = pcg4d(uvec4(floatBitsToUint(cell), BINOMIAL_FACET_STREAM, 0x85a308d3u));
  BinomialFacet f;
  f.unitSlope = sampleGgxUnitSlope(randomUnit2(r.xy));
  vec2 slope = f.unitSlope * max(alpha, vec2(MIN_ALPHA));
  f.normal = normalize(vec3(-slope, 1.0));  // slope = -m.xy / m.z
  f.microfacetRoughness = microfacetRoughness;
  return f;
}

// The blurred mirror's lobe about m: the GGX D of roughness b, with sin^2 from the cross product
// (1 - (h.m)^2 has no digits left at a milliradian).
float binomialFacetLobe(BinomialFacet f, vec3 h) {
  float hm = dot(h, f.normal);
  if (hm <= 0.0) return 0.0;
  vec3 c = cross(h, f.normal);
  float b2 = BINOMIAL_FACET_ROUGHNESS * BINOMIAL_FACET_ROUGHNESS;
  float e = dot(c, c) + hm * hm * b2;
  return b2 / (PI * e * e);
}

// f cos of the facet under lights with extent (above), local directions.
vec3 binomialFacetSpecularCos(BinomialFacet f, vec3 wo, vec3 wi, vec3 f0, vec2 alpha) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  float lobe = binomialFacetLobe(f, h) * dot(h, f.normal);
  // smithG2OverCos = G2 / wo.z.
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * smithG2OverCos(NDF_GGX, wo, wi, alpha) * lobe / h.z);
}

// A reflected direction about the facet (its lobe's normals, D_b(h; m) (h.m)), and its density.
vec3 binomialFacetSampleNormal(BinomialFacet f, vec2 u) {
  vec2 t = sampleGgxUnitSlope(u) * BINOMIAL_FACET_ROUGHNESS;
  vec3 m = f.normal;
  vec3 x = normalize(abs(m.z) < 0.999 ? cross(vec3(0.0, 0.0, 1.0), m) : cross(vec3(1.0, 0.0, 0.0), m));
  vec3 y = cross(m, x);
  return normalize(-t.x * x - t.y * y + m);
}

float binomialFacetSamplePdf(BinomialFacet f, vec3 wo, vec3 wi) {
  vec3 h = normalize(wo + wi);
  float oh = dot(wo, h);
  return oh > 0.0 ? binomialFacetLobe(f, h) * dot(h, f.normal) / (4.0 * oh) : 0.0;
}

// f cos under a delta light (above): the smooth BRDF over the reflecting disk's mass, or 0.
vec3 binomialFacetDeltaSpecularCos(BinomialFacet f, vec3 wo, vec3 wi, vec3 f0, vec2 alpha) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  vec2 halfSlope = -h.xy / (h.z * a);
  float radius = sqrt(f.microfacetRoughness) / (h.z * h.z);
  if (distance(f.unitSlope, halfSlope) >= radius) return vec3(0.0);
  return specularCos(NDF_GGX, wo, wi, alpha, f0) / max(ggxDiskMass(length(halfSlope), radius), 1e-30);
}
