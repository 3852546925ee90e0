// The glinty NDF of Kemppinen, Paulin, Thonat, Thiery, Lehtinen & Boubekeur 2025, "Evaluating and
// Sampling Glinty NDFs in Constant Time" (docs/methods.md#kemppinen2025), as glintlab derives it
// from the paper's description: facets are points of a 4D process, a position p in uv and an
// angular point a in the unit square, on an implicit multiscale grid; nothing is stored.
//
//   D(h) = D_base(h) rho(x(h)),  rho(x) = sum_i W(p_i) G_i(x - a_i) / N  (+ the expectation of the
//   facets not visited),
//
// x(h) an equal-area map of the stretched normal into the square, W the pixel's spatial Gaussian,
// G_i a facet's angular lobe, N facets per unit uv area per unit of the square. Facets are uniform
// in both, so E[rho] = 1 everywhere and E[D] = D_base, GGX or Beckmann, exactly, whatever the map:
// the map and the lobes only shape the glints. Level l of the grid stratifies the same density
// differently: spatial cells of side 2^l / sqrt(N), angular cells of side 2^-l, one facet per
// pair (4^l in each spatial cell); the footprint picks l so that its cells are
// POINT_PROCESS_CELL_SIGMAS footprint deviations wide, and only the 2 x 2 spatial by 2 x 2
// angular cells nearest the query are visited (constant cost: 2 levels x 16 facets). What the
// visited cells miss enters as its expectation, D_base (1 - M_s M_a), with M_s and M_a the
// footprint's and the lobe's Gaussian masses over the visited blocks: the mean stays D_base.
#include "core/brdf.glsl"
#include "core/erf.glsl"
#include "core/random.glsl"
#include "core/sampling.glsl"
#include "generated/gpu_contract.glsl"

// Spatial cells this many footprint standard deviations (major axis) wide: the 2 x 2 nearest
// cells cover at least +-4 of them on both axes, so the spatial mass outside (approximated below
// without the footprint's correlation) is below 1e-4.
const float POINT_PROCESS_CELL_SIGMAS = 8.0;
const int POINT_PROCESS_MAX_LEVEL = 20;  // 2^20 angular cells a side: past any lobe in fp32
// Facets of a level survive its share w of the blend stochastically, smoothly over +-this around
// their own threshold (they pop one by one instead of cross-fading; Kemppinen et al.'s choice).
const float POINT_PROCESS_SURVIVAL_SOFTNESS = 0.1;

// The angular coordinate x(h) in [0, 1]^2: h stretched by the roughness (GGX's stretch, under which
// the NDF becomes alpha = 1's), then Lambert's equal-area map of the hemisphere onto the disk of
// radius 1/2 about (1/2, 1/2).
vec2 pointProcessAngular(vec3 h, vec2 alpha) {
  vec3 s = normalize(vec3(h.xy / alpha, h.z));
  return 0.5 + 0.5 * s.xy * inversesqrt(1.0 + s.z);
}

// The inverse of pointProcessAngular; 0 outside the disk (no normal there; reflect(-wo, 0) is below
// the horizon, so a draw there fails).
vec3 pointProcessDirection(vec2 x, vec2 alpha) {
  vec2 q = 2.0 * x - 1.0;
  float r2 = dot(q, q);
  if (r2 >= 1.0) return vec3(0.0);
  vec3 s = vec3(q * sqrt(2.0 - r2), 1.0 - r2);  // Lambert: z = 1 - r^2, |s.xy| = r sqrt(2 - r^2)
  return normalize(vec3(s.xy * alpha, s.z));
}

// |dx / d omega_h|: the stretch's 1 / (ax ay |M h|^3) (M = diag(1/ax, 1/ay, 1)), the equal-area
// map's 1/2, the square's 1/4.
float pointProcessAngularJacobian(vec3 h, vec2 alpha) {
  float m = length(vec3(h.xy / alpha, h.z));
  return 1.0 / (8.0 * alpha.x * alpha.y * m * m * m);
}

// A facet's lobe in x: a Gaussian of variance pi D_base(h) sigma^2 at the query, so that every
// facet's peak D_base G is 1 / (2 pi^2 sigma^2) wherever its normal lies (the paper's choice).
// Floored where D_base underflows (Beckmann's far tail): the lobe is then a point.
const float POINT_PROCESS_MIN_VARIANCE = 1e-30;
float pointProcessLobeVariance(int kind, vec3 h, vec2 alpha, float sigma) {
  return max(PI * ndf(kind, h, alpha) * sigma * sigma, POINT_PROCESS_MIN_VARIANCE);
}

