// How long the procedural normal maps take to generate (Google Benchmark; `make bench-normal-maps`).
// Not a test: timings depend on the machine. `bumps` at the scene format's largest wave count and
// frequency (4096 waves, max_frequency = resolution / 2) by the row sums the generator uses and,
// where it finishes in reasonable time, by the wave-by-wave sum it replaced (the same normals;
// its cost grows as resolution^2 * waves, so larger sizes scale from the 256^2 time). `brushed`,
// `scratches` and `flakes` at their defaults from 1024^2 to 4096^2; a raw-normal EXR file read at
// 4096^2 (written to the temporary directory first, removed after).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "core/image.hpp"
#include "core/image_io.hpp"

#include "scene/normal_maps/bump_waves.hpp"
#include "scene/normal_maps/normal_map.hpp"

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

void brushed(benchmark::State& state) {  // the defaults: 512 waves up to resolution / 4
  const int resolution = static_cast<int>(state.range(0));
  for (auto _ : state)
    benchmark::DoNotOptimize(generate_brushed(resolution, 0.2f, 0.01f, 0.0f, 512, resolution / 4, 1).normals.data());
}

void scratches(benchmark::State& state) {  // the defaults: 300 scratches of a quarter tile
  ScratchParams p;
  p.resolution = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(generate_scratches(p).normals.data());
}

void flakes_defaults(benchmark::State& state) {  // 32 cells per edge, jitter 0.75, a third flat
  const int resolution = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(generate_flakes(resolution, 32, 0.2f, 1, 0.75f, 0.3f).normals.data());
}

void exr_file(benchmark::State& state) {  // float RGB, ZIP: what write_exr writes
  const int resolution = static_cast<int>(state.range(0));
  const auto path = std::filesystem::temp_directory_path() /
                    ("glintlab-bench-normals-" + std::to_string(::getpid()) + ".exr");
  const NormalMap map = generate_bumps(resolution, 0.3f, 256, 64, 1);
  Image image(resolution, resolution);
  for (int y = 0; y < resolution; ++y)
    for (int x = 0; x < resolution; ++x) image.at(x, y) = map.normals[static_cast<std::size_t>(y) * resolution + x];
  write_exr(path, {{"", &image}});
  for (auto _ : state) benchmark::DoNotOptimize(load_normal_map(path).normals.data());
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove(path);
}

// Generation runs on every hardware thread: wall clock, not this thread's CPU time.
BENCHMARK(bumps_scene_default)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(bumps)->Arg(256)->Arg(2048)->Arg(8192)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(bumps_wave_by_wave)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(brushed)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(scratches)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(flakes_defaults)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(exr_file)->Arg(512)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(flakes)->Args({512, 32})->Args({8192, 8192})->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace
}  // namespace glintlab

BENCHMARK_MAIN();
