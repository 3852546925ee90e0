// The light subdivision of Kneiphof & Klein 2024 (docs/methods.md#kneiphof2024): a quad light cut
// into cells with probabilities p_i, the facets that reflect the whole light (probability
// p = sum p_i) counted as in binomialReflectingShare, then split down a binary tree over the cells:
// a node's count c sends a part to its left child binomially with q = p_left / p_node, drawn by
// the counting model's own law (gate and remaining count, glints/binomial/counting.glsl), so
// E[left] = c q exactly and 0 <= left <= c; the right child gets the rest. Each cell then knows
// its own reflecting facets, E[share_i] = p_i, and the glints take the cells' colours and
// positions instead of the whole light's average.
//
// Before including, define LIGHT_CELLS (4 or 16: 2 x 2 or 4 x 4 cells; a power of 4 so that the
// leaves in Morton order make square blocks at every level of the tree).
#include "glints/binomial/ndf.glsl"
#include "core/fragment_inputs.glsl"
#include "glints/binomial/area_shading.glsl"
#include "glints/binomial/light_probability.glsl"

// n, as a loop bound the compiler cannot see through: keeps the loops below rolled. Unrolled,
// the 4 x 4 split (12 vertices x 4 cells x 15 splits) and the 16 cells' LTC integrals make a
// shader llvmpipe takes minutes to compile. (uMaterial is an index, never negative.)
int rolledCount(int n) { return uMaterial >= 0 ? n : 0; }

const int LIGHT_TREE_NODES = 2 * LIGHT_CELLS - 1;  // heap order: node j has children 2j + 1, 2j + 2
const int LIGHT_FIRST_LEAF = LIGHT_CELLS - 1;

// The cell of leaf i (Morton order) on a grid of side sqrt(LIGHT_CELLS).
ivec2 lightCellOfLeaf(int i) {
  return ivec2((i & 1) | ((i >> 1) & 2), ((i >> 1) & 1) | ((i >> 2) & 2));
}

// A count c >= 1 split with probability q to the left: as c facets, each going left with q.
float splitCount(float c, float q, uvec4 r, int model) {
  float p1 = probabilityAnyReflects(q, c);
  vec2 law = remainingLaw(q, c, p1, model);
  float gate = reflectionGate(p1, binomialUnit2(r.xy).x);
  return gate * countGivenAny(law, c, binomialGaussian(binomialUnit2(r.zw)), model);
}

// The shares of the footprint's facets that reflect each cell. `pNode`: the cells' probabilities
// at the leaves (LIGHT_FIRST_LEAF + i), their sums at the inner nodes; pNode[0] = p <= 1.
void binomialReflectingSharesSplit(BinomialSurface b, vec2 slope, float pNode[LIGHT_TREE_NODES], int model,
                                   out float share[LIGHT_CELLS]) {
  for (int i = 0; i < LIGHT_CELLS; ++i) share[i] = 0.0;
  float p = pNode[0];
  for (int i = 0; i < rolledCount(BINOMIAL_VERTICES); ++i) {
    BinomialVertex v = b.vertices[i];
    float p1 = probabilityAnyReflects(p, v.facets);
    vec2 law = remainingLaw(p, v.facets, p1, model);
    vec2 s = slope + v.slopeOffset;
    vec2 c = floor(s), f = s - c;
    for (int k = 0; k < 4; ++k) {
      ivec2 corner = ivec2(k & 1, k >> 1);
      uvec2 cell = uvec2(ivec2(c) + corner);
      uvec4 r = pcg4d(uvec4(cell, v.key));  // the same numbers as binomialReflectingShare's
      vec2 bilinear = mix(1.0 - f, f, vec2(corner));
      float count[LIGHT_TREE_NODES];
      count[0] = reflectionGate(p1, binomialUnit2(r.xy).x) *
                 countGivenAny(law, v.facets, binomialGaussian(binomialUnit2(r.zw)), model);
      for (int j = 0; j < LIGHT_FIRST_LEAF; ++j) {
        float left = 0.0;
        if (count[j] > 0.0 && pNode[j] > 0.0) {
          uvec4 rs = pcg4d(uvec4(cell, v.key.x ^ (uint(j + 1) * 0x9e3779b9u), v.key.y + 0x632be5abu));
          left = splitCount(count[j], clamp(pNode[2 * j + 1] / pNode[j], 0.0, 1.0), rs, model);
        }
        count[2 * j + 1] = left;
        count[2 * j + 2] = max(count[j] - left, 0.0);
      }
      float weight = v.perFacet * bilinear.x * bilinear.y;
      for (int l = 0; l < LIGHT_CELLS; ++l) share[l] += weight * count[LIGHT_FIRST_LEAF + l];
    }
  }
}

// The glinty specular integral over a quad light cut into LIGHT_CELLS cells of equal parameter
// area (the quad's own bilinear subdivision, an exact partition, instead of the paper's slerped
// spherical quad), per unit radiance: sum over the cells of g_i x the cell's LTC integral, with
// p_i from the D-only LTC and g_i = share_i / p_i. The count is drawn at the half vector towards
// the quad's centre, as undivided.
vec3 subdividedGlintSpecular(Surface s, GlintLtc ltc, BinomialSurface b, LightData L, vec3 wo, int model) {
  vec3 quad[LIGHT_POLYGON_MAX_VERTICES];
  lightPolygonForm(L, quad);
  for (int i = 0; i < LIGHT_POLYGON_MAX_VERTICES; ++i) quad[i] = toLocal(s, quad[i] - s.position);
  vec3 du = quad[1] - quad[0], dv = quad[3] - quad[0];
  const int side = LIGHT_CELLS == 4 ? 2 : 4;
  float pNode[LIGHT_TREE_NODES];
  float integral[LIGHT_CELLS];
  for (int i = 0; i < rolledCount(LIGHT_CELLS); ++i) {
    vec2 cell = vec2(lightCellOfLeaf(i)) / float(side);
    float step = 1.0 / float(side);
    vec3 corner = quad[0] + cell.x * du + cell.y * dv;
    vec3 v[LIGHT_POLYGON_MAX_VERTICES] = vec3[](corner, corner + step * du, corner + step * (du + dv), corner + step * dv);
    pNode[LIGHT_FIRST_LEAF + i] = ltc.ndfScale * ltcPolygonIntegral(ltc.ndfMinv, v, 4);
    integral[i] = ltcPolygonIntegral(ltc.ggxMinv, v, 4);
  }
  for (int j = LIGHT_FIRST_LEAF - 1; j >= 0; --j) pNode[j] = pNode[2 * j + 1] + pNode[2 * j + 2];
  if (!(pNode[0] > 0.0)) return vec3(0.0);
  // p > 1 clamped as undivided; the cells keep their ratios.
  float scale = min(1.0, 1.0 / pNode[0]);
  for (int j = 0; j < LIGHT_TREE_NODES; ++j) pNode[j] *= scale;
  vec3 centreDir = normalize(toLocal(s, lightCentreDirection(L, s.position)));
  vec3 h = normalize(wo + centreDir);
  float share[LIGHT_CELLS];
  binomialReflectingSharesSplit(b, h.xy * b.slopeGridScale, pNode, model, share);
  float sum = 0.0;
  for (int i = 0; i < LIGHT_CELLS; ++i) {
    float pi = pNode[LIGHT_FIRST_LEAF + i];
    if (pi > 0.0) sum += share[i] / pi * integral[i];
  }
  return ltc.ggxScale * sum;
}
