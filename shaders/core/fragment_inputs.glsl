// The forward pass's per-fragment inputs: interpolated vertex attributes (passes/forward.vert)
// and the draw's material. Declared before the method module, so that a method may re-evaluate
// the attributes elsewhere in the pixel (attributesAtOffset; see podee/pixel_corners.glsl).
#include "core/material_inputs.glsl"
#include "core/surface.glsl"  // Footprint, makeFootprint, vertexTangentFrame

#ifdef EXPORTED_SHADER
// An exported shader's entry point (export/shade_pixel.frag) sets them from its arguments.
vec3 vPosition;
vec3 vNormal;
vec4 vTangent;
vec2 vUV;
#else
in vec3 vPosition;
in vec3 vNormal;
in vec4 vTangent;
in vec2 vUV;
#endif

// The vertex attributes at `offset` pixels from the pixel centre, perspective-correct, as
// interpolateAtOffset would give them (extrapolated linearly beyond the triangle). An attribute
// divided by clip w, and 1/w (gl_FragCoord.w), are affine in screen space over the triangle, and
// the 2x2 quad's helper invocations evaluate the same planes, so first-order steps along their
// fine derivatives are exact. interpolateAtOffset itself is not used: Mesa's llvmpipe 22.x
// interpolates perspective inputs affinely at an offset (errors of 30% at a pixel's corner on a
// receding plane). Call in uniform control flow.
struct VertexAttributes {
  vec3 position, normal;
  vec4 tangent;
  vec2 uv;
};

vec4 affineAtOffset(vec4 v, vec2 offset) { return v + offset.x * dFdxFine(v) + offset.y * dFdyFine(v); }

VertexAttributes attributesAtOffset(vec2 offset) {
  float invW = gl_FragCoord.w;
  float w = 1.0 / affineAtOffset(vec4(invW), offset).x;
  vec4 position = affineAtOffset(vec4(vPosition, 1.0) * invW, offset) * w;
  vec4 normal = affineAtOffset(vec4(vNormal, 0.0) * invW, offset) * w;
  vec4 tangent = affineAtOffset(vTangent * invW, offset) * w;
  vec4 uv = affineAtOffset(vec4(vUV, 0.0, 0.0) * invW, offset) * w;
  return VertexAttributes(position.xyz, normal.xyz, tangent, uv.xy);
}

// The pixel footprint (core/footprint.glsl) from the fine screen-space derivatives of the
// interpolated attributes: the raster pass's ray differentials (per pixel, not per quad). Call in
// uniform control flow. Its normal derivatives are the interpolated normal's as interpolated, on
// the front side (the caller turns them to the seen side).
Footprint screenSpaceFootprint(vec3 view, vec2 uv) {
  vec3 t, b;
  vertexTangentFrame(normalize(vNormal), vTangent, 1.0, t, b);  // t is the same on either side
  return makeFootprint(dFdxFine(vPosition), dFdyFine(vPosition), dFdxFine(vNormal), dFdyFine(vNormal), dFdxFine(t),
                       dFdyFine(t), dFdxFine(view), dFdyFine(view), dFdxFine(vUV), dFdyFine(vUV), dFdxFine(uv),
                       dFdyFine(uv));
}
