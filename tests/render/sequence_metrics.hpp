#pragma once
// Mean RMSE and flicker of methods over the first frames of a built-in scene's camera path, at
// 160x90 against a 64-spp reference per frame: the small versions of docs/results.md's tables.
#include <map>
#include <string>
#include <vector>

#include "core/metrics.hpp"
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
  std::map<std::string, FlickerAccumulator> flicker;
  std::map<std::string, Measured> out;
  for (int t = 0; t < frames; ++t) {
    const Camera camera = f.scene.path.at(f.scene.camera, t);
    ReferenceSettings settings;
    settings.spp = 64;
    settings.seed = t;
    const Frame reference = f.renderer->render_reference(camera, w, h, settings).mean;
    for (const auto& id : ids) {
      const auto& method = find_method(id);
      const Frame m = f.renderer->render(method, resolve_params(method, {}), camera, w, h);
      out[id].rmse += rmse(m.total, reference.total) / frames;
      flicker[id].add_frame(m.total, reference.total);
    }
  }
  for (auto& [id, acc] : flicker) out[id].flicker = acc.flicker();
  return out;
}

}  // namespace glintlab::test
