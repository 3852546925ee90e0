// Method `lean`: LEAN mapping (Olano & Baker 2010): the normal map's slope moments, filtered by
// the texture hardware, give the mean normal and the slope covariance inside the pixel's
// texture footprint. Descriptor: src/shading/methods/lean.cpp; docs/methods.md#lean.
#include "common/lobe_shading.glsl"
#include "common/roughness_filtering.glsl"

uniform float param_mirror_alpha;

// Slope moments of the material's normal map (src/render/gpu_scene.cpp): (Bx, By, Bx^2, By^2)
// and Bx By, mipmapped by plain averaging.
layout(binding = 1) uniform sampler2D uSlopeMoments;
layout(binding = 2) uniform sampler2D uSlopeCrossMoment;

Lobe gLeanLobe;  // this pixel's lobe, set by prepareSurface

void prepareSurface(inout Surface s) {
  gLeanLobe = materialLobe(s);
#if MATERIAL_NORMAL_MAP
  vec4 m = textureGrad(uSlopeMoments, s.uv, s.dUVdx, s.dUVdy);
  float mxy = textureGrad(uSlopeCrossMoment, s.uv, s.dUVdx, s.dUVdy).r;
  // Shading frame: the mean normal (B, 1) over the vertex frame; the lobe's covariance lives in
  // the base surface's slope space and is used about the mean normal (exact for small B).
  setShadingNormal(s, normalize(m.x * s.vertexTangent + m.y * s.vertexBitangent + s.vertexNormal));
  gLeanLobe.A += 2.0 * leanSlopeCovariance(m.xy, vec3(m.zw, mxy));
#endif
}

Radiance shadeLight(Surface s, LightData L) { return shadeLobe(s, L, gLeanLobe, param_mirror_alpha); }
