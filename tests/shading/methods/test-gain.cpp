// Descriptor of `test-gain`, a method added the way a contributor adds one (this file and its
// module, test-gain.glsl) but only to test_method_registry: the glintlab binary never lists it.
// It shades as `conventional` times its parameter, so its images are known in advance.
#include "shading/registry.hpp"

namespace glintlab::test {

MethodDescriptor test_gain_method() {
  return {
      .id = "test-gain",
      .title = "Test: conventional times a gain",
      .citation = "none (a test of the method registry)",
      .summary = "conventional's diffuse and specular radiance, each multiplied by `gain`.",
      .params = {{"gain", 1.0f, 0.0f, 4.0f, "factor on conventional's radiance"}},
      .tables = {},
  };
}

GLINTLAB_REGISTER_METHOD(test_gain_method, 100000);  // after every built-in method

}  // namespace glintlab::test
