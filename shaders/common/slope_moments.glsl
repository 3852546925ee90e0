// The slope moments of the material's normal map (src/render/gpu_scene.cpp): (Bx, By, Bx^2, By^2)
// and Bx By, mipmapped by plain averaging, so that one filtered lookup over the pixel's texture
// footprint gives the mean and the covariance of the slopes there (LEAN mapping).
#include "common/roughness_filtering.glsl"
#include "common/surface.glsl"

layout(binding = 1) uniform sampler2D uSlopeMoments;
layout(binding = 2) uniform sampler2D uSlopeCrossMoment;

// Covariance of the normal map's slopes inside the pixel's footprint; meanSlope: their mean B.
// Call in uniform control flow (textureGrad with the surface's uv derivatives is safe anywhere,
// but callers take it with their other per-pixel work).
mat2 footprintSlopeCovariance(Surface s, out vec2 meanSlope) {
  vec4 m = textureGrad(uSlopeMoments, s.uv, s.dUVdx, s.dUVdy);
  float mxy = textureGrad(uSlopeCrossMoment, s.uv, s.dUVdx, s.dUVdy).r;
  meanSlope = m.xy;
  return leanSlopeCovariance(m.xy, vec3(m.zw, mxy));
}

// LEAN mapping's shading frame: the normal moved to the mean of the normal map's slopes inside the
// footprint (over the vertex frame). Returns their covariance, which widens a lobe as A + 2 Sigma
// (about the mean normal; exact for small mean slopes).
mat2 leanShadingFrame(inout Surface s) {
  vec2 meanSlope;
  mat2 covariance = footprintSlopeCovariance(s, meanSlope);
  setShadingNormal(s, mappedNormal(vec3(meanSlope, 1.0), s.vertexTangent, s.vertexBitangent, s.vertexNormal));
  return covariance;
}
