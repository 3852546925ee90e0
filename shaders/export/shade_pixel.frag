// An exported method (`glintlab export`, docs/export.md): the forward pass's shading of one pixel
// (passes/forward.frag) as a function an engine calls, for one light of the kind the export was
// made for. The exporter expands it in a method's, a material kind's and a light kind's variant,
// with its parameters as constants, and defines EXPORTED_SHADER, EXPORTED_LIGHT_KIND (the kind's
// code) and EXPORTED_LIGHT_COMPACT (0 for an environment). main() below, an example that shades a
// mesh's fragments with material 0 and light 0 of the blocks, is left out with GLINTLAB_NO_MAIN.
#define TEXTURE_TRANSFORM_BLOCK_BINDING 3
#include "core/frame.glsl"
#include "core/fragment_inputs.glsl"
#include "lights/lights.glsl"
#include "core/surface_record.glsl"
#include "$MATERIAL"
#include "$METHOD"
#include "lights/light_loop.glsl"

struct GlintlabRadiance {
  vec3 diffuse;
  vec3 specular;
  vec3 emission;  // the material's own, once per pixel (not per light)
};

// Shades the pixel of a fragment shader invocation: the surface point's interpolated world-space
// position, normal, tangent (w: the bitangent's sign) and texture coordinates, the index of its
// material in MaterialBlock (methods read per-material data by it), and one light of the exported
// kind lighting it. Call in uniform control flow (it takes screen-space
// derivatives of its inputs: the pixel's footprint); the camera is the FrameBlock's.
GlintlabRadiance glintlabShade(int material, vec3 position, vec3 normal, vec4 tangent, vec2 texcoord,
                               LightData light) {
  uMaterial = material;
  MaterialData m = materials[material];
  vPosition = position;
  vNormal = normal;
  vTangent = tangent;
  vUV = texcoord;
  vec2 uv = normalMapCoordinates(vUV);
  vec3 view = viewDirectionFrom(vPosition);
  Footprint footprint = screenSpaceFootprint(view, uv);
  vec3 mapped = normalMapValue(uv, footprint.dUVdx, footprint.dUVdy);
  vec3 emission;
  Surface s = surfaceRecord(m, vPosition, vNormal, vTangent, vUV, uv, view, cross(footprint.dPdx, footprint.dPdy),
                            footprint, mapped, emission);
  prepareSurface(s);
  light.colour_type.a = float(EXPORTED_LIGHT_KIND);  // a constant: the light dispatch folds to the kind
#if EXPORTED_LIGHT_COMPACT
  Radiance r = shadeLight(s, light);
#else
  Radiance r = shadeEnvironmentLight(s, light);
#endif
  return GlintlabRadiance(r.diffuse, r.specular, emission);
}

#ifndef GLINTLAB_NO_MAIN
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inTexcoord;
layout(location = 0) out vec4 outTotal;
layout(location = 1) out vec4 outSpecular;

void main() {
  GlintlabRadiance r = glintlabShade(0, inPosition, inNormal, inTangent, inTexcoord, lights[0]);
  outTotal = vec4(r.diffuse + r.specular + r.emission, 1.0);
  outSpecular = vec4(r.specular, 1.0);
}
#endif
