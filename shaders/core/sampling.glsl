// Random numbers and BRDF sampling for the reference renderer, with the densities of the
// reflected directions they produce (for multiple importance sampling).
#include "core/brdf.glsl"
#include "core/constants.glsl"

// PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering").
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
uint hash3(uvec3 v) { return pcgHash(v.x ^ pcgHash(v.y ^ pcgHash(v.z))); }
float uintToUnit(uint v) { return float(v >> 8u) * (1.0 / 16777216.0); }
vec2 hashToUnit2(uint h) { return vec2(uintToUnit(h), uintToUnit(pcgHash(h))); }

// R2 low-discrepancy sequence (Roberts 2018), index i, with a Cranley-Patterson rotation:
// consecutive indices stay well stratified over [0,1)^2.
vec2 r2Point(uint i, vec2 rotation) {
  const vec2 g = vec2(0.75487766624669276, 0.56984029099805327);
  return fract(rotation + g * float(i) + vec2(0.5));
}

// GGX visible-normal sampling (Heitz 2018, "Sampling the GGX Distribution of Visible Normals").
vec3 sampleGGXVisibleNormal(vec3 wo, vec2 alpha, vec2 u) {
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  vec3 vh = normalize(vec3(a.x * wo.x, a.y * wo.y, wo.z));
  float lensq = vh.x * vh.x + vh.y * vh.y;
  vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
  vec3 t2 = cross(vh, t1);
  float r = sqrt(u.x);
  float phi = TWO_PI * u.y;
  float p1 = r * cos(phi);
  float p2 = r * sin(phi);
  float s = 0.5 * (1.0 + vh.z);
  p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
  vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
  return normalize(vec3(a.x * nh.x, a.y * nh.y, max(1e-6, nh.z)));
}

// Beckmann normal sampling proportional to D(h) cos(theta_h): slopes are Gaussian with
// standard deviation alpha / sqrt(2) per axis (Walter et al. 2007, eq. 28, anisotropic form).
vec3 sampleBeckmannNormal(vec2 alpha, vec2 u) {
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  float r = sqrt(-log(max(1.0 - u.x, 1e-12)));
  float phi = TWO_PI * u.y;
  vec2 slope = a * r * vec2(cos(phi), sin(phi));
  return normalize(vec3(-slope, 1.0));
}

// GGX normal sampling proportional to D(h) cos(theta_h): GGX's stretch takes it to alpha = 1,
// whose D cos is cos / pi, drawn by Malley's method (a uniform disk point lifted to the hemisphere).
vec3 sampleGGXNormal(vec2 alpha, vec2 u) {
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  float r = sqrt(u.x);
  float phi = TWO_PI * u.y;
  vec2 d = r * vec2(cos(phi), sin(phi));
  return normalize(vec3(a * d, sqrt(max(0.0, 1.0 - u.x))));
}

// Solid-angle density of wi = reflect(-wo, h) for h from sampleGGXVisibleNormal: the visible-normal
// density G1(wo) max(0, wo.h) D(h) / wo.z (Heitz 2018, eq. 3) times the reflection Jacobian
// 1 / (4 wo.h) (Walter et al. 2007, eq. 14), i.e. D(h) G1(wo) / (4 wo.z), with G1 / wo.z in its
// stable form: specularCos / this pdf = F G2 / G1 <= 1 at every angle, grazing included.
float ggxVisibleReflectionPdf(vec3 wo, vec3 wi, vec2 alpha) {
  vec3 m = wo + wi;
  if (wo.z <= 0.0 || dot(m, m) <= 0.0) return 0.0;
  vec3 h = normalize(m);
  if (dot(wo, h) <= 0.0) return 0.0;
  return ndfGGX(h, alpha) / (4.0 * (wo.z + smithLambdaCos(0, wo, alpha)));
}

// The half vector h of wo and wi, and the Jacobian 1 / (4 wo.h) that turns a density of normals
// into one of the directions wi = reflect(-wo, h) they reflect to (Walter et al. 2007, eq. 14);
// 0 where there is none: normals facing away from wo (wo.h <= 0) reflect below the horizon.
float reflectionJacobian(vec3 wo, vec3 wi, out vec3 h) {
  vec3 m = wo + wi;
  h = vec3(0.0, 0.0, 1.0);
  if (dot(m, m) <= 0.0) return 0.0;
  h = normalize(m);
  float oh = dot(wo, h);
  return oh > 0.0 ? 1.0 / (4.0 * oh) : 0.0;
}

// Solid-angle density of wi = reflect(-wo, h) for h from sampleBeckmannNormal: D(h) h.z / (4 wo.h).
float beckmannReflectionPdf(vec3 wo, vec3 wi, vec2 alpha) {
  vec3 h;
  float jacobian = reflectionJacobian(wo, wi, h);
  return jacobian > 0.0 ? ndfBeckmann(h, alpha) * h.z * jacobian : 0.0;
}

// Power-heuristic weight of a strategy of density `pdf` against one of density `other` (Veach
// 1997), as 1 / (1 + r^2) with r = other / pdf, finite for any pair with pdf > 0.
float powerHeuristic(float pdf, float other) {
  float r = other / pdf;
  return 1.0 / (1.0 + r * r);
}
