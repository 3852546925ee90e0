#pragma once
// Mean RMSE and flicker of methods over a built-in scene's camera path shortened to `frames`, at
// 160x90 against a 64-spp reference per frame: the small versions of docs/results.md's tables,
// measured with the accumulator of `glintlab animate` (TemporalAccumulator, tested through
// run_animate in tests/eval/test_animate.cpp).
#include <map>
#include <string>
#include <vector>

#include "eval/commands.hpp"
#include "gl_fixture.hpp"

namespace glintlab::test {

struct Measured {
  double rmse = 0;
  double flicker = 0;
};

inline std::map<std::string, Measured> measure_sequence(const std::string& builtin, int frames,
                                                        const std::vector<std::string>& ids) {
  SceneFixture f(load_scene("builtin:" + builtin));
  f.scene.path.frames = frames;
  const int w = 160, h = 90;
  std::map<std::string, TemporalAccumulator> sequences;
  for (int t = 0; t < frames; ++t) {
    const Camera camera = f.scene.path.at(f.scene.camera, t);
    ReferenceSettings settings;
    settings.spp = 64;
    settings.seed = t;
    const Frame reference = f.reference_at(camera, w, h, settings).mean;
    for (const auto& id : ids) {
      const auto& method = find_method(id);
      const Frame m = f.renderer->render(method, resolve_params(method, {}), camera, w, h);
      sequences[id].add_frame(m.total, reference.total);
    }
  }
  std::map<std::string, Measured> out;
  for (const auto& [id, sequence] : sequences) {
    const TemporalMetrics r = sequence.result(id);
    out[id] = {r.mean_rmse, r.flicker};
  }
  return out;
}

}  // namespace glintlab::test
