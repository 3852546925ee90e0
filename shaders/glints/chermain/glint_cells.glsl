// Diagnostics, not a method: the number of glint cells inside each pixel's footprint at the two
// levels the glinty BRDF blends (glints/chermain/ndf.glsl, without its guard of GLINT_MAX_CELLS per
// level), in the specular output: r = level floor(lod), g = level floor(lod) + 1, b = 1 for a
// glinty pixel. Each light adds its share, so the sum over the scene's lights is the count.
#include "glints/chermain/shading.glsl"

const ivec2 kGlintCellsLightRanges[LIGHT_KIND_COUNT] = LIGHT_RANGES;
vec3 gGlintCells = vec3(0.0);

void prepareSurface(inout Surface s) {
#if MATERIAL_KIND == MATERIAL_KIND_GLINTY
  GlintPatch fp = prepareGlints(s, materials[uMaterial], false, false).footprint;
  if (fp.level >= 0)
    gGlintCells = vec3(fp.level < GLINT_LEVELS ? glintCellCount(fp.fine) : 0,
                       fp.level + 1 < GLINT_LEVELS ? glintCellCount(fp.coarse) : 0, 1.0);
#endif
}

Radiance shadeLight(Surface s, LightData L) {
  return Radiance(vec3(0.0), gGlintCells / float(kGlintCellsLightRanges[LIGHT_KIND_COUNT - 1].y));
}
