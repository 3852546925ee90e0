// Yan et al. 2016's position-normal distribution (P-NDF) of a Gaussian pixel footprint over a normal
// map, by brute force over the map's elements (docs/methods.md#yan2016; the CPU twin is
// src/prefilter/position_normal.cpp). Positions u are in texels (texel (i, j)'s centre at
// (i + 0.5, j + 0.5)); the map wraps. The surface is n(u) = normalize(bilinear texel normals), and
// its NDF at u is N2(s; n(u).xy, sigma_r^2 I) over the projected normal s = h.xy.
//
// Elements: k x k per texel (k = 1 or 2, a compile-time constant at every call), centres
// u_e = (e + 0.5) / k, each a Gaussian of shape Sigma_h = sh2 I, sh2 = (1.5 / (k sqrt 12))^2, with
// the field linearised about it: p_e = n(u_e).xy, J_e = dp/du by central differences (delta 0.5/k).
// For a footprint N(c, Sigma_p), with T = Sigma_h + Sigma_p and d = c - u_e, element e has
//   w_e = N2(c; u_e, T) (its constant cancels in P and is dropped),
//   Sigma_u = (Sigma_h^-1 + Sigma_p^-1)^-1 = sh2 I - sh2^2 T^-1   (no Sigma_p^-1: finite at Sigma_p = 0),
//   m_e - u_e = Sigma_u Sigma_p^-1 d = sh2 T^-1 d,
//   mean_e = p_e + J_e (m_e - u_e), cov_e = J_e Sigma_u J_e^T + sigma_r^2 I,
// and P(s) = sum_e w_e N2(s; mean_e, cov_e) / sum_e w_e over the elements with d^T T^-1 d <= 9.
#include "core/constants.glsl"
#include "core/wrap.glsl"

struct PositionNormalFootprint {
  vec2 centre;        // c, in texels, wrapped into [0, size)
  mat2 totalInverse;  // (Sigma_h + Sigma_p)^-1
  mat2 sigmaU;        // Sigma_u
  float shapeVariance;
  float sigmaR2;      // sigma_r^2
  ivec2 first;        // the first element index (before wrapping) of the truncation box
  ivec2 count;        // elements per axis in the box
  ivec2 size;         // the map's texels
};

// The footprint N(centre, sigmaP) (texels; sigmaP: the pixel footprint's texel covariance,
// footprintTexelCovariance in core/footprint.glsl) prepared for the sums below. Truncation: the elements
// in the bounding box of the 3-sigma ellipse of T, whose half extents are kept within maxRadius
// texels by scaling Sigma_p down (a large footprint is then under-blurred: the baseline's cost is
// O(maxRadius^2 k^2) per evaluation).
PositionNormalFootprint positionNormalFootprint(vec2 centre, mat2 sigmaP, ivec2 size, const int k, float sigmaR,
                                                float maxRadius) {
  PositionNormalFootprint f;
  float sh2 = 0.1875 / float(k * k);  // (1.5 / (k sqrt 12))^2
  vec2 room = max(vec2(maxRadius * maxRadius / 9.0 - sh2), vec2(0.0));
  vec2 diagonal = max(vec2(sigmaP[0][0], sigmaP[1][1]), vec2(1e-30));
  sigmaP *= min(1.0, min(room.x / diagonal.x, room.y / diagonal.y));
  mat2 total = sigmaP + mat2(sh2);
  f.centre = mod(centre, vec2(size));
  f.totalInverse = inverse(total);
  f.sigmaU = mat2(sh2) - sh2 * sh2 * f.totalInverse;
  f.shapeVariance = sh2;
  f.sigmaR2 = max(sigmaR * sigmaR, 1e-8);  // a sigma_r of 0 would make point elements singular
  vec2 radius = min(3.0 * sqrt(vec2(total[0][0], total[1][1])), vec2(maxRadius));
  f.first = ivec2(ceil(float(k) * (f.centre - radius) - 0.5));
  ivec2 last = ivec2(floor(float(k) * (f.centre + radius) - 0.5));
  f.count = max(last - f.first + 1, ivec2(0));
  f.size = size;
  return f;
}

vec3 mapTexel(sampler2D map, ivec2 size, ivec2 i) { return texelFetch(map, floorMod(i, size), 0).xyz; }

