// Descriptor of `lean`: LEAN mapping (Olano & Baker 2010).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor lean_method() {
  return {
      .id = "lean",
      .title = "LEAN mapping",
      .citation = "M. Olano, D. Baker, LEAN Mapping, I3D 2010",
      .summary = "The normal map's slope moments B = E[n.xy / n.z] and M = E[B B^T], mipmapped by plain "
                 "averaging, give per pixel the mean normal and the slope covariance Sigma = M - B B^T "
                 "(correlation included); the lobe's roughness matrix is diag(alpha^2) + 2 J Sigma J^T, an "
                 "anisotropic, rotated lobe about the mean normal (J: base slopes to the mean normal's slopes). Without a normal map it equals conventional.",
      .params = {area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(lean_method, 600);

}  // namespace glintlab
