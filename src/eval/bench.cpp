#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "eval/commands.hpp"
#include "eval/outputs.hpp"
#include "gl/gpu_timer.hpp"

namespace glintlab {

namespace {
constexpr const char* kUnshaded = "(unshaded)";

/// The floor taken apart: the same unshaded frame into cheaper colour targets. What the default
/// floor costs over the depth-only one is the colour targets' bandwidth; over nothing, the vertex
/// work, rasterisation and the fragment shader's surface record.
struct FloorLayout {
  const char* name;
  TargetLayout layout;
};
constexpr FloorLayout kFloorLayouts[] = {
    {"(unshaded, two RGBA16F targets)", {GL_RGBA16F, 2}},
    {"(unshaded, one RGBA32F target)", {GL_RGBA32F, 1}},
    {"(unshaded, depth only)", {GL_RGBA32F, 0}},
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

std::vector<BenchResult> run_bench(Session& session, const std::vector<MethodChoice>& methods, int frames, int warmup,
                                   const std::filesystem::path& out, bool floor_breakdown) {
  const Camera camera = session.camera(0);
  GpuTimer timer;
  // The methods, then the fixed cost of a frame: the same draws with a module that shades nothing
  // (and with --floor-breakdown, into each of kFloorLayouts).
  std::vector<RenderTarget> floors;
  if (floor_breakdown)
    for (const auto& f : kFloorLayouts) floors.emplace_back(session.width(), session.height(), f.layout);
  const std::size_t count = methods.size() + 1 + floors.size();
  auto draw = [&](std::size_t k) {
    if (k < methods.size())
      session.renderer().draw(*methods[k].method, methods[k].params, camera, session.width(), session.height());
    else if (k == methods.size())
      session.renderer().draw_module("passes/unshaded.glsl", {}, camera, session.width(), session.height());
    else
      session.renderer().draw_module("passes/unshaded.glsl", {}, camera, floors[k - methods.size() - 1]);
  };
  auto name = [&](std::size_t k) -> std::string {
    if (k < methods.size()) return methods[k].display_name();
    return k == methods.size() ? kUnshaded : kFloorLayouts[k - methods.size() - 1].name;
  };
  // At least one untimed frame each, even with --warmup 0: the first draw compiles the programs,
  // and llvmpipe's time query around a context's first draws reports hours.
  for (std::size_t k = 0; k < count; ++k)
    for (int i = 0; i < std::max(warmup, 1); ++i) draw(k);
  finish_gl_work();
  // Methods take turns frame by frame, so that drift of the machine's speed affects them alike
  // and the ratios between them are fair.
  std::vector<std::vector<double>> gpu(count), wall(count);
  for (int i = 0; i < frames; ++i)
    for (std::size_t k = 0; k < count; ++k) {
      const GpuTime time = timer.time([&] { draw(k); });
      gpu[k].push_back(time.gpu_ms);
      wall[k].push_back(time.wall_ms);
    }
  std::vector<BenchResult> results;
  for (std::size_t k = 0; k < count; ++k)
    results.push_back({name(k), median(gpu[k]), median(wall[k]), frames});
  nlohmann::json json = run_metadata(session);
  json["frames"] = frames;
  json["warmup"] = warmup;
  json["unshaded_definition"] = std::string(kUnshaded) +
                                ": the same frame with a shading module that returns nothing (clears, vertices, "
                                "rasterisation, surface record, two RGBA32F colour targets): the floor under every "
                                "method";
  json["ratio_definition"] = "median time of the method / median time of the first method listed";
  for (const auto& r : results)
    json["methods"].push_back({{"method", r.method},
                               {"gpu_ms_median", r.gpu_ms_median},
                               {"wall_ms_median", r.wall_ms_median},
                               {"gpu_ratio", r.gpu_ms_median / std::max(results.front().gpu_ms_median, 1e-9)},
                               {"wall_ratio", r.wall_ms_median / std::max(results.front().wall_ms_median, 1e-9)}});
  std::cout << json.dump(2) << "\n";
  if (!out.empty()) write_text_file(out / "bench.json", json.dump(2) + "\n");
  return results;
}

}  // namespace glintlab
