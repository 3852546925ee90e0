// Method `podee`: micro-specular highlights (Podee, Max, Iwasaki, Dobashi): the pixel's four
// corner reflection vectors span a reflection space on the light plane; the direction to its
// point closest to the light's centre is shaded and weighted by the fraction of the reflection
// space the light covers. Extended to sphere lights and suns, and to glossy lobes.
// Descriptor: src/shading/methods/podee.cpp; derivations: docs/methods.md#podee.
#include "lobe/lobe_shading.glsl"
#include "podee/pixel_corners.glsl"
#include "podee/reflection_space_shading.glsl"
#include "lobe/slope_moments.glsl"

CornerRays gCorners;  // this pixel's corner rays, set by prepareSurface
Lobe gLobe;           // this pixel's lobe, set by prepareSurface

void prepareSurface(inout Surface s) {
  // A branch on a uniform is uniform control flow, so the derivative variant may take its
  // derivatives inside it.
  if (param_corners == CORNERS_INTERPOLATED) gCorners = interpolatedCornerRays(s, param_corner_lod);
  else gCorners = derivativeCornerRays(s, param_corner_lod);
  if (param_origin == ORIGIN_CENTRE)
    for (int i = 0; i < 4; ++i) gCorners.origin[i] = s.position;
  gLobe = materialSmoothLobe(s);
#if MATERIAL_NORMAL_MAP
  // Normals that vary inside the footprint the corners read the map over are invisible to them,
  // but not to the footprint's slope moments: LEAN's frame and covariance, as `lean`.
  if (param_lobe == LOBE_LEAN) gLobe.A += 2.0 * leanShadingFrame(s);
#endif
}

Radiance shadeLight(Surface s, LightData L) {
  // The reflection space is measured against the light's disk form (disks, spheres, suns).
  if (lightHasDiskForm(L))
    return shadeReflectionSpace(s, L, gCorners, gLobe, ReflectionSpaceOptions(param_area, param_glossy == GLOSSY_ON));
  return shadeLobe(s, L, gLobe);  // delta lights and polygons: the baseline
}
