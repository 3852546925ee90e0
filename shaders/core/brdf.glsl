// Microfacet BRDF: anisotropic GGX or Beckmann NDF, height-correlated Smith masking-shadowing,
// Schlick Fresnel; Lambert diffuse. Directions are in the local shading frame (z = normal).
#include "core/constants.glsl"

// GGX (Trowbridge-Reitz) NDF, Walter et al. 2007 eq. 33 with Heitz 2014's anisotropic form.
float ndfGGX(vec3 h, vec2 alpha) {
  if (h.z <= 0.0) return 0.0;
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  float e = (h.x * h.x) / (a.x * a.x) + (h.y * h.y) / (a.y * a.y) + h.z * h.z;
  return 1.0 / (PI * a.x * a.y * e * e);
}

// Beckmann NDF, Walter et al. 2007 eq. 25 (anisotropic).
float ndfBeckmann(vec3 h, vec2 alpha) {
  if (h.z <= 0.0) return 0.0;
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  float cos2 = h.z * h.z;
  float e = ((h.x * h.x) / (a.x * a.x) + (h.y * h.y) / (a.y * a.y)) / cos2;
  return exp(-e) / (PI * a.x * a.y * cos2 * cos2);
}

float ndf(int kind, vec3 h, vec2 alpha) { return kind == 1 ? ndfBeckmann(h, alpha) : ndfGGX(h, alpha); }

// Smith Lambda (Heitz 2014, eqs. 72 and 80) times |w.z|, from s2 = alpha(w)^2 |w.xy|^2 (so that
// alpha(w)^2 tan^2 = s2 / w.z^2; for a lobe with slope covariance A, s2 = w.xy^T A w.xy) and
// z = |w.z|, in forms without division by z: finite and exact as z -> 0, where Lambda itself
// diverges. G1 and G2 / wo.z are built from it.
float smithLambdaCosOfS2(int kind, float s2, float z) {
  if (kind == 1) {
    // Beckmann, Walter's fit in b = z / s: z Lambda = s (1 - 1.259 b + 0.396 b^2) / (3.535 + 2.181 b).
    float s = sqrt(s2);
    if (z >= 1.6 * s) return 0.0;
    float b = z / s;
    return s * (1.0 - 1.259 * b + 0.396 * b * b) / (3.535 + 2.181 * b);
  }
  // GGX: z (sqrt(1 + s^2/z^2) - 1) / 2 = s^2 / (2 (z + sqrt(z^2 + s^2))).
  float d = z + sqrt(z * z + s2);
  return d > 0.0 ? 0.5 * s2 / d : 0.0;
}

// |w.z| Lambda(w) for direction w of the axis-aligned NDF.
float smithLambdaCos(int kind, vec3 w, vec2 alpha) {
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  return smithLambdaCosOfS2(kind, a.x * a.x * w.x * w.x + a.y * a.y * w.y * w.y, abs(w.z));
}

float smithG1(int kind, vec3 w, vec2 alpha) { return abs(w.z) / (abs(w.z) + smithLambdaCos(kind, w, alpha)); }

// Height-correlated masking-shadowing (Heitz 2014, eq. 99), G2 = 1 / (1 + Lambda(wo) + Lambda(wi)),
// divided by wo.z for wo.z, wi.z > 0 from lo = wo.z Lambda(wo) and li = wi.z Lambda(wi): finite
// as either cosine tends to 0 (G2 / wo.z -> 1 / lo ~ 2 / alpha, the true limit, not 1 / wo.z).
float smithG2OverCosOfLambdaCos(float woz, float wiz, float lo, float li) { return 1.0 / (woz + lo + li * woz / wiz); }

float smithG2OverCos(int kind, vec3 wo, vec3 wi, vec2 alpha) {
  return smithG2OverCosOfLambdaCos(wo.z, wi.z, smithLambdaCos(kind, wo, alpha), smithLambdaCos(kind, wi, alpha));
}

vec3 fresnelSchlick(vec3 f0, float cosTheta) {
  float m = clamp(1.0 - cosTheta, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// f_s(wo, wi) * cos(theta_i): the specular BRDF times the cosine, for local directions.
vec3 specularCos(int kind, vec3 wo, vec3 wi, vec2 alpha, vec3 f0) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  float d = ndf(kind, h, alpha);
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * d * smithG2OverCos(kind, wo, wi, alpha));
}

// Lambert diffuse times the cosine.
vec3 diffuseCos(vec3 albedo, vec3 wi) { return albedo * (INV_PI * max(wi.z, 0.0)); }
