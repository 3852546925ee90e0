// The split-sum's second factor (Karis 2013, "Real Shading in Unreal Engine 4"): the directional
// albedo of the specular BRDF of core/brdf.glsl (GGX or Beckmann, height-correlated Smith G2,
// Schlick's F), E = f0 A + B, from the dfg table (src/tables/dfg_table.cpp; unit TABLE_UNIT_DFG
// from the table registry). Layout (src/tables/dfg/dfg.hpp): DFG_TABLE_SIZE^2 texels, (A, B) of
// GGX in .xy and of Beckmann in .zw, the texel centres at cos_o = (i + 0.5) / DFG_TABLE_SIZE and
// perceptual roughness r = sqrt(alpha) = (j + 0.5) / DFG_TABLE_SIZE: the texture coordinate of
// (cos_o, alpha) is (cos_o, sqrt(alpha)) itself, bilinear between the grid's points and held at
// its edges (clamped to the edge) beyond them.
#include "core/constants.glsl"
#include "generated/gpu_contract.glsl"

layout(binding = TABLE_UNIT_DFG) uniform sampler2D uDfg;

// (A, B) of NDF `ndf` (NDF_GGX or NDF_BECKMANN) at cos(theta_o) and alpha (floored at MIN_ALPHA,
// like the NDFs).
vec2 dfgTerms(int ndf, float cosO, float alpha) {
  vec2 uv = clamp(vec2(cosO, sqrt(max(alpha, MIN_ALPHA))), 0.0, 1.0);
  vec4 t = textureLod(uDfg, uv, 0.0);
  return ndf == NDF_BECKMANN ? t.zw : t.xy;
}

// The integral over the hemisphere of f_s(wo, wi) cos(theta_i) with Schlick's F of f0: f0 A + B.
vec3 splitSumSpecularAlbedo(int ndf, vec3 f0, float cosO, float alpha) {
  vec2 ab = dfgTerms(ndf, cosO, alpha);
  return f0 * ab.x + ab.y;
}
