#include <algorithm>
#include <chrono>
#include <epoxy/gl.h>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "eval/commands.hpp"
#include "gl/objects.hpp"

namespace glintlab {

namespace {
double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

std::vector<BenchResult> run_bench(Session& session, const std::vector<MethodChoice>& methods, int frames, int warmup,
                                   const std::filesystem::path& out) {
  std::vector<BenchResult> results;
  const Camera camera = session.camera(0);
  gl::Query query = gl::make_query(GL_TIME_ELAPSED);
  for (const auto& m : methods) {
    for (int i = 0; i < warmup; ++i) session.renderer().draw(*m.method, m.params, camera, session.width(), session.height());
    glFinish();
    std::vector<double> gpu, wall;
    for (int i = 0; i < frames; ++i) {
      const auto t0 = std::chrono::steady_clock::now();
      glBeginQuery(GL_TIME_ELAPSED, query.id());
      session.renderer().draw(*m.method, m.params, camera, session.width(), session.height());
      glEndQuery(GL_TIME_ELAPSED);
      glFinish();
      const auto t1 = std::chrono::steady_clock::now();
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &ns);
      gpu.push_back(static_cast<double>(ns) * 1e-6);
      wall.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    results.push_back({m.method->id, median(gpu), median(wall), frames});
  }
  nlohmann::json json;
  json["scene"] = session.scene().source;
  json["width"] = session.width();
  json["height"] = session.height();
  json["device"] = session.context().info().renderer;
  json["frames"] = frames;
  json["warmup"] = warmup;
  for (const auto& r : results)
    json["methods"].push_back({{"method", r.method}, {"gpu_ms_median", r.gpu_ms_median}, {"wall_ms_median", r.wall_ms_median}});
  std::cout << json.dump(2) << "\n";
  if (!out.empty()) write_text_file(out / "bench.json", json.dump(2) + "\n");
  return results;
}

}  // namespace glintlab
