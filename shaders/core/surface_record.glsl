// The surface record of a point of a shape seen from `view`, from its interpolated vertex
// attributes, its footprint and its normal-map value: what the forward pass builds per fragment
// (passes/forward.frag) and the path tracer per hit (passes/path_direct.comp), so both shade the
// same surface. Textured materials read their parameters here (MATERIAL_TEXTURES), at the base level
// for ground truth (REFERENCE_PASS).
#include "core/material_inputs.glsl"
#if MATERIAL_TEXTURES
#include "core/material_textures.glsl"
#endif
#include "core/surface.glsl"

// The tangent-space normal-map value at uv ((0, 0, 1) without a map): for ground truth
// (REFERENCE_PASS) the map at the sample point itself, bilinear at level 0 (the normals a filtered
// level would average away are the highlights being judged); for a method filtered over the
// footprint's uv derivatives.
vec3 normalMapValue(vec2 uv, vec2 dUVdx, vec2 dUVdy) {
#if MATERIAL_NORMAL_MAP && REFERENCE_PASS
  return normalMapAtPoint(uv);
#elif MATERIAL_NORMAL_MAP
  vec2 st = normalMapFilterCoordinates(uv, dUVdx, dUVdy);
  return textureGrad(uNormalMap, st, dUVdx, dUVdy).xyz;
#else
  return vec3(0.0, 0.0, 1.0);
#endif
}

// position: world space; normal and tangent: as interpolated (the normal not normalised, the
// tangent's w its handedness); vertexUV: the mesh's uv, uv: normalMapCoordinates(vertexUV);
// faceNormal: the triangle's normal, either way round; footprint: how all of it changes over the
// pixel, its normal derivatives those of the interpolated normal on its front side; mapped: the
// tangent-space normal-map value ((0, 0, 1) without a map). `emission`: the material's, at this point.
Surface surfaceRecord(MaterialData m, vec3 position, vec3 normal, vec4 tangent, vec2 vertexUV, vec2 uv, vec3 view,
                      vec3 faceNormal, Footprint footprint, vec3 mapped, out vec3 emission) {
  Surface s;
  s.position = position;
  s.view = view;
  // Two-sided: flip the frame to the side of the triangle the camera sees (the face normal, so
  // silhouettes of closed objects keep their vertex normals).
  vec3 n = normalize(normal);
  float side = 1.0;
  if (dot(faceNormal, faceNormal) > 0.0 && dot(faceNormal, s.view) * dot(faceNormal, n) < 0.0) side = -1.0;
  n *= side;
  vec3 t, b;
  vertexTangentFrame(n, tangent, side, t, b);
  s.vertexNormal = n;
  s.vertexTangent = t;
  s.vertexBitangent = b;
  s.anisotropyRotation = m.alpha_rho.w;
  s.mappedNormal = mapped;
  setShadingNormal(s, mappedNormal(mapped, t, b, n));
  s.uv = uv;
  footprint.dNdx *= side;  // the seen side's, as the vertex normal
  footprint.dNdy *= side;
  s.footprint = footprint;
  s.ndf = int(m.f0_ndf.a + 0.5);
  s.alpha = m.alpha_rho.xy;
  s.rho = m.alpha_rho.z;
  s.f0 = m.f0_ndf.rgb;
  s.diffuse = m.diffuse_tiling.rgb;
  s.hasNormalMap = MATERIAL_NORMAL_MAP != 0;
  emission = m.emission.rgb;
#if MATERIAL_TEXTURES
  // The parameters at this point of the surface, before any method widens the lobe.
  TexturedParameters texel = texturedParameters(m, vertexUV, s.footprint.dVertexUVdx, s.footprint.dVertexUVdy,
                                                REFERENCE_PASS != 0);
  s.alpha = texel.alpha;
  s.f0 = texel.f0;
  s.diffuse = texel.diffuse;
  emission = texel.emission;
#endif
  return s;
}
