#pragma once
// The forward programs that Images/EveryMethodOnBuiltinScene (tests/render/test_images.cpp)
// compiles: every method's module at its defaults, and the reference's, in each material variant
// of a built-in scene, specialised on that scene's light kinds. Shaders.EveryMethodAndPassCompiles*
// (tests/gl/test_shaders.cpp) compile the rest, so that every (module, material variant, light
// kind) is compiled somewhere in the suite, and once: compiling is most of both tests' time on
// llvmpipe, and the two never compile the same program (the light ranges differ).
#include <map>
#include <set>

#include "gl_fixture.hpp"

namespace glintlab::test {

/// Each material variant of the built-in scenes, with the light kinds (indices into
/// all_light_kinds()) of the scenes that have it.
inline const std::map<MaterialVariant, std::set<int>>& builtin_scene_light_kinds() {
  static const std::map<MaterialVariant, std::set<int>> kinds = [] {
    std::map<MaterialVariant, std::set<int>> out;
    for (const auto& b : builtin_scenes()) {
      const Scene scene = load_scene("builtin:" + b.name);
      const GpuScene gpu(scene, test_table_cache());
      std::set<int> present;
      for (int k = 0; k < static_cast<int>(gpu.light_ranges().size()); ++k)
        if (gpu.light_ranges()[k].x < gpu.light_ranges()[k].y) present.insert(k);
      for (const auto& mesh : gpu.meshes()) out[material_variant(gpu, mesh.material)].insert(present.begin(), present.end());
    }
    return out;
  }();
  return kinds;
}

}  // namespace glintlab::test
