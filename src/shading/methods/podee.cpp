// Descriptor of `podee`: micro-specular highlights by reflection-vector selection and
// area-fraction weighting (Podee, Max, Iwasaki, Dobashi), with glintlab's extensions.
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

/// Default of `corner_lod`, chosen by measurement against the reference (docs/methods.md#podee).
constexpr float kPodeeCornerLodDefault = -16.0f;

MethodDescriptor podee_method() {
  return {
      .id = "podee",
      .title = "Podee et al. (micro-specular highlights: reflection space on the light plane)",
      .citation = "N. Podee, N. Max, K. Iwasaki, Y. Dobashi, Micro-specular-highlight real-time rendering",
      .summary = "The reflected rays through the pixel's four corners hit the light plane (through the light's "
                 "centre, normal towards it) in a quadrilateral, the pixel's reflection space. The direction to "
                 "its point closest to the light's centre is shaded and weighted by the fraction of the "
                 "reflection space that the projected light covers. Disk lights (the paper), sphere lights and "
                 "suns; glossy lobes by convolving the light with the lobe in the light plane. Quad and delta "
                 "lights are shaded as by `conventional`.",
      .params = {{"corners", 0, 0, 1,
                  "corner reflection vectors: attributes interpolated at the corners (exact) or first order "
                  "from screen-space derivatives",
                  {"interpolated", "derivatives"}},
                 {"origin", 0, 0, 1,
                  "rays start at the corners' surface points (exact for a flat mirror) or all at the pixel "
                  "centre (the paper's assumption)",
                  {"corners", "centre"}},
                 {"area", 0, 0, 2,
                  "covered fraction: exact (projected disk as an ellipse, clipped exactly), light as a circle "
                  "of equal area, or light and reflection space both as circles (a lens, closed form)",
                  {"exact", "circle", "lens"}},
                 {"glossy", 1, 0, 1,
                  "lobe extension: the light convolved with the material's lobe in the light plane (on), or "
                  "every material shaded as a mirror (off, the paper)",
                  {"off", "on"}},
                 {"lobe", 0, 0, 1,
                  "the lobe of the extension: the material's, or widened by the normal map's slope covariance "
                  "inside the pixel's footprint (LEAN), which the four filtered corner normals cannot see",
                  {"material", "lean"}},
                 {"corner_lod", kPodeeCornerLodDefault, -16, 0,
                  "mip levels finer than the pixel centre's at which the corners read the normal map: 0 "
                  "the centre's footprint (bumps smaller than the pixel are averaged away), -1 half of it, "
                  "..., -16 in effect the base level (bilinear)"}},
      .tables = {},
      .light_kinds_built = {"quad"},  // the light widened by the reflection space (podee/reflection_space_shading.glsl)
  };
}

GLINTLAB_REGISTER_METHOD(podee_method, 700);

}  // namespace glintlab