// Element e's centre, normal p_e and Jacobian J_e (columns d/du.x, d/du.y), from the texels
// around it. k = 1: the element sits on texel centre e, its +-0.5 neighbours on the midpoints to
// the four adjacent texels. k = 2: all five points lie in the 2 x 2 texels whose cell holds the
// element, at fractions {0, 0.25, 0.5, 0.75, 1}.
void positionNormalElement(sampler2D map, ivec2 size, ivec2 e, const int k, out vec2 u, out vec2 p, out mat2 J) {
  u = (vec2(e) + 0.5) / float(k);
  if (k == 1) {
    vec3 t = mapTexel(map, size, e);
    vec2 px = normalize(t + mapTexel(map, size, e + ivec2(1, 0))).xy;
    vec2 mx = normalize(t + mapTexel(map, size, e - ivec2(1, 0))).xy;
    vec2 py = normalize(t + mapTexel(map, size, e + ivec2(0, 1))).xy;
    vec2 my = normalize(t + mapTexel(map, size, e - ivec2(0, 1))).xy;
    p = normalize(t).xy;
    J = mat2(px - mx, py - my);  // / (2 delta), delta = 0.5
  } else {
    // Grid coordinate g = u - 0.5 = e / 2 - 0.25: cell a = floor(g), fraction 0.75 (e even) or 0.25.
    ivec2 a = ivec2(floor(u - 0.5));
    vec2 f = u - 0.5 - vec2(a);
    vec3 t00 = mapTexel(map, size, a), t10 = mapTexel(map, size, a + ivec2(1, 0));
    vec3 t01 = mapTexel(map, size, a + ivec2(0, 1)), t11 = mapTexel(map, size, a + ivec2(1, 1));
#define BILINEAR_XY(q) normalize(mix(mix(t00, t10, (q).x), mix(t01, t11, (q).x), (q).y)).xy
    p = BILINEAR_XY(f);
    J = mat2(BILINEAR_XY(f + vec2(0.25, 0.0)) - BILINEAR_XY(f - vec2(0.25, 0.0)),
             BILINEAR_XY(f + vec2(0.0, 0.25)) - BILINEAR_XY(f - vec2(0.0, 0.25))) * 2.0;  // / (2 delta), delta = 0.25
#undef BILINEAR_XY
  }
}

// erfc(x) for x >= 0, relative error < 3e-5: Abramowitz & Stegun 7.1.26 below 2 (absolute error
// 1.5e-7), above it the continued fraction erfc(x) = exp(-x^2) / (sqrt(pi) (x + (1/2) / (x + 1 / (x +
// (3/2) / ...)))) at 12 levels (relative error < 3e-7 there, where 7.1.26's grows to 1%).
vec4 erfcPositive(vec4 x) {
  vec4 t = 1.0 / (1.0 + 0.3275911 * x);
  vec4 near = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  vec4 far = max(x, vec4(2.0));
  vec4 f = far;
  for (int n = 12; n >= 1; --n) f = far + 0.5 * float(n) / f;
  return mix(near, 0.5641895835 / f, greaterThanEqual(x, vec4(2.0))) * exp(-x * x);
}

// The means over [a, b] of four 1D normal densities of means m and standard deviation sigma.
// Intervals under half a sigma (including zero width: the density itself) by 4-point
// Gauss-Legendre; wider ones from erfc of |z| at both ends (no cancellation on either side).
vec4 gaussianIntervalMean(float a, float b, vec4 m, float sigma) {
  vec4 za = (a - m) / sigma, zb = (b - m) / sigma;
  float width = (b - a) / sigma;
  const float INV_SQRT_2PI = 0.3989422804;
  if (width < 0.5) {
    const float NODES[4] = float[](-0.8611363116, -0.3399810436, 0.3399810436, 0.8611363116);
    const float WEIGHTS[4] = float[](0.1739274226, 0.3260725774, 0.3260725774, 0.1739274226);  // sum to 1
    vec4 sum = vec4(0.0);
    for (int j = 0; j < 4; ++j) {
      vec4 z = 0.5 * (za + zb) + (0.5 * NODES[j]) * (zb - za);
      sum += WEIGHTS[j] * exp(-0.5 * z * z);
    }
    return sum * (INV_SQRT_2PI / sigma);
  }
  const float INV_SQRT2 = 0.7071067812;
  vec4 ea = erfcPositive(abs(za) * INV_SQRT2), eb = erfcPositive(abs(zb) * INV_SQRT2);
  // The standard normal's mass over [za, zb]: on one side of 0, or across it.
  vec4 mass = mix(mix(1.0 - 0.5 * (ea + eb), 0.5 * (eb - ea), lessThanEqual(zb, vec4(0.0))), 0.5 * (ea - eb),
                  greaterThanEqual(za, vec4(0.0)));
  return mass / (width * sigma);
}

