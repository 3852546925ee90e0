// Binomial glints under an environment (Kneiphof & Klein 2025, "Real-time Image-based Lighting of
// Glints"; docs/methods.md#kneiphof2025): the environment is cut into regions of luminance L_k
// (level 0 black, three log-spaced lit levels; src/scene/lights/environment_glint_levels.hpp) whose
// weight maps are prefiltered by the radiance's own GGX chain, so that at the reflected direction
// w_k is the share of the lobe's reflected directions in region k. A footprint's facets reflect
// into the upper hemisphere with probability p (the D-only LTC's magnitude over T, as for a light
// of kneiphof2024), and region k with p_k = p w_k: their count, drawn as binomialReflectingShare
// draws it, is split down a binary tree over the four regions (count_split.glsl; the paper's
// hierarchical multinomial), and the split-sum radiance is scaled by
//   g = sum_k L_k share_k / sum_k L_k p_k,
// the glints' luminance over its expectation: E[share_k] = p_k makes E[g] = 1, so the glints' mean
// is the split sum's, and as the facets multiply g tends to 1.
//
// Before including, define LIGHT_CELLS = 4 (the regions).
#include "generated/gpu_contract.glsl"
#include "core/surface.glsl"
#include "glints/binomial/count_split.glsl"
#include "lights/environment.glsl"

layout(binding = ENVIRONMENT_GLINT_WEIGHTS_UNIT) uniform sampler2D uEnvironmentGlintWeights;

// The regions' weights w_1, w_2, w_3 at direction `dir` for a lobe of roughness alpha: the chain's
// level as the prefiltered radiance reads it (environmentPrefilteredRadiance).
vec3 environmentGlintWeights(LightData L, vec3 dir, float alpha) {
  float levels = float(textureQueryLevels(uEnvironmentGlintWeights));
  float lod = sqrt(clamp(alpha, 0.0, 1.0)) * (levels - 1.0);
  return clamp(textureLod(uEnvironmentGlintWeights, environmentUv(L, dir), lod).rgb, 0.0, 1.0);
}

// The lit levels L_1, L_2, L_3 (the environment light's record carries them).
vec3 environmentGlintLevels(LightData L) { return L.axis_u.xyz; }

// g for the footprint's facets b given the regions' weights w (w_1 .. w_3; w_0 the rest), their
// levels and p, the probability that a facet reflects into the upper hemisphere. The count is
// drawn at slope (0, 0) of each vertex's slope grid (the paper's choice: the set of sparkles
// changes only as the regions' probabilities cross the facets' thresholds, not with the half vector).
float environmentGlintFactorOfWeights(BinomialSurface b, vec3 w, vec3 levels, float p, int model) {
  float pNode[LIGHT_TREE_NODES];
  pNode[LIGHT_FIRST_LEAF] = p * max(1.0 - w.x - w.y - w.z, 0.0);
  pNode[LIGHT_FIRST_LEAF + 1] = p * w.x;
  pNode[LIGHT_FIRST_LEAF + 2] = p * w.y;
  pNode[LIGHT_FIRST_LEAF + 3] = p * w.z;
  for (int j = LIGHT_FIRST_LEAF - 1; j >= 0; --j) pNode[j] = pNode[2 * j + 1] + pNode[2 * j + 2];
  float expected = dot(levels, vec3(pNode[LIGHT_FIRST_LEAF + 1], pNode[LIGHT_FIRST_LEAF + 2], pNode[LIGHT_FIRST_LEAF + 3]));
  if (!(expected > 0.0)) return 1.0;  // a black environment, or no facet reflects it
  float share[LIGHT_CELLS];
  binomialReflectingSharesSplit(b, vec2(0.0), pNode, BINOMIAL_VERTICES, model, share);
  return dot(levels, vec3(share[1], share[2], share[3])) / expected;
}

// g at the reflected direction of s, for a lobe of roughness alpha.
float environmentGlintFactor(Surface s, BinomialSurface b, LightData L, float alpha, float p, int model) {
  vec3 w = environmentGlintWeights(L, reflect(-s.view, s.normal), alpha);
  return environmentGlintFactorOfWeights(b, w, environmentGlintLevels(L), p, model);
}
