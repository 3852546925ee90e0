// The specular lobe a method shades with: the material's NDF, possibly filtered over the pixel
// footprint. Two forms cover every filtering method of docs/methods.md:
// - a roughness matrix A, the slope-space second-moment matrix of a non-axis-aligned anisotropic
//   GGX or Beckmann NDF (A = diag(alpha_x^2, alpha_y^2) for the material itself; Kaplanyan et al.
//   2016's R; Tokuyoshi & Kaplanyan 2021, eq. 1);
// - optionally a slope-space box of half sides `footprint` that the NDF is averaged over
//   (Kaplanyan et al. 2016's rectangle filter; closed forms below).
// Directions are in the local shading frame (z = normal).
#include "core/brdf.glsl"
#include "core/material.glsl"
#include "core/surface.glsl"

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
// Along an axis where the box is at least NARROW_BOX wide the integral is taken in closed form;
// along a narrower axis by 4-point Gauss-Legendre quadrature (exact for degree 7, exact in the
// zero-width limit). The closed forms are differences of O(1) numbers: their float rounding is
// about 1e-7 absolute, so they are used only where the box holds at least TAIL_MASS of the lobe
// (relative error ~1e-4). A box holding less lies in the tails, whatever its width, and is
// integrated by quadrature after substitutions that flatten the tails (ggxTailAverage).
const float NARROW_BOX = 0.5;
const float TAIL_MASS = 1e-3;
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
// (atan(c + h) - atan(c - h)) / (2 h) without cancellation, and its limit 1 / (1 + c^2) at h = 0.
float atanSlope(float c, float h) {
  float q = 1.0 + (c - h) * (c + h);
  return h > 0.0 ? atan(2.0 * h, q) / (2.0 * h) : 1.0 / q;
}

// GGX box average in the tails, by substitutions that make the integrand smooth and bounded:
// the inner axis u = c tan t with c^2 = 1 + v^2 (p du = cos^2 t / (pi c^3) dt), the outer axis
// v = C tan T with C^2 = 1 + u_near^2 (u_near: the box's u closest to the peak), so that the
// marginal of v becomes about cos T / C^2. The outer axis is the one nearer the peak (where the
// density is flattest). 4x4 Gauss-Legendre, accurate for boxes of any width far from the peak.
float ggxTailAverage(vec2 c, vec2 h) {
  vec2 near = max(abs(c) - h, vec2(0.0));
  bool outerV = near.y <= near.x;
  vec2 co = outerV ? c : c.yx, ho = outerV ? h : h.yx, no = outerV ? near : near.yx;  // x: inner, y: outer
  float C = sqrt(1.0 + no.x * no.x);
  float T0 = atan((co.y - ho.y) / C);
  float outerSlope = atanSlope(co.y / C, ho.y / C) / C;  // (T1 - T0) / (2 h_v)
  float sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    float T = T0 + outerSlope * ho.y * (1.0 + GL4_NODES[i]);
    float v = C * tan(T), cosT = cos(T);
    float cv = sqrt(1.0 + v * v);
    float t0 = atan((co.x - ho.x) / cv);
    float innerSlope = atanSlope(co.x / cv, ho.x / cv) / cv;  // (t1 - t0) / (2 h_u)
    float inner = 0.0;
    for (int j = 0; j < 4; ++j) {
      float ct = cos(t0 + innerSlope * ho.x * (1.0 + GL4_NODES[j]));
      inner += GL4_WEIGHTS[j] * ct * ct;
    }
    sum += GL4_WEIGHTS[i] * (C / (cosT * cosT)) * innerSlope * inner / (PI * cv * cv * cv);
  }
  return sum * outerSlope;
}
float ggxDensity(float u, float v) {
  float e = 1.0 + u * u + v * v;
  return 1.0 / (PI * e * e);
}

