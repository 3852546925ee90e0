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
//
// A footprint whose 3-sigma box holds more elements than the caller's budget (llvmpipe stops a
// shader's loops after 65535 iterations in all) is never shrunk: the sum runs over a stratified
// subset, the element grid cut into s x s cells (s the smallest stride that fits the budget) and
// one element per cell chosen by a hash of the cell, fixed on the surface (no flicker as the
// footprint moves). Over the hash, every element is in the subset with probability 1 / s^2, so
// both sums are unbiased and their ratio consistent; the error is sampling noise of the map's
// normals, not a lost part of the footprint (issue 30, item 2).
//
// Where the including method defines POSITION_NORMAL_STORED_ELEMENTS, p_e and J_e are read from
// the material's elements, computed once from the map (resource `position-normal-elements`,
// src/prefilter/position_normal_elements.hpp): one vec2 and one vec4 load per element instead of
// five texel reads and five normalisations per element, light and pixel. The caller sets the
// footprint's firstElement (positionNormalFirstElement[material]).
#include "generated/gpu_contract.glsl"
#include "core/constants.glsl"
#include "core/sampling.glsl"
#include "core/wrap.glsl"

#ifdef POSITION_NORMAL_STORED_ELEMENTS
layout(std430, binding = POSITION_NORMAL_ELEMENT_NORMALS_BINDING) readonly buffer PositionNormalElementNormals {
  uint positionNormalFirstElement[MAX_MATERIALS + MAX_MATERIALS % 2];  // even: the vec2s after them align
  vec2 positionNormalElementNormals[];
};
layout(std430, binding = POSITION_NORMAL_ELEMENT_JACOBIANS_BINDING) readonly buffer PositionNormalElementJacobians {
  vec4 positionNormalElementJacobians[];  // J_e's columns dp/du.x, dp/du.y
};
#endif

struct PositionNormalFootprint {
  vec2 centre;        // c, in texels, wrapped into [0, size)
  mat2 totalInverse;  // (Sigma_h + Sigma_p)^-1
  mat2 sigmaU;        // Sigma_u
  float shapeVariance;
  float sigmaR2;      // sigma_r^2
  float boxElements;  // the elements in the 3-sigma box of T (a float: it may pass 2^31)
  int stride;         // s: one element per s x s cell of the element grid (1: every element)
  ivec2 firstCell;    // the first cell (element index / s, before wrapping) that meets the box
  ivec2 cells;        // cells per axis; cells.x cells.y <= the budget
  uint seed;          // the subset's hash seed (0 in the methods; tests vary it)
  ivec2 size;         // the map's texels
  uint firstElement;  // the material's first stored element (POSITION_NORMAL_STORED_ELEMENTS)
#if defined(MATERIAL_WANG_TILES) && MATERIAL_WANG_TILES
  NormalMapSurface surface;  // the Wang-tiled surface whose texels the elements are made of (core/normal_map.glsl)
#endif
};

// The cells of stride s that the elements [first, last] meet along each axis.
vec2 positionNormalCells(vec2 first, vec2 last, float s) { return floor(last / s) - floor(first / s) + 1.0; }

// The smallest stride s whose cells over the box [first, last] number at most `budget`: between
// sqrt(a b / budget) (fewer cells than that is impossible) and the root of
// (budget - 4) s^2 - 2 (a + b) s - a b (a side meets at most a / s + 2 cells), by bisection.
int positionNormalStride(vec2 first, vec2 last, float budget) {
  vec2 box = last - first + 1.0;
  if (box.x * box.y <= budget) return 1;
  float m = max(budget - 4.0, 1.0), sum = box.x + box.y;
  int lo = max(int(sqrt(box.x * box.y / budget)) - 1, 1);  // too small
  int hi = max(int(ceil((sum + sqrt(sum * sum + m * box.x * box.y)) / m)), 2);  // fits
  for (int i = 0; i < 32 && hi - lo > 1; ++i) {
    int mid = (lo + hi) / 2;
    vec2 n = positionNormalCells(first, last, float(mid));
    if (n.x * n.y <= budget) hi = mid; else lo = mid;
  }
  return hi;
}

