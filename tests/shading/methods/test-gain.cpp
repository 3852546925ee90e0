// Descriptor of `test-gain`, a method added the way a contributor adds one (this file and its
// module, test-gain.glsl) but only to test_method_registry: the glintlab binary never lists it.
// It shades as `conventional` times its parameter, so its images are known in advance; its
// enumeration `terms` reaches the module as an int, compared with the generated TERMS_* defines.
#include "shading/registry.hpp"

namespace glintlab::test {

MethodDescriptor test_gain_method() {
  return {
      .id = "test-gain",
      .title = "Test: conventional times a gain",
      .citation = "none (a test of the method registry)",
      .summary = "conventional's diffuse and specular radiance, each multiplied by `gain` (or the specular only).",
      .params = {{"gain", 1.0f, 0.0f, 4.0f, "factor on conventional's radiance"},
                 {"terms", 0, 0, 1, "the terms `gain` scales: both, or the specular only", {"both", "specular"}}},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(test_gain_method, 100000);  // after every built-in method

}  // namespace glintlab::test