// Average of p over the box centre c +- half h (alpha units).
float ggxBoxAverage(vec2 c, vec2 h) {
  bool narrowU = h.x < NARROW_BOX, narrowV = h.y < NARROW_BOX;
  float average = 0.0;
  if (narrowU && narrowV) {
    // Smooth over a box less than an alpha wide: 4x4 Gauss-Legendre on the density.
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        average += GL4_WEIGHTS[i] * GL4_WEIGHTS[j] * ggxDensity(c.x + h.x * GL4_NODES[i], c.y + h.y * GL4_NODES[j]);
    return average;
  }
  if (!narrowU && !narrowV) {
    vec2 lo = c - h, hi = c + h;
    average = (ggxQuadrantMass(hi.x, hi.y) - ggxQuadrantMass(lo.x, hi.y) - ggxQuadrantMass(hi.x, lo.y) +
               ggxQuadrantMass(lo.x, lo.y)) / (4.0 * h.x * h.y);
  } else {
    // Quadrature along the narrow axis, closed form along the wide one (p is symmetric in u, v).
    vec2 cn = narrowU ? c : c.yx, hn = narrowU ? h : h.yx;
    for (int i = 0; i < 4; ++i)
      average += GL4_WEIGHTS[i] * ggxStripMass(cn.x + hn.x * GL4_NODES[i], cn.y - hn.y, cn.y + hn.y);
    average /= 2.0 * hn.y;
  }
  // The box's mass decides, not its average density: a wide box on the peak has a small average.
  return average * 4.0 * h.x * h.y < TAIL_MASS ? ggxTailAverage(c, h) : average;
}