// The footprint N(centre, sigmaP) (texels; sigmaP: the pixel footprint's texel covariance,
// footprintTexelCovariance in core/footprint.glsl) prepared for the sums below: the elements in
// the bounding box of the 3-sigma ellipse of T, every one while they number at most `budget`,
// a stratified subset of `budget` or fewer past it (the cost is O(min(box, budget)) per evaluation).
PositionNormalFootprint positionNormalFootprint(vec2 centre, mat2 sigmaP, ivec2 size, const int k, float sigmaR,
                                                float budget) {
  PositionNormalFootprint f;
  float sh2 = 0.1875 / float(k * k);  // (1.5 / (k sqrt 12))^2
  mat2 total = sigmaP + mat2(sh2);
  f.centre = mod(centre, vec2(size));
  f.totalInverse = inverse(total);
  f.sigmaU = mat2(sh2) - sh2 * sh2 * f.totalInverse;
  f.shapeVariance = sh2;
  f.sigmaR2 = max(sigmaR * sigmaR, 1e-8);  // a sigma_r of 0 would make point elements singular
  vec2 radius = 3.0 * sqrt(vec2(total[0][0], total[1][1]));
  vec2 first = ceil(float(k) * (f.centre - radius) - 0.5), last = floor(float(k) * (f.centre + radius) - 0.5);
  vec2 box = max(last - first + 1.0, vec2(0.0));
  f.boxElements = box.x * box.y;
  f.stride = f.boxElements > 0.0 ? positionNormalStride(first, last, max(budget, 1.0)) : 1;
  f.firstCell = ivec2(floor(first / float(f.stride)));
  f.cells = f.boxElements > 0.0 ? ivec2(positionNormalCells(first, last, float(f.stride))) : ivec2(0);
  f.seed = 0u;
  f.size = size;
#if defined(MATERIAL_WANG_TILES) && MATERIAL_WANG_TILES
  f.surface = normalMapSurface();
#endif
  f.firstElement = 0u;
  return f;
}

// Element index of cell `cell`: the cell's own at stride 1, else the one its hash picks.
ivec2 positionNormalCellElement(ivec2 cell, int stride, uint seed) {
  if (stride == 1) return cell;
  uint h = hash3(uvec3(uvec2(cell), uint(stride) ^ (seed * 0x9e3779b9u)));
  uint s = uint(stride);
  return cell * stride + ivec2(int(h % s), int((h / s) % s));
}

// Texel i of the footprint's map (wrapped; on a Wang-tiled map, the surface's texel).
vec3 mapTexel(sampler2D map, PositionNormalFootprint f, ivec2 i) {
#if defined(MATERIAL_WANG_TILES) && MATERIAL_WANG_TILES
  return normalMapTexel(f.surface, i);
#else
  return texelFetch(map, floorMod(i, f.size), 0).xyz;
#endif
}

// Element e's centre, normal p_e and Jacobian J_e (columns d/du.x, d/du.y), from the texels
// around it. k = 1: the element sits on texel centre e, its +-0.5 neighbours on the midpoints to
// the four adjacent texels. k = 2: all five points lie in the 2 x 2 texels whose cell holds the
// element, at fractions {0, 0.25, 0.5, 0.75, 1}.
void positionNormalElement(sampler2D map, PositionNormalFootprint footprint, ivec2 e, const int k, out vec2 u, out vec2 p, out mat2 J) {
  u = (vec2(e) + 0.5) / float(k);
  if (k == 1) {
    vec3 t = mapTexel(map, footprint, e);
    vec2 px = normalize(t + mapTexel(map, footprint, e + ivec2(1, 0))).xy;
    vec2 mx = normalize(t + mapTexel(map, footprint, e - ivec2(1, 0))).xy;
    vec2 py = normalize(t + mapTexel(map, footprint, e + ivec2(0, 1))).xy;
    vec2 my = normalize(t + mapTexel(map, footprint, e - ivec2(0, 1))).xy;
    p = normalize(t).xy;
    J = mat2(px - mx, py - my);  // / (2 delta), delta = 0.5
  } else {
    // Grid coordinate g = u - 0.5 = e / 2 - 0.25: cell a = floor(g), fraction 0.75 (e even) or 0.25.
    ivec2 a = ivec2(floor(u - 0.5));
    vec2 f = u - 0.5 - vec2(a);
    vec3 t00 = mapTexel(map, footprint, a), t10 = mapTexel(map, footprint, a + ivec2(1, 0));
    vec3 t01 = mapTexel(map, footprint, a + ivec2(0, 1)), t11 = mapTexel(map, footprint, a + ivec2(1, 1));
#define BILINEAR_XY(q) normalize(mix(mix(t00, t10, (q).x), mix(t01, t11, (q).x), (q).y)).xy
    p = BILINEAR_XY(f);
    J = mat2(BILINEAR_XY(f + vec2(0.25, 0.0)) - BILINEAR_XY(f - vec2(0.25, 0.0)),
             BILINEAR_XY(f + vec2(0.0, 0.25)) - BILINEAR_XY(f - vec2(0.0, 0.25))) * 2.0;  // / (2 delta), delta = 0.25
#undef BILINEAR_XY
  }
}

