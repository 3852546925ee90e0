// Descriptor of `chermain2021`: geometric glint anti-aliasing and slope correlation
// (Chermain et al. 2021) on the glinty BRDF of 2020.
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor chermain2021_method() {
  return {
      .id = "chermain2021",
      .title = "Chermain et al. 2021 (geometric glint anti-aliasing, slope correlation)",
      .citation = "X. Chermain, S. Lucas, B. Sauvage, J.-M. Dischler, C. Dachsbacher, Real-Time Geometric Glint "
                  "Anti-Aliasing with Normal Map Filtering, I3D 2021 (PACMCGIT 4(1)); on " +
                  std::string(kChermain2020Citation),
      .summary = "chermain2020 plus geometric glint anti-aliasing: the half vector's screen-space derivatives, "
                 "mapped by each cell's inverse transform, give a slope kernel that filters the cell's two "
                 "marginals (textureGrad over the dictionary's mip chain, mirrored repeat); and the slope "
                 "correlation rho in the transform M, so that LEAN mapping's anisotropic, rotated covariance "
                 "can be combined with the glints. Equals chermain2020 when rho = 0 and kernel = 0.",
      .params = {glint_lean_param(true),
                 {"kernel", 0.5f, 0.0f, 4.0f,
                  "s_K: the filter kernel's size in pixels of half-vector change (0.5: adjacent pixels' kernels "
                  "do not overlap; 1: less shimmering, more blur; 0: no anti-aliasing)"},
                 {"derivatives", 0, 0, 1,
                  "what is differentiated per pixel: the projected half vector h.xy (eq. 21, better at grazing "
                  "angles) or the half slope -h.xy / h.z (eq. 20)",
                  {"projected", "slopes"}},
                 glint_light_extent_param()},
      .tables = {"glint-dictionary"},
      .material_kinds = {"glinty"},
  };
}

GLINTLAB_REGISTER_METHOD(chermain2021_method, 810);

}  // namespace glintlab
