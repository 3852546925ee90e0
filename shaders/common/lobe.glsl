// The specular lobe a method shades with: the material's NDF, possibly filtered over the pixel
// footprint. Two forms cover every filtering method of docs/methods.md:
// - a roughness matrix A, the slope-space second-moment matrix of a non-axis-aligned anisotropic
//   GGX or Beckmann NDF (A = diag(alpha_x^2, alpha_y^2) for the material itself; Kaplanyan et al.
//   2016's R; Tokuyoshi & Kaplanyan 2021, eq. 1);
// - optionally a slope-space box of half sides `footprint` that the NDF is averaged over
//   (Kaplanyan et al. 2016's rectangle filter; closed forms below).
// Directions are in the local shading frame (z = normal).
#include "common/brdf.glsl"
#include "common/material.glsl"
#include "common/surface.glsl"

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

// Square root of a symmetric positive definite 2x2 matrix: (A + sqrt(det A) I) / sqrt(tr A + 2 sqrt(det A)).
mat2 sqrtSpd(mat2 m) {
  float s = sqrt(max(determinant(m), 0.0));
  float t = sqrt(max(m[0][0] + m[1][1] + 2.0 * s, 1e-30));
  return (m + mat2(s)) / t;
}

// Width of the lobe in alpha units: sqrt of A's largest eigenvalue plus the box.
float lobeWidth(Lobe lobe) { return sqrt(maxEigenvalue(lobe.A)) + max(lobe.footprint.x, lobe.footprint.y); }

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

// erf, Abramowitz & Stegun 7.1.26 (absolute error < 1.5e-7).
float erfApprox(float x) {
  float t = 1.0 / (1.0 + 0.3275911 * abs(x));
  float y = 1.0 - t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429)))) *
                      exp(-x * x);
  return sign(x) * y;
}

// Average of a slope density over a slope-space box (Kaplanyan et al. 2016's rectangle filter),
// for axis-aligned A = diag(alpha^2). In units of alpha (u = x / alpha_x, v = y / alpha_y) the
// densities are p(u, v) = 1 / (pi (1 + u^2 + v^2)^2) (GGX) and exp(-u^2 - v^2) / pi (Beckmann).
// Along an axis where the box is at least NARROW_BOX wide the integral is taken in closed form.
// Closed forms are differences of nearly equal numbers when the box is narrow or far out in the
// tails, so there 4-point Gauss-Legendre quadrature (exact for degree 7, stable, exact in the
// zero-width limit) is used instead: for a narrow axis always, and for the whole box when the
// closed form's average falls below TAIL_DENSITY (float rounding would dominate it; it matters
// because D = P22 / cos^4 magnifies it at grazing half vectors).
const float NARROW_BOX = 0.5;
const float TAIL_DENSITY = 1e-4;
const vec4 GL4_NODES = vec4(-0.8611363116, -0.3399810436, 0.3399810436, 0.8611363116);
const vec4 GL4_WEIGHTS = vec4(0.3478548451, 0.6521451549, 0.6521451549, 0.3478548451) * 0.5;  // sum to 1

// GGX in alpha units: mass of p in the quadrant [0,u]x[0,v], odd in each argument, 1/4 at infinity.
float ggxQuadrantMass(float u, float v) {
  float su = sqrt(1.0 + u * u), sv = sqrt(1.0 + v * v);
  return (u / su * atan(v / su) + v / sv * atan(u / sv)) / TWO_PI;
}
// GGX in alpha units: integral of p(u, v) over v in [v0, v1] (d/dv of the bracket is 1/(c^2+v^2)^2).
float ggxStripMass(float u, float v0, float v1) {
  float c2 = 1.0 + u * u, c = sqrt(c2);
  float f1 = v1 / (2.0 * c2 * (c2 + v1 * v1)) + atan(v1 / c) / (2.0 * c2 * c);
  float f0 = v0 / (2.0 * c2 * (c2 + v0 * v0)) + atan(v0 / c) / (2.0 * c2 * c);
  return (f1 - f0) / PI;
}
float ggxDensity(float u, float v) {
  float e = 1.0 + u * u + v * v;
  return 1.0 / (PI * e * e);
}
float ggxQuadratureAverage(vec2 c, vec2 h) {
  float sum = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      sum += GL4_WEIGHTS[i] * GL4_WEIGHTS[j] * ggxDensity(c.x + h.x * GL4_NODES[i], c.y + h.y * GL4_NODES[j]);
  return sum;
}

