// How long the CP decomposition of one NDF block takes (Google Benchmark; one thread, CPU time).
// Not a test: timings depend on the machine. The data stand in for glinty NDFs: each of the K
// slices (positions) is 1 to 4 Gaussian lobes of 0.5 to 3.5 texels at random places in a 16 x 16
// block, independent across slices (harder than real footprints, whose neighbours share lobes).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "prefilter/cp_decomposition.hpp"

namespace glintlab {
namespace {

Tensor3 lobe_slices(int size, int slices, std::uint32_t seed) {
  Tensor3 x(size, size, slices);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int k = 0; k < slices; ++k) {
    const int lobes = 1 + static_cast<int>(rng() % 4);
    for (int l = 0; l < lobes; ++l) {
      const float ci = u(rng) * size, cj = u(rng) * size, sigma = 0.5f + 3.0f * u(rng), weight = u(rng);
      for (int i = 0; i < size; ++i)
        for (int j = 0; j < size; ++j) {
          const float di = i + 0.5f - ci, dj = j + 0.5f - cj;
          x.at(i, j, k) += weight * std::exp(-(di * di + dj * dj) / (2.0f * sigma * sigma));
        }
    }
  }
  return x;
}

// Args: slices K, rank, nonnegative (1: HALS, the default; 0: ALS). Ten different blocks in turn.
void decompose_block(benchmark::State& state) {
  std::vector<Tensor3> blocks;
  for (std::uint32_t seed = 1; seed <= 10; ++seed) blocks.push_back(lobe_slices(16, static_cast<int>(state.range(0)), seed));
  CpSettings settings;
  settings.rank = static_cast<int>(state.range(1));
  settings.nonnegative = state.range(2) != 0;
  double iterations = 0.0, error = 0.0, calls = 0.0;
  std::size_t next = 0;
  for (auto _ : state) {
    const CpFactors f = decompose(blocks[next], settings);
    next = (next + 1) % blocks.size();
    iterations += f.iterations;
    error += f.relative_error;
    calls += 1.0;
  }
  state.counters["sweeps"] = iterations / calls;
  state.counters["rel_error"] = error / calls;
}

BENCHMARK(decompose_block)
    ->ArgNames({"K", "rank", "nonneg"})
    ->Args({256, 16, 1})
    ->Args({256, 16, 0})
    ->Args({64, 16, 1})
    ->Args({1024, 16, 1})
    ->Args({256, 32, 1})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace
}  // namespace glintlab

BENCHMARK_MAIN();
