// Descriptor of `vlachos`: roughness floor from the normal's screen-space change (Vlachos 2015).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor vlachos_method() {
  return {
      .id = "vlachos",
      .title = "Vlachos (geometric roughness floor)",
      .citation = "A. Vlachos, Advanced VR Rendering, GDC 2015",
      .summary = "Clamps perceptual roughness sqrt(alpha) from below by "
                 "scale * max(|dn/dx|^2, |dn/dy|^2)^exponent, n the interpolated vertex normal: "
                 "curvature aliasing only; normal maps are left as they are.",
      .params = {{"scale", 1.0f, 0.0f, 4.0f, "gain of the roughness floor"},
                 {"exponent", 1.0f / 3.0f, 0.05f, 1.0f, "exponent of max(|dn/dx|^2, |dn/dy|^2) (1/3 in the talk)"},
                 area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(vlachos_method, 300);

}  // namespace glintlab
