// Method `lean`: LEAN mapping (Olano & Baker 2010): the normal map's slope moments, filtered by
// the texture hardware, give the mean normal and the slope covariance inside the pixel's
// texture footprint. Descriptor: src/shading/methods/lean.cpp; docs/methods.md#lean.
#include "common/lobe_shading.glsl"
#include "common/slope_moments.glsl"

uniform float param_mirror_alpha;

Lobe gLeanLobe;  // this pixel's lobe, set by prepareSurface

void prepareSurface(inout Surface s) {
  gLeanLobe = materialLobe(s);
#if MATERIAL_NORMAL_MAP
  vec2 b;
  mat2 covariance = footprintSlopeCovariance(s, b);
  // Shading frame: the mean normal (B, 1) over the vertex frame; the lobe's covariance lives in
  // the base surface's slope space and is used about the mean normal (exact for small B).
  setShadingNormal(s, mappedNormal(vec3(b, 1.0), s.vertexTangent, s.vertexBitangent, s.vertexNormal));
  gLeanLobe.A += 2.0 * covariance;
#endif
}

Radiance shadeLight(Surface s, LightData L) { return shadeLobe(s, L, gLeanLobe, param_mirror_alpha); }