// Average of p over the box centre c +- half h (alpha units).
float ggxBoxAverage(vec2 c, vec2 h) {
  bool narrowU = h.x < NARROW_BOX, narrowV = h.y < NARROW_BOX;
  if (narrowU && narrowV) return ggxQuadratureAverage(c, h);
  float average;
  if (!narrowU && !narrowV) {
    vec2 lo = c - h, hi = c + h;
    average = (ggxQuadrantMass(hi.x, hi.y) - ggxQuadrantMass(lo.x, hi.y) - ggxQuadrantMass(hi.x, lo.y) +
               ggxQuadrantMass(lo.x, lo.y)) / (4.0 * h.x * h.y);
  } else {
    // Quadrature along the narrow axis, closed form along the wide one (p is symmetric in u, v).
    vec2 cn = narrowU ? c : c.yx, hn = narrowU ? h : h.yx;
    average = 0.0;
    for (int i = 0; i < 4; ++i)
      average += GL4_WEIGHTS[i] * ggxStripMass(cn.x + hn.x * GL4_NODES[i], cn.y - hn.y, cn.y + hn.y);
    average /= 2.0 * hn.y;
  }
  return average < TAIL_DENSITY ? ggxQuadratureAverage(c, h) : average;
}

// Beckmann is separable: the average of exp(-u^2) along one axis.
float gaussianAxisAverage(float c, float h) {
  float closed = 0.886226925 * (erfApprox(c + h) - erfApprox(c - h)) / (2.0 * max(h, 1e-30));  // sqrt(pi)/2
  if (h >= NARROW_BOX && closed >= TAIL_DENSITY) return closed;
  vec4 u = c + h * GL4_NODES;
  return dot(GL4_WEIGHTS, exp(-u * u));
}

float boxAveragedSlopeDensity(int ndf, vec2 centre, vec2 halfSize, vec2 alpha) {
  vec2 c = centre / alpha, h = halfSize / alpha;
  float average = ndf == NDF_BECKMANN ? gaussianAxisAverage(c.x, h.x) * gaussianAxisAverage(c.y, h.y) / PI
                                      : ggxBoxAverage(c, h);
  return max(average, 0.0) / (alpha.x * alpha.y);
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
float lobeLambda(Lobe lobe, vec3 w) {
  return smithLambdaOfT2(lobe.ndf, dot(w.xy, lobe.A * w.xy) / max(w.z * w.z, 1e-12));
}

// f_s(wo, wi) cos(theta_i) with the lobe's NDF: D G2 F / (4 cos(theta_o)).
vec3 lobeSpecularCos(Lobe lobe, vec3 wo, vec3 wi, vec3 f0) {
  if (wo.z <= 0.0 || wi.z <= 0.0) return vec3(0.0);
  vec3 h = normalize(wo + wi);
  float g = 1.0 / (1.0 + lobeLambda(lobe, wo) + lobeLambda(lobe, wi));
  return fresnelSchlick(f0, dot(wo, h)) * (lobeNdf(lobe, h) * g / (4.0 * wo.z));
}

// The lobe widened by w alpha units in every direction, sqrt(A') = sqrt(A) + w I (the matrix
// form of alpha' = alpha + w), and the factor that keeps its peak energy: sqrt(det A / det A'),
// or for a box-averaged (axis-aligned) lobe the same with each axis' effective width
// sqrt(alpha^2 + footprint^2).
Lobe widenLobe(Lobe lobe, float w, out float normalisation) {
  mat2 root = sqrtSpd(lobe.A);
  mat2 widened = root + mat2(w);
  vec2 box2 = lobe.footprint * lobe.footprint;
  vec2 before = vec2(lobe.A[0][0], lobe.A[1][1]) + box2;
  vec2 after = vec2(widened[0][0] * widened[0][0], widened[1][1] * widened[1][1]) + box2;
  normalisation = lobe.footprint == vec2(0.0) ? determinant(root) / max(determinant(widened), 1e-36)
                                              : sqrt((before.x * before.y) / (after.x * after.y));
  return Lobe(lobe.ndf, widened * widened, lobe.footprint);
}
