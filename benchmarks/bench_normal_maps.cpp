// How long the procedural normal maps take to generate (Google Benchmark; `make bench-normal-maps`).
// Not a test: timings depend on the machine. `bumps` at the scene format's largest wave count and
// frequency (4096 waves, max_frequency = resolution / 2) by the row sums the generator uses and,
// where it finishes in reasonable time, by the wave-by-wave sum it replaced (the same normals;
// its cost grows as resolution^2 * waves, so larger sizes scale from the 256^2 time).
#include <benchmark/benchmark.h>

#include "scene/bump_waves.hpp"
#include "scene/normal_map.hpp"

namespace glintlab {
namespace {

constexpr int kMaxWaves = 4096;

void bumps(benchmark::State& state) {
  const int resolution = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(generate_bumps(resolution, 0.3f, kMaxWaves, resolution / 2, 1).normals.data());
  state.counters["texels"] = static_cast<double>(resolution) * resolution;
}

void bumps_wave_by_wave(benchmark::State& state) {
  const int resolution = static_cast<int>(state.range(0));
  const BumpSpectrum spectrum = choose_bump_waves(0.3f, kMaxWaves, resolution / 2, 1, 1.0f, 0.0f);
  for (auto _ : state) benchmark::DoNotOptimize(bump_normals_per_wave(spectrum, resolution).data());
  state.counters["texels"] = static_cast<double>(resolution) * resolution;
}

void bumps_scene_default(benchmark::State& state) {  // the scene format's defaults: 512^2, 128 waves
  for (auto _ : state) benchmark::DoNotOptimize(generate_bumps(512, 0.3f, 128, 24, 1).normals.data());
}

void flakes(benchmark::State& state) {
  const int resolution = static_cast<int>(state.range(0)), cells = static_cast<int>(state.range(1));
  for (auto _ : state) benchmark::DoNotOptimize(generate_flakes(resolution, cells, 0.2f, 1).normals.data());
}

// Generation runs on every hardware thread: wall clock, not this thread's CPU time.
BENCHMARK(bumps_scene_default)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(bumps)->Arg(256)->Arg(2048)->Arg(8192)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(bumps_wave_by_wave)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(flakes)->Args({512, 32})->Args({8192, 8192})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
}  // namespace glintlab

BENCHMARK_MAIN();
