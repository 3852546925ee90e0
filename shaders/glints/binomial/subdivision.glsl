// The light subdivision of Kneiphof & Klein 2024 (docs/methods.md#kneiphof2024): a quad light cut
// into cells with probabilities p_i, the facets that reflect the whole light (probability
// p = sum p_i) counted as in binomialReflectingShare, then split down a binary tree over the cells
// (glints/binomial/count_split.glsl), so that each cell knows its own reflecting facets,
// E[share_i] = p_i, and the glints take the cells' colours and positions instead of the whole
// light's average.
//
// Before including, define LIGHT_CELLS (4 or 16: 2 x 2 or 4 x 4 cells).
#include "glints/binomial/count_split.glsl"
#include "core/fragment_inputs.glsl"
#include "glints/binomial/area_shading.glsl"
#include "glints/binomial/light_probability.glsl"

// n, as a loop bound the compiler cannot see through: keeps the loops below rolled. Unrolled,
// the 4 x 4 split (12 vertices x 4 cells x 15 splits) and the 16 cells' LTC integrals make a
// shader llvmpipe takes minutes to compile. (uMaterial is an index, never negative.)
int rolledCount(int n) { return uMaterial >= 0 ? n : 0; }

// The glinty specular integral over a quad light cut into LIGHT_CELLS cells of equal parameter
// area (the quad's own bilinear subdivision, an exact partition, instead of the paper's slerped
// spherical quad), per unit radiance: sum over the cells of g_i x the cell's LTC integral, with
// p_i from the D-only LTC and g_i = share_i / p_i. The count is drawn at the half vector towards
// the quad's centre, as undivided. `reuseGgxShape`: p_i from the cell's GGX LTC integral (as
// glintLightIntegral).
vec3 subdividedGlintSpecular(Surface s, GlintLtc ltc, BinomialSurface b, LightData L, vec3 wo, int model,
                             const bool reuseGgxShape) {
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
    integral[i] = ltcPolygonIntegral(ltc.ggxMinv, v, 4);
    pNode[LIGHT_FIRST_LEAF + i] = ltc.ndfScale * (reuseGgxShape ? integral[i] : ltcPolygonIntegral(ltc.ndfMinv, v, 4));
  }
  for (int j = LIGHT_FIRST_LEAF - 1; j >= 0; --j) pNode[j] = pNode[2 * j + 1] + pNode[2 * j + 2];
  if (!(pNode[0] > 0.0)) return vec3(0.0);
  // p > 1 clamped as undivided; the cells keep their ratios.
  float scale = min(1.0, 1.0 / pNode[0]);
  for (int j = 0; j < LIGHT_TREE_NODES; ++j) pNode[j] *= scale;
  vec3 centreDir = normalize(toLocal(s, lightCentreDirection(L, s.position)));
  vec3 h = normalize(wo + centreDir);
  float share[LIGHT_CELLS];
  binomialReflectingSharesSplit(b, h.xy * b.slopeGridScale, pNode, rolledCount(BINOMIAL_VERTICES), model, share);
  float sum = 0.0;
  for (int i = 0; i < LIGHT_CELLS; ++i) {
    float pi = pNode[LIGHT_FIRST_LEAF + i];
    if (pi > 0.0) sum += share[i] / pi * integral[i];
  }
  return ltc.ggxScale * sum;
}
