// Forward shading: builds the surface record once per fragment (derivatives in uniform control
// flow), then sums the method's (or the reference's) radiance over every light. The modules are
// chosen by the renderer through the $MATERIAL include (the material's kind behind the material
// interface, generated/materials/<kind>.glsl) and the $METHOD include; this pass never names a
// method or a kind. Variant defines (src/render/renderer.cpp, forward_variant): LIGHT_RANGES
// (lights/light_loop.glsl), MATERIAL_KIND (the kind's code: compare with MATERIAL_KIND_<ID>),
// MATERIAL_NORMAL_MAP (1 when the material has a normal map), MATERIAL_TEXTURES (1 when its
// parameters vary per texel), MATERIAL_ANISOTROPIC (1 when its smooth lobe can be anisotropic:
// lobe/lobe_shading.glsl), REFERENCE_PASS (1 for ground truth, which evaluates the surface
// itself at each sample: textures at their base level), REFERENCE_SURFACE (the surface a
// reference gives stochastic materials: REFERENCE_SURFACE_MODEL, _REALISATION or _FACETS).
#include "core/frame.glsl"
#include "core/fragment_inputs.glsl"
#include "lights/lights.glsl"
#if MATERIAL_TEXTURES
#include "core/material_textures.glsl"
#endif
#include "core/surface.glsl"
#include "$MATERIAL"
#include "$METHOD"
#include "lights/light_loop.glsl"

layout(location = 0) out vec4 outTotal;
layout(location = 1) out vec4 outSpecular;

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

void main() {
  MaterialData m = materials[uMaterial];
  vec2 uv = normalMapCoordinates(vUV);
  vec3 view = viewDirectionFrom(vPosition);
  // The footprint first, while control flow is uniform.
  Footprint footprint = screenSpaceFootprint(view, uv);
#if MATERIAL_NORMAL_MAP && REFERENCE_PASS
  // Ground truth takes the map at this sample point (bilinear at level 0), never an average over
  // a footprint: the normals a filtered level would average away are the highlights being judged.
  vec3 mapped = textureLod(uNormalMap, uv, 0.0).xyz;
#elif MATERIAL_NORMAL_MAP
  vec3 mapped = textureGrad(uNormalMap, uv, footprint.dUVdx, footprint.dUVdy).xyz;
#else
  vec3 mapped = vec3(0.0, 0.0, 1.0);
#endif

  Surface s;
  s.position = vPosition;
  s.view = view;
  // Two-sided: flip the frame to the side of the triangle the camera sees (face normal from
  // the position derivatives, so silhouettes of closed objects keep their vertex normals).
  vec3 faceNormal = cross(footprint.dPdx, footprint.dPdy);
  float faceLength = length(faceNormal);
  vec3 n = normalize(vNormal);
  float side = 1.0;
  if (faceLength > 0.0 && dot(faceNormal, s.view) * dot(faceNormal, n) < 0.0) side = -1.0;
  n *= side;
  vec3 t, b;
  vertexTangentFrame(n, vTangent, side, t, b);
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
  vec3 emission = m.emission.rgb;
#if MATERIAL_TEXTURES
  // The parameters at this point of the surface, before any method widens the lobe.
  TexturedParameters texel = texturedParameters(m, vUV, s.footprint.dVertexUVdx, s.footprint.dVertexUVdy,
                                                REFERENCE_PASS != 0);
  s.alpha = texel.alpha;
  s.f0 = texel.f0;
  s.diffuse = texel.diffuse;
  emission = texel.emission;
#endif

  prepareSurface(s);  // the method's per-pixel step (e.g. a filtered roughness), in uniform control flow
  Radiance sum = shadeAllLights(s);
  outTotal = vec4(sum.diffuse + sum.specular + emission, 1.0);
  outSpecular = vec4(sum.specular, 1.0);
}