// The mean over the box [lo, hi] of N2(mean, cov): along y exactly given x (the conditional is a 1D
// Gaussian of mean mean.y + (cov01 / cov00)(x - mean.x)), along x by 10-point Gauss-Legendre over the
// box clipped to mean.x +- 5 sigma_x (the CPU twin's box_integral, src/prefilter/position_normal.cpp),
// evaluated as three vec4 batches of nodes (the last two lanes of weight 0).
// A box of zero width or height gives the density's mean over the other side (or the density).
float gaussianBoxMean(vec2 mean, mat2 cov, vec2 lo, vec2 hi) {
  const vec4 NODES[3] = vec4[](vec4(-0.9739065285, -0.8650633667, -0.6794095683, -0.4333953941),
                               vec4(-0.1488743390, 0.1488743390, 0.4333953941, 0.6794095683),
                               vec4(0.8650633667, 0.9739065285, 0.0, 0.0));
  const vec4 WEIGHTS[3] = vec4[](vec4(0.0666713443, 0.1494513492, 0.2190863625, 0.2692667193),
                                 vec4(0.2955242247, 0.2955242247, 0.2692667193, 0.2190863625),
                                 vec4(0.1494513492, 0.0666713443, 0.0, 0.0));
  float sx = sqrt(cov[0][0]);
  float a = max(lo.x, mean.x - 5.0 * sx), b = min(hi.x, mean.x + 5.0 * sx);
  if (!(a <= b)) return 0.0;
  float slope = cov[0][1] / cov[0][0];
  float sc = sqrt(max(cov[1][1] - slope * cov[0][1], 1e-6 * cov[1][1]));
  float mid = 0.5 * (a + b), halfSpan = 0.5 * (b - a);
  float sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    vec4 x = mid + NODES[i] * halfSpan;
    vec4 zx = (x - mean.x) / sx;
    sum += dot(WEIGHTS[i] * exp(-0.5 * zx * zx), gaussianIntervalMean(lo.y, hi.y, mean.y + slope * (x - mean.x), sc));
  }
  float width = hi.x - lo.x;
  float share = width > 0.0 ? halfSpan / width : 0.5;  // (b - a) / 2 over the box's width
  return sum * share * 0.3989422804 / sx;
}

// A truncation radius (texels) within llvmpipe's 65535 loop iterations per invocation: at most
// maxRadius, and the element loops of all the scene's lights together under 60000, (2 r k + 1)^2
// elements per light. Applied on every driver, so that images agree. Needs the forward pass's
// LIGHT_RANGES (a method module's context; absent in the tests' compute harness).
#ifdef LIGHT_RANGES
float positionNormalRadiusBudget(float maxRadius, const int k) {
  const ivec2 ranges[LIGHT_KIND_COUNT] = LIGHT_RANGES;
  int lights = 0;
  for (int i = 0; i < LIGHT_KIND_COUNT; ++i) lights += ranges[i].y - ranges[i].x;
  float perLight = 60000.0 / float(max(lights, 1));
  return min(maxRadius, (floor(sqrt(perLight)) - 1.0) / (2.0 * float(k)));
}
#endif

// sum_e w_e X_e / sum_e w_e over the footprint's elements, where X_e is the element's density
// N2(s; mean_e, cov_e) at s = lo (`box` false), or its mean over the box [lo, hi] (`box` true).
// One loop over a flat index with a per-pixel trip count (never unrolled; llvmpipe counts every
// iteration towards its 65535 cap, which the caller's maxRadius respects).
float positionNormalSum(sampler2D map, PositionNormalFootprint f, const int k, vec2 lo, vec2 hi, const bool box) {
  float sum = 0.0, weights = 0.0;
  int n = f.count.x * f.count.y;
  for (int i = 0; i < n; ++i) {
    ivec2 e = f.first + ivec2(i % f.count.x, i / f.count.x);
    vec2 u, p;
    mat2 J;
    positionNormalElement(map, f.size, e, k, u, p, J);
    vec2 d = f.centre - u;
    vec2 q = f.totalInverse * d;
    float distance2 = dot(d, q);
    if (distance2 > 9.0) continue;  // beyond 3 sigma of the footprint convolved with the element
    float w = exp(-0.5 * distance2);
    vec2 mean = p + J * (f.shapeVariance * q);
    mat2 cov = J * f.sigmaU * transpose(J) + mat2(f.sigmaR2);
    float x;
    if (box) {
      x = gaussianBoxMean(mean, cov, lo, hi);
    } else {
      float det = cov[0][0] * cov[1][1] - cov[0][1] * cov[1][0];
      vec2 r = lo - mean;
      float quadratic = (cov[1][1] * r.x * r.x - 2.0 * cov[0][1] * r.x * r.y + cov[0][0] * r.y * r.y) / det;
      x = exp(-0.5 * quadratic) / (TWO_PI * sqrt(det));
    }
    sum += w * x;
    weights += w;
  }
  return weights > 0.0 ? sum / weights : 0.0;
}

// P(s) of the footprint: a density over the plane of projected normals (integrates to 1).
float positionNormalDensity(sampler2D map, PositionNormalFootprint f, const int k, vec2 s) {
  return positionNormalSum(map, f, k, s, s, false);
}

// The mean of P over the box [lo, hi].
float positionNormalBoxMean(sampler2D map, PositionNormalFootprint f, const int k, vec2 lo, vec2 hi) {
  return positionNormalSum(map, f, k, lo, hi, true);
}
