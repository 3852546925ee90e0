// Importance sampling of a pixel footprint's NDF over projected half vectors s = h.xy: the GLSL
// twins of src/prefilter/ndf_sampling.cpp (docs/methods.md#deng2022, "Importance sampling"), for
// deng2022's compressed pyramid (Deng et al. 2022, sec. 5.2) and yan2016's element mixture. Each
// sampler's density is the NDF its method evaluates over that NDF's mass, so that MIS weights and
// estimators built from the evaluation stay consistent. Discrete choices are single-pass weighted
// reservoirs (item i kept with probability m_i / (m_0 + ... + m_i): the last one kept is i with
// probability m_i / total), their uniforms hashed from `seed`; no array is indexed at run time.
#include "core/sampling.glsl"
#include "glints/normal-map/position_normal.glsl"
#include "glints/normal-map/prefiltered_ndf.glsl"

struct NdfSample {
  vec2 s;     // the projected half vector
  float pdf;  // its density over the plane of s; 0: no sample
};

const NdfSample NO_NDF_SAMPLE = NdfSample(vec2(0.0), 0.0);

// Stage `stage`, item i's uniform in [0, 1) of a sample's seed.
float ndfChoiceUniform(uint seed, uint stage, uint i) { return uintToUnit(hash3(uvec3(seed, stage, i))); }

// One step of a weighted reservoir: whether item i of mass m replaces the kept one; `total` sums
// the masses so far.
bool ndfReservoirTakes(float m, inout float total, float u) {
  total += max(m, 0.0);
  return m > 0.0 && u * total < m;
}

// ---- deng2022 ----

// Footprint f's pixels integrated over [x0, x1] (pixel coordinates), through its box prefix tables
// where the pyramid was packed with them, block by block otherwise.
float pndfRangeSum(PndfHeader h, uint f, vec2 x0, vec2 x1) {
  return h.tables != PNDF_NONE ? pndfPixelRangeSumByCorners(h, f, x0, x1) : pndfPixelRangeSum(h, f, x0, x1);
}

// The footprint's mass in the square: the integral of pndfDensity (the sampler's normaliser).
float pndfMass(PndfHeader h, vec2 centre, float sigma) {
  const PndfInterpolation interpolation = pndfInterpolation(h, centre, sigma);
  float sum = 0.0;
  for (int q = 0; q < 8; ++q) {
    float weight;
    const uint f = pndfCorner(interpolation, q, weight);
    if (weight > 0.0) sum += weight * pndfRangeSum(h, f, vec2(0.0), vec2(float(h.n)));
  }
  const float pixel = 2.0 * h.extent / float(h.n);
  return sum * pixel * pixel;
}

// The sampler's density at s: pndfDensity / pndfMass.
float pndfSamplePdf(PndfHeader h, vec2 centre, float sigma, vec2 s) {
  const float mass = pndfMass(h, centre, sigma);
  return mass > 0.0 ? pndfDensity(h, centre, sigma, s) / mass : 0.0;
}

// The inverse CDF of the unit tent on [-1, 1]: a pixel's box convolved with itself, the bilinear
// interpolation's kernel.
float ndfTentInverse(float u) { return u < 0.5 ? sqrt(2.0 * u) - 1.0 : 1.0 - sqrt(2.0 * max(1.0 - u, 0.0)); }