struct PointProcessFootprint {
  vec2 uv;
  mat2 inverseCovariance;  // of the spatial Gaussian W (uv^2)
  float spatialNorm;       // 1 / (2 pi sqrt(det)) of W
  vec2 marginalSigma;      // W's standard deviation along u and along v
  float sqrtDensity;       // sqrt(N)
  int level;               // the finer of the two levels blended
  float blend;             // the coarser level's share w in [0, 1)
  float sigma;             // the facets' angular lobe width
  int kind;                // NDF_GGX or NDF_BECKMANN
  vec2 alpha;
};

// The footprint of a pixel whose uv Gaussian has covariance `covariance`, on a surface of
// e^logDensity facets per unit uv area per unit of the square. The footprint is at least a
// POINT_PROCESS_CELL_SIGMAS-th of the facets' spacing (a point sample has one facet at most).
PointProcessFootprint pointProcessFootprint(vec2 uv, mat2 covariance, float logDensity, float sigma, int kind,
                                            vec2 alpha) {
  PointProcessFootprint f;
  f.uv = uv;
  f.sqrtDensity = exp(0.5 * logDensity);
  float floorSigma = 1.0 / (POINT_PROCESS_CELL_SIGMAS * f.sqrtDensity);
  mat2 c = covariance + mat2(floorSigma * floorSigma);  // mat2(s) is s I
  float det = determinant(c);
  f.inverseCovariance = inverse(c);
  f.spatialNorm = 1.0 / (TWO_PI * sqrt(det));
  f.marginalSigma = sqrt(vec2(c[0][0], c[1][1]));
  // Largest eigenvalue of c: the major axis' variance.
  float mean = 0.5 * (c[0][0] + c[1][1]);
  float major = sqrt(mean + sqrt(max(mean * mean - det, 0.0)));
  float lambda = clamp(log2(POINT_PROCESS_CELL_SIGMAS * major * f.sqrtDensity), 0.0, float(POINT_PROCESS_MAX_LEVEL));
  f.level = min(int(floor(lambda)), POINT_PROCESS_MAX_LEVEL - 1);
  f.blend = lambda - float(f.level);  // the coarser level l + 1 takes this share
  f.sigma = sigma;
  f.kind = kind;
  f.alpha = max(alpha, vec2(MIN_ALPHA));
  return f;
}

// A level's expected share of the facets: E[survival] for blend share w, with the threshold
// uniform on [-e, 1 + e] (so a share of 0 or 1 still blends smoothly): (w + e) / (1 + 2e). The two
// levels' shares sum to 1.
float pointProcessLevelShare(float w) {
  const float e = POINT_PROCESS_SURVIVAL_SOFTNESS;
  return (w + e) / (1.0 + 2.0 * e);
}
float pointProcessSurvival(float w, float threshold01) {
  const float e = POINT_PROCESS_SURVIVAL_SOFTNESS;
  float t = -e + (1.0 + 2.0 * e) * threshold01;
  return smoothstep(t - e, t + e, w);
}

// The Gaussian mass of N(mu, s^2) over [a, b].
float gaussianIntervalMass(float a, float b, float mu, float s) {
  float k = 0.70710678 / s;
  return 0.5 * (erfApprox((b - mu) * k) - erfApprox((a - mu) * k));
}

// One facet of level `level` in spatial cell `cell` and angular cell `angularCell`: its uv
// position, its angular point and its survival threshold.
struct PointProcessFacet {
  vec2 position;
  vec2 angular;
  float threshold;
};
PointProcessFacet pointProcessFacet(ivec2 cell, ivec2 angularCell, int level, float cellSize, float angularSize) {
  uvec4 r = pcg4d(uvec4(uvec2(cell), uvec2(angularCell) ^ uvec2(uint(level) * 0x9e3779b9u, 0x85ebca6bu)));
  uvec4 s = pcg4d(r ^ uvec4(0x632be5abu));
  PointProcessFacet f;
  f.position = (vec2(cell) + randomUnit2(r.xy)) * cellSize;
  f.angular = (vec2(angularCell) + randomUnit2(r.zw)) * angularSize;
  f.threshold = randomUnit2(s.xy).x;
  return f;
}

