// The procedural glinty slope distribution of Chermain et al. 2020 with the slope correlation and
// the filtered lookups of Chermain et al. 2021 (docs/methods.md#chermain2020): a patch-SDF over
// the pixel's footprint, a weighted sum over the cells of a virtual MIP hierarchy of linearly
// transformed products of two dictionary marginals (2021, eqs. 3-6, 10, 15, 18).
#include "core/constants.glsl"
#include "core/erf.glsl"
#include "core/footprint.glsl"
#include "glints/chermain/dictionary.glsl"
#include "lobe/lobe.glsl"

// Cells inside the footprint evaluated per level at most: glintlab's guard (the authors' shaders
// stop after 101 cells of the bounding box; docs/methods.md, "Departures from the authors'
// shaders"). glint_cells.glsl counts how many a footprint holds.
const int GLINT_MAX_CELLS = 100;
// Standard deviation of the per-cell jitter of the dictionary level (2020, sec. 4.3: zeta = 2).
const float GLINT_LEVEL_JITTER = 2.0;

// The material's slope distribution in its smooth limit, a Beckmann lobe of roughness matrix
// A = 2 Sigma (lobe/lobe.glsl), and the map from its slopes to the dictionary's (2021, eq. 18):
// M = (1 / sigma_dict) [[sigma_x sqrt(1 - rho^2), rho sigma_x], [0, sigma_y]], so that
// M Sigma_dict M^T is Sigma = [[sx^2, rho sx sy], [rho sx sy, sy^2]] (eq. 16).
struct GlintLobe {
  mat2 A;
  mat2 invM;      // M^-1, before the per-cell rotation
  float detInvM;  // the Jacobian of the change of variables (eq. 4)
};

GlintLobe glintLobe(mat2 A) {
  vec2 sigma = sqrt(0.5 * vec2(A[0][0], A[1][1]));
  float rho = clamp(A[0][1] / sqrt(A[0][0] * A[1][1]), -0.99, 0.99);
  A[0][1] = A[1][0] = rho * sqrt(A[0][0] * A[1][1]);
  float k = sqrt(1.0 - rho * rho);
  // M^-1 = sigma_dict [[1 / (sx k), -rho / (sy k)], [0, 1 / sy]] (GLSL matrices are column-major).
  mat2 invM = GLINT_DICT_SIGMA * mat2(1.0 / (sigma.x * k), 0.0, -rho / (sigma.y * k), 1.0 / sigma.y);
  return GlintLobe(A, invM, determinant(invM));
}

// The footprint ellipse in the cells of one level: the implicit ellipse A s^2 + B s t + C t^2 < 1
// about st (cell centres at integers), widened by one cell (pbrt-v3, MIPMap::EWA), and its
// bounding box of cells [lo, hi].
struct GlintEllipse {
  vec2 st;
  vec3 abc;
  ivec2 lo, hi;
};

// The pixel's footprint at the two levels of the virtual MIP hierarchy that the patch-SDF blends
// (2021, eq. 3), computed once per pixel. level < 0 marks a degenerate footprint (the smooth NDF).
struct GlintPatch {
  int level;
  float blend;  // weight of level + 1
  GlintEllipse fine, coarse;
};

GlintEllipse glintEllipse(vec2 uv, vec2 axis0, vec2 axis1, int level) {
  float cellsPerUV = exp2(float(GLINT_LEVELS - 1 - level));
  vec2 st = uv * cellsPerUV - 0.5;
  vec2 d0 = axis0 * cellsPerUV, d1 = axis1 * cellsPerUV;
  float A = d0.y * d0.y + d1.y * d1.y + 1.0;
  float B = -2.0 * (d0.x * d0.y + d1.x * d1.y);
  float C = d0.x * d0.x + d1.x * d1.x + 1.0;
  vec3 abc = vec3(A, B, C) / (A * C - 0.25 * B * B);
  float det = 4.0 * abc.x * abc.z - abc.y * abc.y;
  vec2 halfBox = 2.0 * sqrt(vec2(det * abc.z, det * abc.x)) / det;
  return GlintEllipse(st, abc, ivec2(ceil(st - halfBox)), ivec2(floor(st + halfBox)));
}

// The pixel footprint's uv derivatives (in the glint uv: core/footprint.glsl, footprintInUnits) as
// an ellipse with a major axis, the longer of the two, and a minor one lengthened so that the
// eccentricity is at most maxAnisotropy (pbrt's EWA clamp, as the papers' shaders); its level of
// detail lod = levels - 1 + log2(|minor|): level l has 2^(levels - 1 - l) cells per uv unit, so
// the minor axis spans one to two cells of level floor(lod).
GlintPatch glintPatch(vec2 uv, Footprint footprint, float maxAnisotropy) {
  vec2 major = footprint.dUVdx, minor = footprint.dUVdy;
  if (dot(major, major) < dot(minor, minor)) {
    major = footprint.dUVdy;
    minor = footprint.dUVdx;
  }
  float majorLength = length(major), minorLength = length(minor);
  if (minorLength * maxAnisotropy < majorLength && minorLength > 0.0) {
    float scale = majorLength / (minorLength * maxAnisotropy);
    minor *= scale;
    minorLength *= scale;
  }
  float lod = minorLength > 0.0 ? max(0.0, float(GLINT_LEVELS - 1) + log2(minorLength)) : -1.0;
  int level = int(floor(lod));
  return GlintPatch(level, lod - floor(lod), glintEllipse(uv, major, minor, max(level, 0)),
                    glintEllipse(uv, major, minor, max(level + 1, 0)));
}