// Sec. 5.2: one of the trilinear blend's stored footprints by its weight times its mass, one of its
// kept blocks by its range mass, the block's pixel down a quadtree of range queries, then the
// pixel's centre plus a tent offset per axis (u), so that the samples' density is the bilinear
// interpolation pndfDensity evaluates, over the mass.
NdfSample pndfSample(PndfHeader h, vec2 centre, float sigma, uint seed, vec2 u) {
  const PndfInterpolation interpolation = pndfInterpolation(h, centre, sigma);
  const vec2 whole = vec2(float(h.n));
  float total = 0.0;
  uint footprint = PNDF_NONE;
  for (int q = 0; q < 8; ++q) {
    float weight;
    const uint f = pndfCorner(interpolation, q, weight);
    const float m = weight > 0.0 ? weight * pndfRangeSum(h, f, vec2(0.0), whole) : 0.0;
    if (ndfReservoirTakes(m, total, ndfChoiceUniform(seed, 0u, uint(q)))) footprint = f;
  }
  if (footprint == PNDF_NONE) return NO_NDF_SAMPLE;
  const float pixel = 2.0 * h.extent / float(h.n), mass = total * pixel * pixel;

  const int nb = h.n / h.b;
  float blocks = 0.0;
  ivec2 lo = ivec2(-1);
  for (int i = 0; i < nb * nb; ++i) {
    const ivec2 origin = ivec2(i % nb, i / nb) * h.b;
    const float m = pndfRangeSum(h, footprint, vec2(origin), vec2(origin + h.b));
    if (ndfReservoirTakes(m, blocks, ndfChoiceUniform(seed, 1u, uint(i)))) lo = origin;
  }
  if (lo.x < 0) return NO_NDF_SAMPLE;
  ivec2 hi = lo + h.b;
  // Down the quadtree: each side longer than a pixel split in two (log2 B levels).
  for (int level = 0; level < 16 && (hi.x - lo.x > 1 || hi.y - lo.y > 1); ++level) {
    const ivec2 mid = (lo + hi) / 2;
    const bvec2 split = greaterThan(hi - lo, ivec2(1));
    float children = 0.0;
    ivec2 keptLo = lo, keptHi = hi;
    for (int c = 0; c < 4; ++c) {
      const ivec2 side = ivec2(c & 1, c >> 1);
      if ((side.x == 1 && !split.x) || (side.y == 1 && !split.y)) continue;
      const ivec2 cLo = ivec2(split.x ? (side.x == 0 ? lo.x : mid.x) : lo.x, split.y ? (side.y == 0 ? lo.y : mid.y) : lo.y);
      const ivec2 cHi = ivec2(split.x ? (side.x == 0 ? mid.x : hi.x) : hi.x, split.y ? (side.y == 0 ? mid.y : hi.y) : hi.y);
      const float m = pndfRangeSum(h, footprint, vec2(cLo), vec2(cHi));
      if (ndfReservoirTakes(m, children, ndfChoiceUniform(seed, 2u + uint(level), uint(c)))) {
        keptLo = cLo;
        keptHi = cHi;
      }
    }
    if (!(children > 0.0)) return NO_NDF_SAMPLE;
    lo = keptLo;
    hi = keptHi;
  }
  const vec2 s = (vec2(lo) + 0.5 + vec2(ndfTentInverse(u.x), ndfTentInverse(u.y))) * pixel - h.extent;
  const float pdf = pndfDensity(h, centre, sigma, s) / mass;
  return pdf > 0.0 ? NdfSample(s, pdf) : NO_NDF_SAMPLE;
}

// ---- yan2016 ----

// An element of the footprint's sum (its subset past the budget) by its weight w_e, then a point of
// its Gaussian N2(mean_e, cov_e) (Box-Muller through the covariance's Cholesky factor, u). The
// mixture is normalised, so the pdf is positionNormalDensity. Two passes over the elements.
NdfSample positionNormalSample(sampler2D map, PositionNormalFootprint f, const int k, uint seed, vec2 u) {
  float total = 0.0;
  ivec2 chosen = ivec2(0);
  bool any = false;
  const int n = f.cells.x * f.cells.y;
  for (int i = 0; i < n; ++i) {
    const ivec2 e = positionNormalCellElement(f.firstCell + ivec2(i % f.cells.x, i / f.cells.x), f.stride, f.seed);
    const vec2 d = f.centre - (vec2(e) + 0.5) / float(k);
    const float distance2 = dot(d, f.totalInverse * d);
    const float w = distance2 > 9.0 ? 0.0 : exp(-0.5 * distance2);
    if (ndfReservoirTakes(w, total, ndfChoiceUniform(seed, 0u, uint(i)))) {
      chosen = e;
      any = true;
    }
  }
  if (!any) return NO_NDF_SAMPLE;
  vec2 centreOfElement, p;
  mat2 J;
  positionNormalElement(map, f, chosen, k, centreOfElement, p, J);
  const vec2 q = f.totalInverse * (f.centre - centreOfElement);
  const vec2 mean = p + J * (f.shapeVariance * q);
  const mat2 cov = J * f.sigmaU * transpose(J) + mat2(f.sigmaR2);
  const float radius = sqrt(-2.0 * log(max(1.0 - u.x, 1e-30))), angle = TWO_PI * u.y;
  const vec2 z = radius * vec2(cos(angle), sin(angle));
  const float l00 = sqrt(cov[0][0]), l10 = cov[0][1] / l00, l11 = sqrt(max(cov[1][1] - l10 * l10, 0.0));
  const vec2 s = mean + vec2(l00 * z.x, l10 * z.x + l11 * z.y);
  const float pdf = positionNormalDensity(map, f, k, s);
  return pdf > 0.0 ? NdfSample(s, pdf) : NO_NDF_SAMPLE;
}