// Beckmann is separable: the average of exp(-u^2) along one axis.
float gaussianAxisAverage(float c, float h) {
  float closed = 0.886226925 * (erfApprox(c + h) - erfApprox(c - h)) / (2.0 * max(h, 1e-30));  // sqrt(pi)/2
  if (h >= NARROW_BOX && 2.0 * h * closed >= TAIL_MASS) return closed;
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

// Mass of the unit GGX slope density p(u) = 1 / (pi (1 + |u|^2)^2) (alpha units) in the disk of
// radius r centred at distance d from the peak. The ring integral of p at radius q about the
// disk's centre is 2 q a / (a^2 - b^2)^(3/2), a = 1 + d^2 + q^2, b = 2 d q; with w = q^2 it
// integrates to M = 1/2 + N / (2 S), N = r^2 - 1 - d^2, S = sqrt((r^2 + 1 - d^2)^2 + 4 d^2)
// (d = 0: the GGX slope CDF r^2 / (1 + r^2)). Where N < 0 the sum cancels; there
// M = 2 r^2 / (S (S - N)), from S^2 - N^2 = 4 r^2. M is homogeneous of degree 0 in (1, d, r),
// so it is evaluated in units of m = max(1, d, r), where nothing overflows (a huge light seen by
// a mirror-like lobe has d and r near 1e15 in alpha units).
float ggxDiskMass(float d, float r) {
  float m = max(1.0, max(d, r));
  float dm = d / m, rm = r / m, e = 1.0 / m;
  float r2 = rm * rm, e2 = e * e, d2 = dm * dm;
  float n = r2 - e2 - d2;
  float k = r2 + e2 - d2;
  float s = max(sqrt(k * k + 4.0 * d2 * e2), 1e-30);
  return n >= 0.0 ? (s + n) / (2.0 * s) : 2.0 * r2 * e2 / (s * (s - n));
}

// The light's image in the lobe's slope space. A light whose outline, seen from p, is to first
// order the ellipse lc + dl1 x1 + dl2 x2 about the direction lc to its centre, is seen through
// the half vector h = (wo + l) / |wo + l| as the ellipse centre + J x, |x| <= 1: dh = (I - h h^T) dl / |wo + l| (in-plane changes of l are halved,
// the others scaled by 1 / (2 cos theta_d)), and the slope s = -h.xy / h.z changes by
// ds = -(dh.xy + s dh.z) / h.z (lightImage in lobe/lobe_shading.glsl).
struct LightImage {
  vec2 centre;  // slope of the half vector towards the light's centre
  mat2 J;       // columns: the image's semi-axes (conjugate) in slope space
};
// Fraction of the lobe's slope distribution inside the light's image: the light's radiance
// weighted by the lobe, integrated over the light (the lobe convolved with the light). It tends
// to the mirror's all-or-nothing as the lobe narrows and to P22 x (image area) as the light
// shrinks, and its integral over image positions is the image's area for every lobe (energy).
// Matrix lobes: in the lobe's whitened space (u = A^-1/2 s, where p is isotropic) the image is an
// ellipse c + K x, |x| <= 1, taken as a disk at distance d = |c| from the peak (GGX in closed form,
// ggxDiskMass; Beckmann as the square of equal area, separable erf). Its radius: where the image
// is small against the lobe, that of equal area (|det K|), so the small-light limit is exact;
// where it is large, the ellipse's radius towards the peak (1 / |K^-1 c/|c||), so the edge a
// narrow lobe crosses is the ellipse's own; geometric interpolation by the weight
// 1 / (1 + |det K|) between them, and towards equal area as d -> 0 (where the direction is lost).
// Box lobes (the box average of Kaplanyan et al.'s GGX filter, axis-aligned in alpha units):
// the image as the box of equal area and the aspect of its bounding box, convolved with the
// footprint box; the limits are the box average as the light shrinks and the image's box as the
// footprint vanishes.
float lobeMassOnImage(Lobe lobe, LightImage image) {
  float detJ = abs(determinant(image.J));
  if (lobe.footprint != vec2(0.0)) {
    vec2 alpha = sqrt(vec2(lobe.A[0][0], lobe.A[1][1]));
    mat2 K = mat2(image.J[0] / alpha, image.J[1] / alpha);  // alpha units
    float area = PI * detJ / (alpha.x * alpha.y);
    vec2 extent = sqrt(K[0] * K[0] + K[1] * K[1]) + 1e-20;  // bounding half sides
    vec2 imageHalf = extent * sqrt(0.25 * area / (extent.x * extent.y));
    // The box-averaged density averaged again over the image's box: per axis the larger of the
    // two boxes in closed form, the smaller by 2-point Gauss-Legendre (exact for cubics). The
    // convolution of the footprint box with anything normalised keeps its partition of unity
    // over neighbouring pixels, so the image's energy is kept however the boxes compare.
    vec2 b = lobe.footprint / alpha;
    vec2 large = max(b, imageHalf), small = min(b, imageHalf);
    float sum = 0.0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        vec2 offset = small * vec2(i == 0 ? -0.5773503 : 0.5773503, j == 0 ? -0.5773503 : 0.5773503);
        sum += 0.25 * boxAveragedSlopeDensity(lobe.ndf, image.centre + offset * alpha, large * alpha, alpha);
      }
    return min(area * sum * alpha.x * alpha.y, 1.0);
  }
  float sqrtDet;
  float d2 = inverseQuadratic(lobe.A, image.centre, sqrtDet);
  float areaR2 = detJ / sqrtDet;  // |det K|
  // Direction from the image's centre to the peak, in whitened space, and K^-1 along it:
  // K = A^-1/2 J, so K^-1 e = J^-1 A^1/2 e with A^1/2 e = -A^1/2 A^-1/2 c / |c| = -s / |A^-1/2 s|.
  vec2 toPeak = -image.centre * inversesqrt(max(d2, 1e-30));
  mat2 adjJ = mat2(image.J[1][1], -image.J[0][1], -image.J[1][0], image.J[0][0]);
  vec2 kInvE = adjJ * toPeak / max(detJ, 1e-30);
  float dirR2 = 1.0 / max(dot(kInvE, kInvE), 1e-30);
  float t = d2 / (1.0 + d2) * (1.0 - 1.0 / (1.0 + areaR2));
  float r = sqrt(areaR2 * exp2(t * (log2(dirR2) - log2(max(areaR2, 1e-30)))));
  if (lobe.ndf == NDF_BECKMANN) {
    float h = 0.886226925 * r;  // sqrt(pi)/2 r: the square of equal area, at (d, 0)
    float d = sqrt(d2);
    return 0.25 * (erfApprox(d + h) - erfApprox(d - h)) * 2.0 * erfApprox(h);
  }
  return ggxDiskMass(sqrt(d2), r);
}
