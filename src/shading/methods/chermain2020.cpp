// Descriptor of `chermain2020`: the procedural glinty BRDF (Chermain et al. 2020).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor chermain2020_method() {
  return {
      .id = "chermain2020",
      .title = "Chermain et al. 2020 (procedural physically based BRDF for real-time glints)",
      .citation = kChermain2020Citation,
      .summary = "A glinty material's slope distribution over the pixel's uv footprint: the cells of a virtual "
                 "MIP hierarchy inside the footprint ellipse (two levels blended), each a product of two 1D "
                 "marginals picked at random from a multiscale dictionary, randomly rotated and scaled to the "
                 "material's roughness; empty cells by relative area; V-cavity masking. Converges to the "
                 "anisotropic Beckmann NDF at large footprints. No slope correlation, no filtering of the half "
                 "vector: curved surfaces alias. Materials without glints are shaded as by conventional.",
      .params = {glint_lean_param(false), glint_light_extent_param()},
      .tables = {"glint-dictionary"},
      .material_kinds = {"glinty"},
  };
}

GLINTLAB_REGISTER_METHOD(chermain2020_method, 800);

}  // namespace glintlab
