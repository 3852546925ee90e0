#pragma once
// The forward programs that Images/EveryMethodOnBuiltinScene (tests/render/test_images.cpp)
// compiles: every method's module at its defaults, and the reference's, in each material variant
// of the built-in scenes, with each light kind a scene of that variant has. Shaders.EveryMethodAndPassCompiles*
// (tests/glsl/test_shaders.cpp) compile the rest, so that every (module, material variant, light
// kind) is compiled somewhere in the suite, and once: compiling is most of both tests' time on
// llvmpipe, and the two never compile the same program (the light ranges differ).
#include <map>
#include <set>

#include "gl_fixture.hpp"

namespace glintlab::test {

/// Each built-in scene's programs as (material variant, light kind) pairs: every material
/// variant of the scene with each light kind (index into all_light_kinds()) it has.
using ProgramPairs = std::set<std::pair<MaterialVariant, int>>;
inline const std::map<std::string, ProgramPairs>& builtin_scene_program_pairs() {
  static const std::map<std::string, ProgramPairs> pairs = [] {
    std::map<std::string, ProgramPairs> out;
    context();  // GpuScene uploads to the GL
    for (const auto& b : builtin_scenes()) {
      const Scene scene = load_scene("builtin:" + b.name);
      const GpuScene gpu(scene, test_table_cache());
      ProgramPairs& p = out[b.name];
      for (int k = 0; k < static_cast<int>(gpu.light_ranges().size()); ++k)
        if (gpu.light_ranges()[k].x < gpu.light_ranges()[k].y)
          for (const auto& mesh : gpu.meshes()) p.insert({material_variant(gpu, mesh.material), k});
    }
    return out;
  }();
  return pairs;
}

/// A material kind, textured or not: what the scenes every method renders on must hold between
/// them. A kind's normal-mapped twin need not be drawn by every method: the lobe methods draw it in
/// their own tests, and every module is validated in it (Shaders.EveryMethodAndPassCompiles*).
inline std::pair<int, bool> kind_and_textures(const MaterialVariant& v) { return {v.kind, v.textures}; }

/// The built-in scenes Images/EveryMethodOnBuiltinScene renders every method on: few whose
/// materials hold every material kind (textured or not) of the built-in scenes (greedy: each step
/// the scene adding the most, then with the most (variant, light kind) pairs, the first in
/// builtin_scenes() order on ties). Drawing is what makes llvmpipe build a program's machine code,
/// seconds a program, most of the suite's time: so each method renders finite on every material
/// kind, the other scenes render `conventional` and the reference, and
/// Shaders.EveryMethodAndPassCompiles* validate (glslang) the variants and light kinds these scenes
/// leave out. The default scene (what `make demo` shows) is added to them: it holds every material
/// kind but textures under other lights than the chosen scenes', so the cover is chosen without it.
inline const std::set<std::string>& every_method_scenes() {
  static const std::set<std::string> chosen = [] {
    std::set<std::pair<int, bool>> missing;
    for (const auto& [scene, pairs] : builtin_scene_program_pairs())
      for (const auto& p : pairs) missing.insert(kind_and_textures(p.first));
    std::set<std::string> out;
    while (!missing.empty()) {
      std::string best;
      std::pair<std::size_t, std::size_t> best_gain{0, 0};  // kinds added, then pairs
      for (const auto& b : builtin_scenes()) {
        if ("builtin:" + b.name == kDefaultScene) continue;
        std::set<std::pair<int, bool>> added;
        for (const auto& p : builtin_scene_program_pairs().at(b.name))
          if (missing.contains(kind_and_textures(p.first))) added.insert(kind_and_textures(p.first));
        const std::pair<std::size_t, std::size_t> gain{added.size(), builtin_scene_program_pairs().at(b.name).size()};
        if (gain.first > 0 && gain > best_gain) best = b.name, best_gain = gain;
      }
      out.insert(best);
      for (const auto& p : builtin_scene_program_pairs().at(best)) missing.erase(kind_and_textures(p.first));
    }
    out.insert(std::string(kDefaultScene).substr(std::string("builtin:").size()));
    return out;
  }();
  return chosen;
}

/// Each material variant of the scenes every method renders on, with their light kinds: what
/// Images/EveryMethodOnBuiltinScene compiles by drawing.
inline const std::map<MaterialVariant, std::set<int>>& builtin_scene_light_kinds() {
  static const std::map<MaterialVariant, std::set<int>> kinds = [] {
    std::map<MaterialVariant, std::set<int>> out;
    for (const auto& scene : every_method_scenes())
      for (const auto& [variant, kind] : builtin_scene_program_pairs().at(scene)) out[variant].insert(kind);
    return out;
  }();
  return kinds;
}

}  // namespace glintlab::test
