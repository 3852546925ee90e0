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
#include "core/surface_record.glsl"
#include "$MATERIAL"
#include "$METHOD"
#include "lights/light_loop.glsl"

layout(location = 0) out vec4 outTotal;
layout(location = 1) out vec4 outSpecular;

void main() {
  MaterialData m = materials[uMaterial];
  vec2 uv = normalMapCoordinates(vUV);
  vec3 view = viewDirectionFrom(vPosition);
  // The footprint first, while control flow is uniform.
  Footprint footprint = screenSpaceFootprint(view, uv);
  vec3 mapped = normalMapValue(uv, footprint.dUVdx, footprint.dUVdy);

  // The face normal from the position derivatives.
  vec3 emission;
  Surface s = surfaceRecord(m, vPosition, vNormal, vTangent, vUV, uv, view, cross(footprint.dPdx, footprint.dPdy),
                            footprint, mapped, emission);

  prepareSurface(s);  // the method's per-pixel step (e.g. a filtered roughness), in uniform control flow
  Radiance sum = shadeAllLights(s);
  outTotal = vec4(sum.diffuse + sum.specular + emission, 1.0);
  outSpecular = vec4(sum.specular, 1.0);
}