// The visited cells of one level around (uv, x): the lower corners of the 2 x 2 blocks nearest.
struct PointProcessLevel {
  int level;
  float share;        // its expected share of the facets
  float w;            // its blend share (each facet's survival threshold is compared with it)
  float cellSize;     // uv
  float angularSize;  // of an angular cell
  ivec2 cell;         // lower corner of the spatial block
  float spatialMass;  // M_s: W's mass over the block (without W's correlation)
};
PointProcessLevel pointProcessLevel(PointProcessFootprint f, int which) {
  PointProcessLevel L;
  L.level = f.level + which;
  L.w = which == 0 ? 1.0 - f.blend : f.blend;
  L.share = pointProcessLevelShare(L.w);
  L.cellSize = exp2(float(L.level)) / f.sqrtDensity;
  L.angularSize = exp2(-float(L.level));
  L.cell = ivec2(floor(f.uv / L.cellSize - 0.5));
  vec2 lo = vec2(L.cell) * L.cellSize, hi = lo + 2.0 * L.cellSize;
  L.spatialMass = gaussianIntervalMass(lo.x, hi.x, f.uv.x, f.marginalSigma.x) *
                  gaussianIntervalMass(lo.y, hi.y, f.uv.y, f.marginalSigma.y);
  return L;
}

// W(p): the footprint's normalised spatial Gaussian.
float pointProcessSpatialWeight(PointProcessFootprint f, vec2 p) {
  vec2 d = p - f.uv;
  return f.spatialNorm * exp(-0.5 * dot(d, f.inverseCovariance * d));
}

// D(h) of the footprint (see the top of the file).
float pointProcessNdf(PointProcessFootprint f, vec3 h) {
  if (h.z <= 0.0) return 0.0;
  float base = ndf(f.kind, h, f.alpha);
  vec2 x = pointProcessAngular(h, f.alpha);
  float variance = pointProcessLobeVariance(f.kind, h, f.alpha, f.sigma);
  float s = sqrt(variance);
  // A visited facet adds D_base W / N G = W / N exp(-d^2 / 2v) / (2 pi^2 sigma^2) (v = pi D_base
  // sigma^2), which stays finite where D_base underflows.
  float peak = 1.0 / (2.0 * PI * PI * f.sigma * f.sigma * f.sqrtDensity * f.sqrtDensity);
  float glints = 0.0, expected = 0.0;
  for (int which = 0; which < 2; ++which) {
    PointProcessLevel L = pointProcessLevel(f, which);
    ivec2 angularCell = ivec2(floor(x / L.angularSize - 0.5));
    vec2 lo = vec2(angularCell) * L.angularSize, hi = lo + 2.0 * L.angularSize;
    float angularMass = gaussianIntervalMass(lo.x, hi.x, x.x, s) * gaussianIntervalMass(lo.y, hi.y, x.y, s);
    for (int k = 0; k < 16; ++k) {
      ivec2 ds = ivec2(k & 1, (k >> 1) & 1), da = ivec2((k >> 2) & 1, k >> 3);
      PointProcessFacet facet = pointProcessFacet(L.cell + ds, angularCell + da, L.level, L.cellSize, L.angularSize);
      vec2 d = x - facet.angular;
      glints += pointProcessSurvival(L.w, facet.threshold) * pointProcessSpatialWeight(f, facet.position) *
                exp(-0.5 * dot(d, d) / variance);
    }
    expected += L.share * (1.0 - L.spatialMass * angularMass);
  }
  return peak * glints + base * expected;
}

// ---------------------------------------------------------------------------------------------
// Importance sampling in constant time, with the exact density of what it draws: a mixture of the
// base NDF (D_base cos) and the facets' lobes. A lobe is drawn as D's own facet terms are: the
// NDF at x visits the facets of the 2 x 2 angular cells nearest x, so a facet of cell j enters D
// only inside the window of two cells centred on j, [(j - 1/2) s, (j + 3/2) s)^2; the sampler
// draws its lobe truncated to that window. Then the facets whose lobes can have drawn x are
// exactly those D visits at x, and the density is a sum over them:
//   level l by its share; angular cell j by a Beta(2, 2) per axis (close to D_base cos's spread in
//   x, and its cells' probabilities are closed-form); among the 4 facets of cell j in the level's
//   spatial block, one by its share of the integral of D cos (or none: pointProcessCellFacets); x
//   from its Gaussian (variance at its own direction) truncated to j's window, by inversion.
// Facets whose angular point is outside the disk (no normal) are never drawn; a draw outside the
// disk fails (h.z <= 0), and the density is that of the directions drawn.

