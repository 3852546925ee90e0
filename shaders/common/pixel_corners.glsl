// The reflected rays through the four corners of a pixel (Podee et al., sec. 3.1, Fig. 2), two
// ways: exact, by interpolating the vertex attributes at the corners (attributesAtOffset) and
// reading the normal map there; or to first order, from the screen-space derivatives of the
// centre's position and reflection vector. Call in uniform control flow (derivatives; a branch
// on a uniform is uniform).
#include "common/fragment_inputs.glsl"
#include "common/frame.glsl"
#include "common/reflection_space_shading.glsl"
#include "common/surface.glsl"

// Corner offsets from the pixel centre, counter-clockwise on screen.
const vec2 PIXEL_CORNERS[4] = vec2[](vec2(-0.5, -0.5), vec2(0.5, -0.5), vec2(0.5, 0.5), vec2(-0.5, 0.5));

// Exact corners: the attributes interpolated at the corner, the shading normal rebuilt there as
// forward.frag builds it at the centre (same side of the surface, same normal-map frame). The
// normal map is read with the centre's footprint, so a corner normal is as filtered as the
// centre's: detail smaller than that footprint is invisible to the corners (the method's failure
// case at a distance, docs/methods.md#podee).
CornerRays interpolatedCornerRays(Surface s) {
  CornerRays rays;
  float side = dot(normalize(vNormal), s.vertexNormal) < 0.0 ? -1.0 : 1.0;
  for (int i = 0; i < 4; ++i) {
    VertexAttributes corner = attributesAtOffset(PIXEL_CORNERS[i]);
    vec3 p = corner.position;
    vec3 n = normalize(corner.normal) * side;
#if MATERIAL_NORMAL_MAP
    vec3 t, b;
    vertexTangentFrame(n, corner.tangent, side, t, b);
    n = mappedNormal(textureGrad(uNormalMap, normalMapCoordinates(corner.uv), s.dUVdx, s.dUVdy).xyz, t, b, n);
#endif
    rays.origin[i] = p;
    rays.direction[i] = reflect(-viewDirectionFrom(p), n);
  }
  return rays;
}

// First-order corners: r + dr/dx ox + dr/dy oy from the centre's shading normal (normal map
// included). Fine derivatives are one-sided within the 2x2 quad, so two of the four corners are
// extrapolated.
CornerRays derivativeCornerRays(Surface s) {
  vec3 r = reflect(-s.view, s.normal);
  vec3 drdx = dFdxFine(r), drdy = dFdyFine(r);
  CornerRays rays;
  for (int i = 0; i < 4; ++i) {
    vec2 o = PIXEL_CORNERS[i];
    rays.origin[i] = s.position + o.x * s.dPdx + o.y * s.dPdy;
    rays.direction[i] = normalize(r + o.x * drdx + o.y * drdy);
  }
  return rays;
}
