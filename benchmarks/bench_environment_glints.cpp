// What kneiphof2025 recomputes when the environment changes (docs/methods.md#kneiphof2025): the
// luminance levels and tent weights of the map, and the weights' GGX-prefiltered chain (the same
// prefilter as the radiance's split-sum chain, on the CPU), for the procedural studio map.
#include <benchmark/benchmark.h>

#include "scene/lights/environment_glint_levels.hpp"
#include "scene/lights/environment_prefilter.hpp"
#include "scene/lights/environment_studio.hpp"

namespace {

using namespace glintlab;

void BM_GlintLevelsAndWeights(benchmark::State& state) {
  const EnvironmentMap map = studio_environment_map();
  for (auto _ : state) benchmark::DoNotOptimize(environment_glint_levels(map.radiance));
  state.counters["texels"] = static_cast<double>(map.radiance.pixel_count());
}
BENCHMARK(BM_GlintLevelsAndWeights)->Unit(benchmark::kMillisecond);

void BM_PrefilterGlintWeights(benchmark::State& state) {
  const EnvironmentMap map = studio_environment_map();
  const Image weights = environment_glint_levels(map.radiance).weights;
  for (auto _ : state) benchmark::DoNotOptimize(prefilter_environment_specular(weights));
}
BENCHMARK(BM_PrefilterGlintWeights)->Unit(benchmark::kMillisecond);

// The radiance's own chain, for scale: the weights cost the same.
void BM_PrefilterRadiance(benchmark::State& state) {
  const EnvironmentMap map = studio_environment_map();
  for (auto _ : state) benchmark::DoNotOptimize(prefilter_environment_specular(map.radiance));
}
BENCHMARK(BM_PrefilterRadiance)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
