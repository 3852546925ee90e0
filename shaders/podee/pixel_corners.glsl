// The reflected rays through the four corners of a pixel (Podee et al., sec. 3.1, Fig. 2), two
// ways: exact, by interpolating the vertex attributes at the corners (attributesAtOffset) and
// reading the normal map there; or to first order, from the screen-space derivatives of the
// centre's position and reflection vector. Call in uniform control flow (derivatives; a branch
// on a uniform is uniform).
#include "core/fragment_inputs.glsl"
#include "core/frame.glsl"
#include "podee/reflection_space_shading.glsl"
#include "core/surface.glsl"

// Corner offsets from the pixel centre, counter-clockwise on screen.
const vec2 PIXEL_CORNERS[4] = vec2[](vec2(-0.5, -0.5), vec2(0.5, -0.5), vec2(0.5, 0.5), vec2(-0.5, 0.5));

// The normal map as the corners see it: read over the pixel's texture footprint scaled by
// 2^lodBias, i.e. lodBias mip levels finer than the centre's (0: the centre's level, where detail
// smaller than the pixel is averaged away, the method's failure case at a distance; -16: in
// effect the base level, bilinear). docs/methods.md#podee, parameter `corner_lod`.
vec3 cornerNormalMap(Surface s, vec2 uv, float lodBias) {
  float scale = exp2(lodBias);
  vec2 dx = s.footprint.dUVdx * scale, dy = s.footprint.dUVdy * scale;
  vec2 st = normalMapFilterCoordinates(uv, dx, dy);
  return textureGrad(uNormalMap, st, dx, dy).xyz;
}

// A corner past the silhouette. The attributes at a corner are the triangle's planes extrapolated
// beyond its edge; on a silhouette triangle, nearly edge-on, they turn the vertex normal through
// large angles within half a pixel, past the contour (n . v = 0) until it faces away from the
// viewer, and its reflection swings back towards the viewer (a normal facing away reflects as its
// opposite). The surface the pixel sees ends at the contour, whose reflection is the view ray
// itself, grazing on: that direction bounds the reflection space on that side.
vec3 cornerReflection(vec3 view, vec3 vertexNormal, vec3 shadingNormal) {
  return dot(vertexNormal, view) < 0.0 ? -view : reflect(-view, shadingNormal);
}

// Exact corners: the attributes interpolated at the corner, the shading normal rebuilt there as
// forward.frag builds it at the centre (same side of the surface, same normal-map frame), the
// normal map read at the level cornerNormalMap chooses.
CornerRays interpolatedCornerRays(Surface s, float lodBias) {
  CornerRays rays;
  float side = dot(normalize(vNormal), s.vertexNormal) < 0.0 ? -1.0 : 1.0;
  for (int i = 0; i < 4; ++i) {
    VertexAttributes corner = attributesAtOffset(PIXEL_CORNERS[i]);
    vec3 p = corner.position;
    vec3 vertexNormal = normalize(corner.normal) * side;
    vec3 n = vertexNormal;
#if MATERIAL_NORMAL_MAP
    vec3 t, b;
    vertexTangentFrame(n, corner.tangent, side, t, b);
    n = mappedNormal(cornerNormalMap(s, normalMapCoordinates(corner.uv), lodBias), t, b, n);
#endif
    rays.origin[i] = p;
    rays.direction[i] = cornerReflection(viewDirectionFrom(p), vertexNormal, n);
  }
  return rays;
}

// First-order corners: origins from the pixel footprint (core/footprint.glsl), directions
// r + dr/dx ox + dr/dy oy from the centre's normal (normal map included, read at the level
// cornerNormalMap chooses; dr by quad differences, as it depends on the map). Fine derivatives are
// one-sided within the 2x2 quad, so two of the four corners are extrapolated.
CornerRays derivativeCornerRays(Surface s, float lodBias) {
  vec3 n = s.normal;
#if MATERIAL_NORMAL_MAP
  n = mappedNormal(cornerNormalMap(s, s.uv, lodBias), s.vertexTangent, s.vertexBitangent, s.vertexNormal);
#endif
  vec3 r = reflect(-s.view, n);
  vec3 drdx = dFdxFine(r), drdy = dFdyFine(r);
  CornerRays rays;
  for (int i = 0; i < 4; ++i) {
    vec2 o = PIXEL_CORNERS[i];
    rays.origin[i] = footprintPositionAt(s.footprint, s.position, o);
    rays.direction[i] = normalize(r + o.x * drdx + o.y * drdy);
    // Past the silhouette (the vertex normal, to first order, facing away): the contour's reflection.
    vec3 vertexNormal = s.vertexNormal + o.x * s.footprint.dNdx + o.y * s.footprint.dNdy;
    if (dot(vertexNormal, viewDirectionFrom(rays.origin[i])) < 0.0) rays.direction[i] = -viewDirectionFrom(rays.origin[i]);
  }
  return rays;
}
