// Descriptor of `toksvig`: roughness from the length of the mip-filtered normal (Toksvig 2005).
#include "shading/methods/shared_params.hpp"
#include "shading/registry.hpp"

namespace glintlab {

MethodDescriptor toksvig_method() {
  return {
      .id = "toksvig",
      .title = "Toksvig (filtered normal length)",
      .citation = "M. Toksvig, Mipmapping Normal Maps, journal of graphics tools 10(3), 2005",
      .summary = "Widens the lobe by the spread of the normal map's normals inside the texture footprint, "
                 "read from the length N of the trilinearly filtered, unnormalised normal: "
                 "beta'^2 = beta^2 + 2 (1 - N) / N with beta^2 = alpha^2 / (1 - alpha^2). "
                 "Without a normal map it equals conventional.",
      .params = {area_lights_param()},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(toksvig_method, 200);

}  // namespace glintlab
