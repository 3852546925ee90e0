// Descriptor of `tokuyoshi`: projected-space NDF filtering (Tokuyoshi & Kaplanyan 2019, 2021).
#include "core/pixel_filter_width.hpp"
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor tokuyoshi_method() {
  return {
      .id = "tokuyoshi",
      .title = "Tokuyoshi & Kaplanyan (projected-space NDF filtering)",
      .citation = "Y. Tokuyoshi, A. S. Kaplanyan, Improved Geometric Specular Antialiasing, I3D 2019; "
                  "Stable Geometric Specular Antialiasing with Projected-Space NDF Filtering, JCGT 10(2), 2021",
      .summary = "Filters in the projected space of the half vector, where GGX's roughness is "
                 "beta^2 = alpha^2 / (1 - alpha^2): kernel K = 2 sigma2 J J^T from the derivatives J of the "
                 "projected half vector (towards the light's centre), scaled down to at most kappa, "
                 "P = diag(beta^2) + K, and back with A = (P + det(P) I) / (1 + tr(P) + det(P)). "
                 "Beckmann materials add K to alpha^2.",
      .params = {{"sigma2", kPixelFilterSigma * kPixelFilterSigma, 0.0f, 1.0f,
                  "variance of the Gaussian pixel filter in pixels^2 (default " + pixel_filter_variance_text() +
                      ": the square of glintlab's one pixel-filter width, as I3D 2019; 1/(4 pi) reproduces "
                      "JCGT 2021's gain)"},
                 {"kappa", 0.18f, 0.0f, 1.0f, "clamp of the kernel's largest eigenvalue"},
                 area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(tokuyoshi_method, 500);

}  // namespace glintlab
