// The split of a count of reflecting facets among the cells of a light (Kneiphof & Klein 2024's
// subdivision; docs/methods.md#kneiphof2024, "Subdivision"): the facets of a footprint that reflect
// the whole light, counted as in binomialReflectingShare, sent down a binary tree over the cells.
//
// A node's count c is a real number: the counting model's gate ramp and lognormal make it so, and
// below one expected facet it is a fraction of a facet. Its split must keep 0 <= left <= c (the
// right child takes exactly the rest) and E[left] = c q, q = p_left / p_node, at every c; drawing
// `left` by the counting model with n = c cannot (below one facet it hands the left child a whole
// facet; its clamp at c - 1 takes from the left what the right then receives).
//
// Before including, define LIGHT_CELLS (4 or 16: 2 x 2 or 4 x 4 cells; a power of 4 so that the
// leaves in Morton order make square blocks at every level of the tree).
#include "glints/binomial/ndf.glsl"

const int LIGHT_TREE_NODES = 2 * LIGHT_CELLS - 1;  // heap order: node j has children 2j + 1, 2j + 2
const int LIGHT_FIRST_LEAF = LIGHT_CELLS - 1;

// The cell of leaf i (Morton order) on a grid of side sqrt(LIGHT_CELLS).
ivec2 lightCellOfLeaf(int i) {
  return ivec2((i & 1) | ((i >> 1) & 2), ((i >> 1) & 1) | ((i >> 2) & 2));
}

// The part of count c that goes left, with q the left child's share of the node's probability:
// left = c (q + W (B - q)), W in [0, 1] choosing "whole" (W = 1: the count goes one way, left when
// B = 1) over "in proportion" (W = 0: c q), B a gate of mean q. E[B] = q makes E[left] = c q
// exactly whatever W is, and 0 <= left <= c. W and B are gate ramps (the count changes
// continuously with q and c), independent, so Var[left] = c^2 E[W^2] Var[B]; E[W^2] is chosen to
// make it c q (1 - q), the binomial variance of c facets, where that fits in [0, 1] (c >= 1.6 for
// any q; 1.15 at q = 1/2), and 1 below: a part of a facet goes whole, as a facet does.
float splitCount(float c, float q, uvec2 r) {
  vec2 u = randomUnit2(r);
  float binomial = q * (1.0 - q);
  float varianceB = max(reflectionGateSecondMoment(q) - q * q, 0.0);
  float wholeSecondMoment = varianceB > 0.0 ? min(1.0, binomial / (c * varianceB)) : 1.0;
  float whole = reflectionGate(reflectionGateWithSecondMoment(wholeSecondMoment), u.x);
  return c * mix(q, reflectionGate(q, u.y), whole);  // <= c in fp32 too: the right child's rest is >= 0
}

// A count down the tree: `count` at the leaves (LIGHT_FIRST_LEAF + i), from count[0] at the root,
// with pNode the cells' probabilities at the leaves and their sums at the inner nodes. Node j's
// split draws its own numbers from the slope cell and the vertex's key.
void splitDownTheTree(inout float count[LIGHT_TREE_NODES], float pNode[LIGHT_TREE_NODES], uvec2 cell, uvec2 key) {
  for (int j = 0; j < LIGHT_FIRST_LEAF; ++j) {
    float left = 0.0;
    if (count[j] > 0.0 && pNode[j] > 0.0) {
      uvec4 r = pcg4d(uvec4(cell, key.x ^ (uint(j + 1) * 0x9e3779b9u), key.y + 0x632be5abu));
      left = splitCount(count[j], clamp(pNode[2 * j + 1] / pNode[j], 0.0, 1.0), r.xy);
    }
    count[2 * j + 1] = left;
    count[2 * j + 2] = count[j] - left;
  }
}

// The shares of the footprint's facets that reflect each cell; pNode as above, pNode[0] = p <= 1.
// `vertices`: BINOMIAL_VERTICES, as a bound the caller may keep opaque (a rolled loop). The root
// count uses binomialReflectingShare's random numbers, so the shares sum to its share exactly.
void binomialReflectingSharesSplit(BinomialSurface b, vec2 slope, float pNode[LIGHT_TREE_NODES], int vertices,
                                   int model, out float share[LIGHT_CELLS]) {
  for (int i = 0; i < LIGHT_CELLS; ++i) share[i] = 0.0;
  float p = pNode[0];
  for (int i = 0; i < vertices; ++i) {
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
      count[0] = reflectionGate(p1, randomUnit2(r.xy).x) *
                 countGivenAny(law, v.facets, randomNormal(randomUnit2(r.zw)), model);
      splitDownTheTree(count, pNode, cell, v.key);
      float weight = v.perFacet * bilinear.x * bilinear.y;
      for (int l = 0; l < LIGHT_CELLS; ++l) share[l] += weight * count[LIGHT_FIRST_LEAF + l];
    }
  }
}
