// The slope moments of the material's normal map (src/render/gpu_scene.cpp): (Bx, By, Bx^2, By^2)
// and Bx By, mipmapped by plain averaging, so that one filtered lookup over the pixel's texture
// footprint gives the mean and the covariance of the slopes there (LEAN mapping).
#include "core/material_inputs.glsl"  // the map's filter coordinates (core/normal_map.glsl)
#include "core/surface.glsl"
#include "lobe/roughness_filtering.glsl"
#include "generated/gpu_contract.glsl"

layout(binding = SLOPE_MOMENTS_UNIT) uniform sampler2D uSlopeMoments;
layout(binding = SLOPE_CROSS_MOMENT_UNIT) uniform sampler2D uSlopeCrossMoment;

// Covariance of the normal map's slopes inside the pixel's footprint; meanSlope: their mean B.
// Where the map is magnified, only the part of the blended texels' covariance that lies inside
// the pixel (magnifiedSpreadShare). Call in uniform control flow (textureGrad with the surface's uv
// derivatives is safe anywhere, but callers take it with their other per-pixel work).
mat2 footprintSlopeCovariance(Surface s, out vec2 meanSlope) {
  vec2 dx = s.footprint.dUVdx, dy = s.footprint.dUVdy;
  vec2 st = normalMapFilterCoordinates(s.uv, dx, dy);
  vec4 m = textureGrad(uSlopeMoments, st, dx, dy);
  float mxy = textureGrad(uSlopeCrossMoment, st, dx, dy).r;
  meanSlope = m.xy;
  float share = magnifiedSpreadShare(s.footprint.dUVdx, s.footprint.dUVdy, vec2(normalMapSize()));
  return share * leanSlopeCovariance(m.xy, vec3(m.zw, mxy));
}

// Jacobian of the shading frame's slopes q = (m.t, m.b) / (m.n) with respect to the vertex frame's
// slopes p (m = p.x T + p.y B + N) at p = meanSlope, where the shading normal is the mean normal:
// there m.t = m.b = 0 and m.n = sqrt(1 + |p|^2), so J_ij = (e_i . T_j) / sqrt(1 + |p|^2) (e = t, b;
// T = vertex tangent, bitangent): 1 / (1 + |p|^2) along the mean slope, 1 / sqrt(1 + |p|^2) across.
mat2 vertexToShadingSlopeJacobian(Surface s, vec2 meanSlope) {
  mat2 j = mat2(dot(s.tangent, s.vertexTangent), dot(s.bitangent, s.vertexTangent),       // column: d/dp.x
                dot(s.tangent, s.vertexBitangent), dot(s.bitangent, s.vertexBitangent));  // column: d/dp.y
  return j * inversesqrt(1.0 + dot(meanSlope, meanSlope));
}

// LEAN mapping's shading frame: the normal moved to the mean of the normal map's slopes inside the
// footprint (over the vertex frame). Returns their covariance in the shading frame's slopes, which
// widens a lobe as A + 2 Sigma': the moments are measured in the vertex frame's slopes, so
// Sigma' = J Sigma J^T (first order about the mean; without J, a lobe whose mean normal is tilted
// by theta is 1 / cos^2 theta too wide along the tilt and 1 / cos theta across it).
mat2 leanShadingFrame(inout Surface s) {
  vec2 meanSlope;
  mat2 covariance = footprintSlopeCovariance(s, meanSlope);
  setShadingNormal(s, mappedNormal(vec3(meanSlope, 1.0), s.vertexTangent, s.vertexBitangent, s.vertexNormal));
  mat2 j = vertexToShadingSlopeJacobian(s, meanSlope);
  return j * covariance * transpose(j);
}
