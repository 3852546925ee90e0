// Ray queries alone (Embree through RayScene; no shading): camera rays, one through each pixel
// centre of a 640x360 film, and secondary rays, one cosine-distributed bounce off each camera hit,
// on every built-in scene (Google Benchmark; `make bench-rays`). `rays_per_s` counts every query,
// hit or miss; `/threads:1` runs in a one-thread TBB arena (a core's rate), `/threads:all` on every
// core (`per_core` divides by them). Issue 29's floor: 4 M camera and 2 M secondary rays per
// second per core. Not a test: timings depend on the machine.
#include <benchmark/benchmark.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <memory>
#include <random>
#include <string>
#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <vector>

#include "path/camera_rays.hpp"
#include "path/ray_scene.hpp"
#include "scene/scene_loader.hpp"

namespace glintlab {
namespace {

constexpr glm::ivec2 kFilm(640, 360);

struct RayLoad {
  std::vector<Ray> camera;
  std::vector<Ray> secondary;
  double camera_hit_share = 0.0;
};

// The camera's rays, and from each of their hits a bounce: cosine-distributed about the facet's
// normal on the side the ray came from, starting just off the surface.
RayLoad make_load(const Scene& scene, const RayScene& rays) {
  RayLoad load;
  const CameraRays camera(scene.camera, kFilm);
  for (int y = 0; y < kFilm.y; ++y)
    for (int x = 0; x < kFilm.x; ++x) {
      const RayDifferential r = camera.at({x + 0.5f, y + 0.5f});
      load.camera.push_back(Ray{.origin = r.origin, .direction = r.direction});
    }
  std::vector<RayHit> hits(load.camera.size());
  rays.intersect(load.camera, hits, RayCoherence::Coherent);
  std::mt19937 random(1);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i].hit()) continue;
    const SurfacePoint p = rays.surface(hits[i]);
    glm::vec3 n = p.geometric_normal;
    if (glm::dot(n, load.camera[i].direction) > 0.0f) n = -n;
    const glm::vec3 t = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const glm::vec3 b = glm::cross(n, t);
    const float r = std::sqrt(uniform(random)), phi = 6.2831853f * uniform(random);
    const glm::vec3 d = r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0f, 1.0f - r * r)) * n;
    load.secondary.push_back(Ray{.origin = p.position, .t_near = 1e-4f, .direction = glm::normalize(d)});
  }
  load.camera_hit_share = static_cast<double>(load.secondary.size()) / static_cast<double>(load.camera.size());
  return load;
}

void trace(benchmark::State& state, const RayScene& scene, const std::vector<Ray>& rays, RayCoherence coherence,
           int threads) {
  std::vector<RayHit> hits(rays.size());
  tbb::task_arena arena(threads);
  for (auto _ : state) {
    arena.execute([&] { scene.intersect(rays, hits, coherence); });
    benchmark::DoNotOptimize(hits.data());
  }
  const double count = static_cast<double>(rays.size());
  state.counters["rays_per_s"] = benchmark::Counter(count, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["per_core"] = benchmark::Counter(count / threads, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace
}  // namespace glintlab

int main(int argc, char** argv) {
  using namespace glintlab;
  benchmark::Initialize(&argc, argv);
  const int cores = tbb::info::default_concurrency();
  // Scenes and their loads live until the benchmarks have run.
  std::vector<std::unique_ptr<RayScene>> scenes;
  std::vector<std::unique_ptr<RayLoad>> loads;
  for (const BuiltinScene& builtin : builtin_scenes()) {
    const Scene scene = load_scene("builtin:" + builtin.name);
    const RayScene* rays = scenes.emplace_back(std::make_unique<RayScene>(scene)).get();
    const RayLoad* load = loads.emplace_back(std::make_unique<RayLoad>(make_load(scene, *rays))).get();
    for (int threads : {1, cores}) {
      const std::string suffix = threads == 1 ? "/threads:1" : "/threads:all";
      benchmark::RegisterBenchmark(("camera/" + builtin.name + suffix).c_str(),
                                   [rays, load, threads](benchmark::State& state) {
                                     trace(state, *rays, load->camera, RayCoherence::Coherent, threads);
                                     state.counters["hit_share"] = load->camera_hit_share;
                                   })
          ->Unit(benchmark::kMillisecond);
      if (!load->secondary.empty())
        benchmark::RegisterBenchmark(("secondary/" + builtin.name + suffix).c_str(),
                                     [rays, load, threads](benchmark::State& state) {
                                       trace(state, *rays, load->secondary, RayCoherence::Incoherent, threads);
                                     })
            ->Unit(benchmark::kMillisecond);
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
