// The glinty NDF of Deliot & Belcour 2023 (docs/methods.md#deliot2023): over each of the
// footprint's four grids, a triangle (simplex) grid of surface cells with per-vertex random
// density and slope-grid offset; per vertex, the binomial count of its facets that reflect h,
// drawn per cell of a slope grid over the projected half vector h.xy and interpolated bilinearly;
// D_glint(h) = sum over grids and vertices of weight x count / facets, times D(0) / R, so that
// E[D_glint(h)] = D(h), the material's GGX NDF.
#include "glints/binomial/counting.glsl"
#include "glints/binomial/footprint.glsl"

const int BINOMIAL_VERTICES = 12;  // 4 grids x 3 triangle vertices

// A surface-grid vertex of one grid: all of it that does not depend on the light.
struct BinomialVertex {
  float facets;      // its facets in this grid's share: N_v x grid weight (N_v: uv area x density)
  float perFacet;    // what one reflecting facet adds to the sum: barycentric weight / N_v
  vec2 slopeOffset;  // random offset of its slope grid, in cells
  uvec2 key;         // seeds its slope cells' random numbers
};

struct BinomialSurface {
  BinomialVertex vertices[BINOMIAL_VERTICES];
  float microfacetRoughness;  // R
  float slopeGridScale;       // slope cells per unit of h.xy
};

// The triangle of a lattice of equilateral triangles of side 1 around x: skewed onto the integer
// lattice by S = [[1, 1/sqrt3], [0, 2/sqrt3]] (S maps the lattice's (1, 0) and (-1/2, sqrt3/2) to
// (1, 0) and (0, 1)), where the triangles are the halves of the unit squares under the diagonal
// (0, 0)-(1, 1); the barycentric weights are linear in x, so continuous across edges.
void simplexTriangle(vec2 x, out ivec2 vertex[3], out vec3 weight) {
  vec2 s = vec2(x.x + 0.57735027 * x.y, 1.15470054 * x.y);
  vec2 c = floor(s), f = s - c;
  ivec2 i = ivec2(c);
  bool lower = f.x > f.y;
  vertex = ivec2[3](i, i + (lower ? ivec2(1, 0) : ivec2(0, 1)), i + ivec2(1, 1));
  weight = lower ? vec3(1.0 - f.x, f.x - f.y, f.y) : vec3(1.0 - f.y, f.y - f.x, f.x);
}

// uv area per lattice vertex in grid units: det S^-1.
const float SIMPLEX_AREA = 0.8660254;

// The per-pixel part: the twelve vertices of the footprint's grids around uv, for a material of
// ln density logDensity (per uv area) randomised per vertex by exp(randomization x N(0, 1)), the
// exponent clamped to [0, 50] as in the paper (at least one facet per uv area; no overflow).
BinomialSurface binomialSurface(vec2 uv, BinomialFootprint footprint, float logDensity, float randomization,
                                float microfacetRoughness, float slopeGridScale) {
  BinomialSurface b;
  b.microfacetRoughness = microfacetRoughness;
  b.slopeGridScale = slopeGridScale;
  for (int g = 0; g < 4; ++g) {
    BinomialGrid grid = footprint.grids[g];
    vec2 minor = vec2(-grid.major.y, grid.major.x);
    vec2 x = vec2(dot(uv, minor), dot(uv, grid.major) / grid.ratio) / grid.cellSize;
    ivec2 vertex[3];
    vec3 w;
    simplexTriangle(x, vertex, w);
    float area = SIMPLEX_AREA * grid.cellSize * grid.cellSize * grid.ratio;
    for (int t = 0; t < 3; ++t) {
      uvec4 r = pcg4d(uvec4(uvec2(vertex[t]), grid.seed, 0x9e3779b9u));
      float density = exp(clamp(logDensity + randomization * randomNormal(randomUnit2(r.xy)), 0.0, 50.0));
      float facets = area * density;
      b.vertices[3 * g + t] = BinomialVertex(facets * grid.weight, w[t] / facets, randomUnit2(r.zw), r.xy);
    }
  }
  return b;
}

// Of the footprint's facets, the share that reflect, each with probability p, counted at the
// slope-grid position `slope` (h.xy x slopeGridScale): each vertex's slope grid gives every cell its
// own uniform (the gate) and normal (the count) numbers; the counts at the four cells around the
// position are blended bilinearly. E[gate x count] = n p, so E[share] = p.
float binomialReflectingShare(BinomialSurface b, vec2 slope, float p, int model) {
  float sum = 0.0;
  for (int i = 0; i < BINOMIAL_VERTICES; ++i) {
    BinomialVertex v = b.vertices[i];
    float p1 = probabilityAnyReflects(p, v.facets);
    vec2 law = remainingLaw(p, v.facets, p1, model);
    vec2 s = slope + v.slopeOffset;
    vec2 c = floor(s), f = s - c;
    float count = 0.0;
    for (int k = 0; k < 4; ++k) {
      ivec2 corner = ivec2(k & 1, k >> 1);
      uvec4 r = pcg4d(uvec4(uvec2(ivec2(c) + corner), v.key));
      vec2 u = randomUnit2(r.xy);
      vec2 bilinear = mix(1.0 - f, f, vec2(corner));
      float gate = reflectionGate(p1, u.x);
      count += bilinear.x * bilinear.y * gate * countGivenAny(law, v.facets, randomNormal(randomUnit2(r.zw)), model);
    }
    sum += v.perFacet * count;
  }
  return sum;
}

// D_glint(h) for the GGX NDF of roughness alpha with REMAINING_COUNT_* model `model`. A facet reflects
// with probability p = R D(h) / D(0) = R / e^2 (GGX: D = 1 / (pi ax ay e^2), e = 1 at h = n), so
// E[D_glint] = E[share] D(0) / R = D(h).
float binomialNdf(BinomialSurface b, vec3 h, vec2 alpha, int model) {
  if (h.z <= 0.0) return 0.0;
  vec2 a = max(alpha, vec2(MIN_ALPHA));
  float e = (h.x * h.x) / (a.x * a.x) + (h.y * h.y) / (a.y * a.y) + h.z * h.z;
  float R = b.microfacetRoughness;
  float p = min(R / (e * e), 1.0);
  return binomialReflectingShare(b, h.xy * b.slopeGridScale, p, model) / (PI * a.x * a.y * R);
}
