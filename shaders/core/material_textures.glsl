// A textured material's parameters at one point (the program variant MATERIAL_TEXTURES; glTF's
// metallic-roughness model, src/scene/materials/material.hpp TexturedMetalRough): factor x texel gives the
// base colour c, metallic m and perceptual roughness r; then
//   alpha = r^2, widened along the anisotropy direction to mix(alpha, 1, strength^2)
//     (KHR_materials_anisotropy),
//   f0 = mix(dielectric f0, c, m), Lambert albedo c (1 - m) (glTF 2.0, appendix B),
//   emission = emissive factor x emissive texel.
// The reference reads texels at the base level, at its own sample point (the surface itself);
// the methods filter them over the pixel's footprint, as they would in an engine.
#include "core/material.glsl"
#include "generated/gpu_contract.glsl"

layout(binding = BASE_COLOR_UNIT) uniform sampler2D uBaseColor;             // sRGB: decoded by the sampler
layout(binding = METALLIC_ROUGHNESS_UNIT) uniform sampler2D uMetallicRoughness;  // g: roughness, b: metallic
layout(binding = EMISSIVE_UNIT) uniform sampler2D uEmissive;               // sRGB

struct TexturedParameters {
  vec2 alpha;
  vec3 f0;
  vec3 diffuse;
  vec3 emission;
};

// One texture's texel at uv, through its slot's transform: at the base level, or filtered over
// the footprint (dUVdx, dUVdy: the uv's derivatives per pixel, the pixel footprint's dVertexUVdx
// and dVertexUVdy, mapped by the transform's linear part).
vec4 materialTexel(sampler2D texture, int slot, vec2 uv, vec2 dUVdx, vec2 dUVdy, bool atSample) {
  vec2 st = uTextureTransforms[slot] * vec3(uv, 1.0);
  mat2 linear = mat2(uTextureTransforms[slot]);
  return atSample ? textureLod(texture, st, 0.0) : textureGrad(texture, st, linear * dUVdx, linear * dUVdy);
}

TexturedParameters texturedParameters(MaterialData m, vec2 uv, vec2 dUVdx, vec2 dUVdy, bool atSample) {
  vec3 base = m.base_color.rgb * materialTexel(uBaseColor, TEXTURE_SLOT_BASE_COLOR, uv, dUVdx, dUVdy, atSample).rgb;
  vec4 mr = materialTexel(uMetallicRoughness, TEXTURE_SLOT_METALLIC_ROUGHNESS, uv, dUVdx, dUVdy, atSample);
  float metallic = clamp(m.metal_rough.x * mr.b, 0.0, 1.0);
  float roughness = clamp(m.metal_rough.y * mr.g, 0.0, 1.0);
  float alpha = roughness * roughness;
  float strength = m.metal_rough.z;
  TexturedParameters p;
  p.alpha = vec2(mix(alpha, 1.0, strength * strength), alpha);
  p.f0 = mix(m.dielectric_f0.rgb, base, metallic);
  p.diffuse = base * (1.0 - metallic);
  p.emission = m.emission.rgb * materialTexel(uEmissive, TEXTURE_SLOT_EMISSIVE, uv, dUVdx, dUVdy, atSample).rgb;
  return p;
}
