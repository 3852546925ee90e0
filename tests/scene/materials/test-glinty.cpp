// Descriptor of `test-glinty`, a material kind added the way a contributor adds one (this file and
// its GLSL, here made by tests/render/test_material_kinds.cpp from shaders/materials/glinty.glsl
// with the kind's prefix renamed) but only to this test binary: a copy of `glinty` under a new name.
#include "scene/materials/material.hpp"

namespace glintlab {

MaterialKind glinty_material_kind();

namespace test {

MaterialKind test_glinty_material_kind() {
  MaterialKind kind = glinty_material_kind();
  kind.id = "test-glinty";
  kind.title = "Test: a copy of glinty";
  return kind;
}

GLINTLAB_REGISTER_MATERIAL_KIND(test_glinty_material_kind, 100000);  // after every built-in kind

}  // namespace test
}  // namespace glintlab