// The Beta(2, 2) distribution's CDF 3t^2 - 2t^3 (smoothstep) and its inverse.
float pointProcessCellCdf(float t) { return smoothstep(0.0, 1.0, t); }
float pointProcessCellQuantile(float u) { return 0.5 - sin(asin(1.0 - 2.0 * u) / 3.0); }

// The probability that the sampler picks angular cell j of side `size`.
float pointProcessCellProbability(ivec2 j, float size) {
  vec2 lo = vec2(j) * size, hi = lo + size;
  return (pointProcessCellCdf(hi.x) - pointProcessCellCdf(lo.x)) * (pointProcessCellCdf(hi.y) - pointProcessCellCdf(lo.y));
}

// The facets of angular cell j in the spatial block of level L: each one's weight, its angular
// point and its lobe's variance at its own direction (weight 0 outside the disk).
// (Four facets in vectors, not arrays: a dynamically indexed local array spills to local memory
// on a GPU; docs/methods.md, "Driver profiles".)
struct PointProcessCellFacets {
  vec4 weight;
  vec4 angularX, angularY;
  vec4 variance;
  float total;
  float scale;  // max(total, its expectation): a facet is drawn with probability weight / scale
};
PointProcessCellFacets pointProcessCellFacets(PointProcessFootprint f, PointProcessLevel L, ivec2 j) {
  PointProcessCellFacets c;
  for (int k = 0; k < 4; ++k) {
    PointProcessFacet facet = pointProcessFacet(L.cell + ivec2(k & 1, k >> 1), j, L.level, L.cellSize, L.angularSize);
    vec3 ha = pointProcessDirection(facet.angular, f.alpha);
    c.angularX[k] = facet.angular.x;
    c.angularY[k] = facet.angular.y;
    // The lobe's variance at h_a, at least (cell / 16)^2: a proposal wider than a lobe far narrower
    // than a cell costs little, and a narrower one would be a point the density cannot resolve.
    float minimum = L.angularSize / 16.0;
    c.variance[k] = ha.z > 0.0 ? max(pointProcessLobeVariance(f.kind, ha, f.alpha, f.sigma), minimum * minimum) : 1.0;
    // Its share of the integral of D cos: survival W / N times D_base(h_a) h_a.z / |dx/dw| (its lobe's
    // mass in x is 1); 0 where D_base underflows (a lobe of no width reflects nothing).
    c.weight[k] = ha.z > 0.0 ? pointProcessSurvival(L.w, facet.threshold) * pointProcessSpatialWeight(f, facet.position) *
                                   ndf(f.kind, ha, f.alpha) * ha.z / pointProcessAngularJacobian(ha, f.alpha)
                             : 0.0;
  }
  c.total = dot(c.weight, vec4(1.0));
  // The scale a cell's total is measured against: what a cell of facets at the normal is expected
  // to hold (the level's share, W's mass over the spatial block per uv area, and D_base cos /
  // |dx/dw| = 8 / pi at the normal, its largest for GGX and Beckmann alike). A cell below it (no
  // facet near the footprint's centre, or only facets that reflect little) draws in proportion
  // and otherwise fails, so the draws go where the glints are.
  float expected = L.share * L.spatialMass / (L.cellSize * L.cellSize) * (8.0 / PI);
  c.scale = max(c.total, expected);
  return c;
}

// The truncated Gaussian N(a, v) on [lo, hi): its mass there, per axis.
vec2 pointProcessWindowMass(vec2 a, float v, vec2 lo, vec2 hi) {
  float s = sqrt(v);
  return vec2(gaussianIntervalMass(lo.x, hi.x, a.x, s), gaussianIntervalMass(lo.y, hi.y, a.y, s));
}

// The base NDF's share of the mixture: what the facets' lobes leave at the normal (the
// compensation's share of D there), kept within [0.1, 0.9] so both draw.
float pointProcessBaseShare(PointProcessFootprint f) {
  float s = sqrt(pointProcessLobeVariance(f.kind, vec3(0.0, 0.0, 1.0), f.alpha, f.sigma));
  float visited = 0.0;
  for (int which = 0; which < 2; ++which) {
    PointProcessLevel L = pointProcessLevel(f, which);
    float m = gaussianIntervalMass(-L.angularSize, L.angularSize, 0.0, s);
    visited += L.share * m * m;
  }
  return clamp(1.0 - visited, 0.1, 0.9);
}