// Integer hash of Hugo Elias / Inigo Quilez, to [0, 1] (the papers' pseudo-random numbers).
float glintHash(uint n) {
  n = (n << 13u) ^ n;
  n = n * (n * n * 15731u + 789221u) + 1376312589u;
  return float(n & 0x7fffffffu) / float(0x7fffffff);
}


// Everything a cell's distribution depends on besides the cell.
struct GlintQuery {
  vec2 slope;               // half-vector slope (-h.xy / h.z) in the shading frame
  vec2 slopeDx, slopeDy;    // its footprint kernel (s_K times its screen derivatives); 0: unfiltered
  bool filtered;            // textureGrad with the kernel (2021) or textureLod (2020)
  float logDensity;         // ln microfacets per unit uv area
  float relativeArea;       // fraction of non-empty cells
};

// P_M^22 of one cell (2020, Alg. 3; 2021, eqs. 4-6, 15, 18): its microfacets drawn from the cell's
// seed, which depends only on the cell's corner in the finest level's cells (coherent across
// levels and frames). levelBase: the dictionary level log4(microfacets per cell) of this level.
float glintCellP22(GlintQuery q, GlintLobe lobe, int level, ivec2 cell, float levelBase) {
  uvec2 corner = uvec2(cell) << uint(level);
  uint seed = corner.x + 1549u * corner.y;
  if (glintHash(seed * 13u) > q.relativeArea) return 0.0;  // an empty cell

  // The dictionary level: the cell's microfacet count, jittered so that levels do not pop at once.
  float u = clamp(glintHash(seed * 2171u), 1e-6, 1.0 - 1e-6);
  float dictLevel = clamp(round(levelBase + GLINT_LEVEL_JITTER * 1.41421356 * erfInverse(2.0 * u - 1.0)), 0.0,
                          float(GLINT_LEVELS));
  if (dictLevel >= float(GLINT_LEVELS)) return slopeDensityBeckmann(q.slope, lobe.A);

  // Random rotation, then the material's transform: slopes in the dictionary's space.
  float theta = TWO_PI * glintHash(seed);
  float c = cos(theta), s = sin(theta);
  mat2 invM = mat2(c, -s, s, c) * lobe.invM;  // R(-theta) M^-1
  vec2 m = invM * q.slope;
  if (any(greaterThan(abs(m), vec2(GLINT_SLOPE_RANGE)))) return 0.0;

  int i = min(int(glintHash(seed * 16807u) * float(GLINT_MARGINALS)), GLINT_MARGINALS - 1);
  int j = min(int(glintHash(seed * 48271u) * float(GLINT_MARGINALS)), GLINT_MARGINALS - 1);
  int l = int(dictLevel);
  float px, py;
  if (q.filtered) {
    vec2 dx = invM * q.slopeDx, dy = invM * q.slopeDy;
    px = glintMarginalFiltered(l, i, m.x, dx.x, dy.x);
    py = glintMarginalFiltered(l, j, m.y, dx.y, dy.y);
  } else {
    px = glintMarginal(l, i, m.x);
    py = glintMarginal(l, j, m.y);
  }
  return px * py * lobe.detInvM;
}

// r^2 of cell (s, t): inside the ellipse when < 1.
float glintCellRadius2(GlintEllipse e, int s, int t) {
  vec2 d = vec2(s, t) - e.st;
  return e.abc.x * d.x * d.x + e.abc.y * d.x * d.y + e.abc.z * d.y * d.y;
}

// The number of cells inside the footprint at one level, without the guard (diagnostics).
int glintCellCount(GlintEllipse e) {
  int count = 0;
  for (int t = e.lo.y; t <= e.hi.y; ++t)
    for (int s = e.lo.x; s <= e.hi.x; ++s)
      if (glintCellRadius2(e, s, t) < 1.0) ++count;
  return count;
}

// The cells of one level inside the footprint, weighted by a truncated Gaussian (pbrt's EWA:
// W = exp(-2 r^2) - exp(-2); 2020, Alg. 2) and normalised by the weights' sum; at most
// GLINT_MAX_CELLS of them.
float glintLevelP22(GlintQuery q, GlintLobe lobe, GlintEllipse e, int level) {
  if (level >= GLINT_LEVELS) return slopeDensityBeckmann(q.slope, lobe.A);
  float levelBase = float(level - (GLINT_LEVELS - 1)) + q.logDensity / 1.38629436;  // log4 of the count
  float sum = 0.0, weights = 0.0;
  int evaluated = 0;
  for (int t = e.lo.y; t <= e.hi.y && evaluated < GLINT_MAX_CELLS; ++t)
    for (int s = e.lo.x; s <= e.hi.x && evaluated < GLINT_MAX_CELLS; ++s) {
      float r2 = glintCellRadius2(e, s, t);
      if (r2 < 1.0) {
        float w = exp(-2.0 * r2) - exp(-2.0);
        sum += w * glintCellP22(q, lobe, level, ivec2(s, t), levelBase);
        weights += w;
        ++evaluated;
      }
    }
  return weights > 0.0 ? sum / weights : 0.0;
}

// The patch-SDF (2021, eq. 3 or eq. 10 when filtered): the two levels around the footprint's
// level of detail, blended linearly.
float glintP22(GlintQuery q, GlintLobe lobe, GlintPatch footprint) {
  if (footprint.level < 0) return slopeDensityBeckmann(q.slope, lobe.A);
  return mix(glintLevelP22(q, lobe, footprint.fine, footprint.level), glintLevelP22(q, lobe, footprint.coarse, footprint.level + 1),
             footprint.blend);
}