#ifdef POSITION_NORMAL_STORED_ELEMENTS
// Element e's centre, p_e and J_e as positionNormalElement computes them, from the stored elements
// (k x k per texel, row major, the grid wrapping as the map).
void positionNormalStoredElement(PositionNormalFootprint f, ivec2 e, const int k, out vec2 u, out vec2 p, out mat2 J) {
  u = (vec2(e) + 0.5) / float(k);
  const ivec2 wrapped = floorMod(e, f.size * k);
  const uint i = f.firstElement + uint(wrapped.y * f.size.x * k + wrapped.x);
  p = positionNormalElementNormals[i];
  const vec4 j = positionNormalElementJacobians[i];
  J = mat2(j.xy, j.zw);
}
#endif

// erfc(x) for x >= 0 with one exp, no branch and no loop: exp(-x^2) t P(t), t = 1 / (1 + 0.44 x),
// P of degree 5 fitted for the least maximum relative error over [0, 12] (5.2e-6; float's
// exp(-x^2) is 0 past 9.3) by tools/fit-erfc.cpp.
vec4 erfcPositive(vec4 x) {
  vec4 t = 1.0 / (1.0 + 0.44 * x);
  vec4 p = 0.2485641985 + t * (0.242537039 + t * (0.263708899 + t * (0.04051555005 + t * (0.3508311959 - t * 0.1461620291))));
  return t * p * exp(-x * x);
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

// The elements one light's sum may visit: at most `budget` for all the scene's lights together,
// and within llvmpipe's 65535 loop iterations per invocation (60000 for the element loops, shared
// by the lights). Applied on every driver, so that images agree. Needs the forward pass's
// LIGHT_RANGES (a method module's context; absent in the tests' compute harness).
#ifdef LIGHT_RANGES
// `extraQueries`: sums beyond one per light (an environment's lobes past the first). With
// POSITION_NORMAL_BUDGET_PER_QUERY (the path tracer's footprint material) `budget` is each sum's
// and only llvmpipe's iterations are shared.
// The lights of the program's light layout (LIGHT_RANGES), of every kind.
int positionNormalLightCount() {
  const ivec2 ranges[LIGHT_KIND_COUNT] = LIGHT_RANGES;
  int lights = 0;
  for (int i = 0; i < LIGHT_KIND_COUNT; ++i) lights += ranges[i].y - ranges[i].x;
  return lights;
}
float positionNormalElementBudget(float budget, int extraQueries) {
  const float queries = float(max(positionNormalLightCount() + extraQueries, 1));
#ifdef POSITION_NORMAL_BUDGET_PER_QUERY
  return floor(min(budget, 60000.0 / queries));
#else
  return floor(min(budget, 60000.0) / queries);
#endif
}
float positionNormalElementBudget(float budget) { return positionNormalElementBudget(budget, 0); }
#endif

// sum_e w_e X_e / sum_e w_e over the footprint's elements, where X_e is the element's density
// N2(s; mean_e, cov_e) at s = lo (`box` false), or its mean over the box [lo, hi] (`box` true).
// One loop over a flat index of the cells with a per-pixel trip count (never unrolled; llvmpipe
// counts every iteration towards its 65535 cap, which the caller's budget respects).
float positionNormalSum(sampler2D map, PositionNormalFootprint f, const int k, vec2 lo, vec2 hi, const bool box) {
  float sum = 0.0, weights = 0.0;
  int n = f.cells.x * f.cells.y;
  for (int i = 0; i < n; ++i) {
    ivec2 e = positionNormalCellElement(f.firstCell + ivec2(i % f.cells.x, i / f.cells.x), f.stride, f.seed);
    vec2 u, p;
    mat2 J;
#ifdef POSITION_NORMAL_STORED_ELEMENTS
    positionNormalStoredElement(f, e, k, u, p, J);
#else
    positionNormalElement(map, f, e, k, u, p, J);
#endif
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