// A normal h drawn with u uniform in [0, 1)^2 (u picks the angular cell; the other choices take a
// hash of u); 0 when the draw fails.
vec3 pointProcessSampleNormal(PointProcessFootprint f, vec2 u) {
  uvec4 r = pcg4d(uvec4(floatBitsToUint(u), 0x2545f491u, 0x9e3779b9u));
  vec2 r01 = randomUnit2(r.xy), r23 = randomUnit2(r.zw);
  float base = pointProcessBaseShare(f);
  if (r01.x < base) return f.kind == NDF_BECKMANN ? sampleBeckmannNormal(f.alpha, u) : sampleGGXNormal(f.alpha, u);
  PointProcessLevel L = pointProcessLevel(f, r01.y < pointProcessLevelShare(1.0 - f.blend) ? 0 : 1);
  float cells = exp2(float(L.level));
  ivec2 j = ivec2(min(floor(vec2(pointProcessCellQuantile(u.x), pointProcessCellQuantile(u.y)) * cells), vec2(cells - 1.0)));
  PointProcessCellFacets c = pointProcessCellFacets(f, L, j);
  float pick = r23.x * c.scale;
  if (!(pick < c.total)) return vec3(0.0);
  // The facet whose share of the total holds `pick`: the first whose running sum passes it.
  vec4 upTo = vec4(c.weight.x, c.weight.x + c.weight.y, c.weight.x + c.weight.y + c.weight.z, c.total);
  vec4 chosen = vec4(lessThan(vec4(pick), upTo)) * vec4(1.0, vec3(lessThanEqual(upTo.xyz, vec3(pick))));
  vec2 a = vec2(dot(chosen, c.angularX), dot(chosen, c.angularY));
  float variance = dot(chosen, c.variance);
  if (dot(chosen, c.weight) <= 0.0) return vec3(0.0);
  // Inversion of the truncated Gaussian per axis: t uniform between the window's two CDF values.
  vec2 lo = (vec2(j) - 0.5) * L.angularSize, hi = lo + 2.0 * L.angularSize;
  float s = sqrt(variance);
  vec2 t = vec2(r23.y, randomUnit2(pcg4d(r).xy).x);
  vec2 cLo = vec2(erfApprox((lo.x - a.x) * 0.70710678 / s), erfApprox((lo.y - a.y) * 0.70710678 / s));
  vec2 cHi = vec2(erfApprox((hi.x - a.x) * 0.70710678 / s), erfApprox((hi.y - a.y) * 0.70710678 / s));
  vec2 e = mix(cLo, cHi, t);
  vec2 x = a + 1.41421356 * s * vec2(erfInverse(e.x), erfInverse(e.y));
  x = clamp(x, lo, hi - 1e-7 * L.angularSize);
  return pointProcessDirection(x, f.alpha);
}

// The solid-angle density of h under pointProcessSampleNormal.
float pointProcessNormalPdf(PointProcessFootprint f, vec3 h) {
  if (h.z <= 0.0) return 0.0;
  float base = pointProcessBaseShare(f);
  vec2 x = pointProcessAngular(h, f.alpha);
  float lobes = 0.0;
  for (int which = 0; which < 2; ++which) {
    PointProcessLevel L = pointProcessLevel(f, which);
    float cells = exp2(float(L.level));
    ivec2 first = ivec2(floor(x / L.angularSize - 0.5));
    for (int q = 0; q < 4; ++q) {
      ivec2 j = first + ivec2(q & 1, q >> 1);
      if (any(lessThan(j, ivec2(0))) || any(greaterThanEqual(vec2(j), vec2(cells)))) continue;
      PointProcessCellFacets c = pointProcessCellFacets(f, L, j);
      if (c.total <= 0.0) continue;
      vec2 lo = (vec2(j) - 0.5) * L.angularSize, hi = lo + 2.0 * L.angularSize;
      float density = 0.0;
      for (int k = 0; k < 4; ++k) {
        vec2 a = vec2(c.angularX[k], c.angularY[k]);
        vec2 mass = pointProcessWindowMass(a, c.variance[k], lo, hi);
        vec2 d = x - a;
        density += c.weight[k] * exp(-0.5 * dot(d, d) / c.variance[k]) / (TWO_PI * c.variance[k] * mass.x * mass.y);
      }
      lobes += L.share * pointProcessCellProbability(j, L.angularSize) * density / c.scale;
    }
  }
  return base * ndf(f.kind, h, f.alpha) * h.z + (1.0 - base) * lobes * pointProcessAngularJacobian(h, f.alpha);
}
