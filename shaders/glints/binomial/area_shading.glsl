// Glints under lights with extent by Kneiphof & Klein 2024 (docs/methods.md#kneiphof2024), on the
// binomial-glints material of Deliot & Belcour 2023: the facets that reflect a light are counted
// with the probability p of glints/binomial/light_probability.glsl instead of Deliot's R D(h) / D(0),
// and their share found over the share expected, the glint factor g = share / p (E[g] = 1),
// scales the smooth GGX's light integral: specular = g x integral over the light of f cos L dl.
// The count is drawn at the slope-grid cell of the half vector towards the light's centre.
#include "core/driver_profile.glsl"
#include "glints/binomial/shading.glsl"
#include "glints/binomial/light_probability.glsl"

// What the LTCs of a pixel's binomial-glints lobe need that is the same for every light (the
// roughness and the view): computed once per pixel (prepareSurface).
struct GlintLtc {
  mat3 ndfMinv;    // the D-only LTC's M^-1 in the view's frame (table ltc-ndf)
  mat3 ggxMinv;    // the GGX LTC's (table ltc-ggx)
  float ndfScale;  // its magnitude / T: p = ndfScale x the LTC's integral over the light
  vec3 ggxScale;   // the GGX lobe's integral with Schlick's Fresnel
  float alpha;     // the isotropic alpha the tables and T are read at
  float totalNdf;  // T
};

GlintLtc glintLtc(Surface s) {
  vec3 wo = toLocal(s, s.view);
  float alpha = glintIsotropicAlpha(s.alpha);
  float totalNdf = ggxTotalNdf(alpha);
  mat3 frame = ltcViewFrame(wo);
  return GlintLtc(ltcInverseMatrix(uLtcNdf, alpha, wo.z) * frame, ltcInverseMatrix(uLtcGgx, alpha, wo.z) * frame,
                  ltcTerms(uLtcNdf, alpha, wo.z).x / totalNdf, ltcSpecularScale(ltcTerms(uLtcGgx, alpha, wo.z), s.f0),
                  alpha, totalNdf);
}

// The smooth specular integral over a light with extent (per unit radiance, Fresnel included) and
// p, each as the LTC's for large lights and the point form's (the BRDF at the centre x solid
// angle; the small-cap p) for small ones (small in their largest extent), blended by glintCapWeight.
struct GlintLightIntegral {
  vec3 specular;  // integral of f cos over the light / radiance
  float p;        // unclamped
  vec3 hCentre;   // local half vector towards the light's centre: where the count is drawn
};

// The weight of the small cap's estimates for a light seen in local direction wi (glintCapWeight).
float glintLightCapWeight(Surface s, GlintLtc ltc, LightData L, vec3 wo, vec3 wi, vec3 centreDir, float solidAngle) {
  float angularRadius = lightLargestAngularRadius(L, s.position, centreDir, solidAngle);
  return glintCapWeight(angularRadius, abs(dot(wi, normalize(wo + wi))), ltc.alpha);
}

// The two estimates of p and the cap's weight: (LTC, small cap, weight of the cap). `ltcIntegral`:
// the integral over the light of the LTC that p's shape is taken from (the D-only table's, or the
// GGX lobe's when reused: glintLightIntegral).
vec3 glintProbabilityEstimates(Surface s, GlintLtc ltc, LightData L, vec3 wo, vec3 centreDir, float solidAngle,
                               float ltcIntegral) {
  vec3 wi = toLocal(s, centreDir);
  float pCap = glintCapProbability(wo, wi, solidAngle, s.alpha, ltc.totalNdf);
  return vec3(ltc.ndfScale * ltcIntegral, pCap, glintLightCapWeight(s, ltc, L, wo, wi, centreDir, solidAngle));
}

// `reuseGgxShape` (a constant at every call; kneiphof2024's light_probability = ggx-ltc): p's
// integral is the GGX lobe's, scaled by the D-only magnitude, instead of its own LTC's. The blend
// of the LTC's and the cap's terms by the cap's weight w is a weighted sum whose sides are
// computed where their weight is not 0 (core/driver_profile.glsl: the hardware profile skips the
// LTC's integrals for small lights and the cap's terms for large ones).
GlintLightIntegral glintLightIntegral(Surface s, GlintLtc ltc, LightData L, LtcLightForm form, vec3 wo,
                                      vec3 centreDir, float solidAngle, const bool reuseGgxShape) {
  vec3 wi = toLocal(s, centreDir);
  float w = glintLightCapWeight(s, ltc, L, wo, wi, centreDir, solidAngle);
  GlintLightIntegral g = GlintLightIntegral(vec3(0.0), 0.0, normalize(wo + wi));
  if (blendSideNeeded(w < 1.0)) {
    float ggxIntegral = ltcLightIntegral(form, L, ltc.ggxMinv);
    float shape = reuseGgxShape ? ggxIntegral : ltcLightIntegral(form, L, ltc.ndfMinv);
    g.specular += (1.0 - w) * (ltc.ggxScale * ggxIntegral);
    g.p += (1.0 - w) * (ltc.ndfScale * shape);
  }
  if (blendSideNeeded(w > 0.0)) {
    g.specular += w * (specularCos(NDF_GGX, wo, wi, s.alpha, s.f0) * solidAngle);
    g.p += w * glintCapProbability(wo, wi, solidAngle, s.alpha, ltc.totalNdf);
  }
  return g;
}

// The glint factor g = share / p of the footprint's facets for probability p at half vector h
// (p > 1 can come from the small-cap estimate of a large light on a sharp lobe: clamped, as the
// paper does, so every facet reflects and g = 1; p = 0: nothing reflects).
float glintFactor(BinomialSurface b, vec3 h, float p, int model) {
  if (!(p > 0.0)) return 0.0;
  float pc = min(p, 1.0);
  return binomialReflectingShare(b, h.xy * b.slopeGridScale, pc, model) / pc;
}

// A delta light: p = R D(h) / D(0) as the material defines it for lights of no size (Deliot &
// Belcour's, as in deliot2023 and the reference), or the small cap of solid angle
// `pointSolidAngle` > 0 (Kneiphof & Klein's sun, 6.8e-5 sr).
Radiance shadeBinomialDeltaGlints(Surface s, BinomialSurface b, LightData L, float pointSolidAngle, int model) {
  vec3 l, irradiance;
  deltaLightIncidence(L, s.position, l, irradiance);
  vec3 wo = toLocal(s, s.view), wi = toLocal(s, l);
  Radiance result = Radiance(diffuseCos(s.diffuse, wi) * irradiance, vec3(0.0));
  if (wo.z <= 0.0 || wi.z <= 0.0) return result;
  vec3 h = normalize(wo + wi);
  vec2 a = max(s.alpha, vec2(MIN_ALPHA));
  float e = (h.x * h.x) / (a.x * a.x) + (h.y * h.y) / (a.y * a.y) + h.z * h.z;
  float p = pointSolidAngle > 0.0
                ? glintCapProbability(wo, wi, pointSolidAngle, s.alpha, ggxTotalNdf(glintIsotropicAlpha(s.alpha)))
                : b.microfacetRoughness / (e * e);
  result.specular = glintFactor(b, h, p, model) * specularCos(NDF_GGX, wo, wi, s.alpha, s.f0) * irradiance;
  return result;
}
