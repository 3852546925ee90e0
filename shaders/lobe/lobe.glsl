// The specular lobe a method shades with: the material's NDF, possibly filtered over the pixel
// footprint. Two forms cover every filtering method of docs/methods.md:
// - a roughness matrix A, the slope-space second-moment matrix of a non-axis-aligned anisotropic
//   GGX or Beckmann NDF (A = diag(alpha_x^2, alpha_y^2) for the material itself; Kaplanyan et al.
//   2016's R; Tokuyoshi & Kaplanyan 2021, eq. 1);
// - optionally a slope-space box of half sides `footprint` that the NDF is averaged over
//   (Kaplanyan et al. 2016's rectangle filter; closed forms in lobe/box_average.glsl).
// Directions are in the local shading frame (z = normal).
#include "core/brdf.glsl"
#include "core/material.glsl"
#include "core/surface.glsl"
#include "lobe/box_average.glsl"

struct Lobe {
  int ndf;         // NDF_GGX or NDF_BECKMANN
  mat2 A;          // roughness matrix (symmetric positive definite)
  vec2 footprint;  // half sides of the slope-space averaging box; (0, 0): point evaluation
};

// The unfiltered, axis-aligned lobe of roughness alpha (clamped to MIN_ALPHA like the NDFs).
Lobe axisAlignedLobe(int ndf, vec2 alpha) {
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  return Lobe(ndf, mat2(a.x * a.x, 0.0, 0.0, a.y * a.y), vec2(0.0));
}

// The material's lobe: A = 2 Sigma for the slope covariance Sigma of deviations alpha / sqrt(2)
// and correlation rho (Chermain et al. 2021, eq. 16).
Lobe materialLobe(Surface s) {
  Lobe lobe = axisAlignedLobe(s.ndf, s.alpha);
  lobe.A[0][1] = lobe.A[1][0] = s.rho * sqrt(lobe.A[0][0] * lobe.A[1][1]);
  return lobe;
}

// Largest eigenvalue of a symmetric 2x2 matrix.
float maxEigenvalue(mat2 m) {
  float half_tr = 0.5 * (m[0][0] + m[1][1]);
  float d = 0.5 * (m[0][0] - m[1][1]);
  return half_tr + sqrt(d * d + m[0][1] * m[0][1]);
}

// Quadratic form s^T A^-1 s and sqrt(det A), with A's determinant kept positive.
float inverseQuadratic(mat2 A, vec2 s, out float sqrtDet) {
  float det = max(determinant(A), 1e-36);
  sqrtDet = sqrt(det);
  vec2 t = vec2(A[1][1] * s.x - A[0][1] * s.y, A[0][0] * s.y - A[0][1] * s.x);  // adj(A) s
  return dot(s, t) / det;
}

// Slope distributions P22 (density of microfacet slopes) of the two NDFs with matrix A.
float slopeDensityGGX(vec2 slope, mat2 A) {
  float sqrtDet;
  float e = 1.0 + inverseQuadratic(A, slope, sqrtDet);
  return 1.0 / (PI * sqrtDet * e * e);
}
float slopeDensityBeckmann(vec2 slope, mat2 A) {
  float sqrtDet;
  float e = inverseQuadratic(A, slope, sqrtDet);
  return exp(-e) / (PI * sqrtDet);
}

// D(h) of the lobe: the slope density at the slope of h, divided by cos^4 (the Jacobian from
// slopes to normals, Walter et al. 2007).
float lobeNdf(Lobe lobe, vec3 h) {
  if (h.z <= 0.0) return 0.0;
  vec2 slope = -h.xy / h.z;
  float cos2 = h.z * h.z;
  float p22;
  if (lobe.footprint != vec2(0.0)) {
    p22 = boxAveragedSlopeDensity(lobe.ndf, slope, lobe.footprint, sqrt(vec2(lobe.A[0][0], lobe.A[1][1])));
  } else {
    p22 = lobe.ndf == NDF_BECKMANN ? slopeDensityBeckmann(slope, lobe.A) : slopeDensityGGX(slope, lobe.A);
  }
  return p22 / (cos2 * cos2);
}

// Smith Lambda of the lobe for direction w: the 1D roughness along w's azimuth is
// alpha_w^2 = w_xy^T A w_xy / |w_xy|^2 (Heitz 2014, sec. 5.4, for a linearly transformed lobe).
// lobeLambdaCos is |w.z| Lambda(w), finite as w.z -> 0 (core/brdf.glsl's smithLambdaCosOfS2).
float lobeLambdaCos(Lobe lobe, vec3 w) { return smithLambdaCosOfS2(lobe.ndf, dot(w.xy, lobe.A * w.xy), abs(w.z)); }
float lobeLambda(Lobe lobe, vec3 w) { return lobeLambdaCos(lobe, w) / max(abs(w.z), 1e-6); }

// G2(wo, wi) / wo.z of the lobe, bounded at grazing views (no 1 / wo.z blow-up).
float lobeG2OverCos(Lobe lobe, vec3 wo, vec3 wi) {
  return smithG2OverCosOfLambdaCos(wo.z, wi.z, lobeLambdaCos(lobe, wo), lobeLambdaCos(lobe, wi));
}

// f_s(wo, wi) cos(theta_i) with the lobe's NDF: D G2 F / (4 cos(theta_o)).
vec3 lobeSpecularCos(Lobe lobe, vec3 wo, vec3 wi, vec3 f0) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  return fresnelSchlick(f0, dot(wo, h)) * (0.25 * lobeNdf(lobe, h) * lobeG2OverCos(lobe, wo, wi));
}
