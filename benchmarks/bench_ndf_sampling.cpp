// Evaluation and importance sampling of a footprint's NDF on the CPU (src/prefilter/ndf_sampling.hpp):
// deng2022's compressed pyramid and yan2016's element mixture against a GGX NDF's (the paper, sec.
// 6: evaluation +15% and sampling about 2x a microfacet BSDF's, offline). A 64^2 bumps map,
// sigma_r 0.03, 64^2 NDF pixels in 16^2 blocks, rank 16; footprints of 2 and 8 texels.
// `build/release/benchmarks/bench_ndf_sampling` (docs/methods.md#deng2022).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "prefilter/ndf_precompute.hpp"
#include "prefilter/ndf_sampling.hpp"
#include "tables/ltc/ltc_targets.hpp"

namespace {

using namespace glintlab;

const NormalMap& map() {
  static const NormalMap m = generate_bumps(64, 0.3f, 48, 8, 5);
  return m;
}

const PrefilteredNdf& pyramid() {
  static const PrefilteredNdf p = [] {
    PrefilterSettings s;
    s.ndf_resolution = 64;
    s.block_size = 16;
    s.base_stride = 1;
    return precompute_prefiltered_ndf(map(), 0.03, s);
  }();
  return p;
}

const PositionNormalDistribution& elements() {
  static const PositionNormalDistribution pnd(map(), 0.03, 2);
  return pnd;
}

struct Inputs {
  std::mt19937_64 rng{7};
  std::uniform_real_distribution<double> u{0.0, 1.0};
  glm::dvec3 next() { return {u(rng), u(rng), u(rng)}; }
};

void GgxEvaluate(benchmark::State& state) {
  Inputs in;
  for (auto _ : state) {
    const glm::dvec3 r = in.next();
    benchmark::DoNotOptimize(ggx_ndf(glm::normalize(glm::dvec3(r.x - 0.5, r.y - 0.5, 1.0)), 0.2));
  }
}
// D(h) cos(theta_h) sampled in closed form: tan^2 theta = alpha^2 u / (1 - u), phi = 2 pi u'.
void GgxSample(benchmark::State& state) {
  Inputs in;
  const double alpha = 0.2;
  for (auto _ : state) {
    const glm::dvec3 r = in.next();
    const double tan2 = alpha * alpha * r.x / (1.0 - r.x), cos_theta = 1.0 / std::sqrt(1.0 + tan2);
    const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta), phi = 6.283185307179586 * r.y;
    const glm::dvec3 h(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
    benchmark::DoNotOptimize(h);
    benchmark::DoNotOptimize(ggx_ndf(h, alpha) * cos_theta);  // the sample and its pdf
  }
}

void DengEvaluate(benchmark::State& state) {
  pyramid();  // precomputed before the clock starts
  Inputs in;
  const double sigma = static_cast<double>(state.range(0));
  for (auto _ : state) {
    const glm::dvec3 r = in.next();
    benchmark::DoNotOptimize(pyramid().density({64.0 * r.x, 64.0 * r.y}, sigma, {0.6 * r.z - 0.3, 0.1}));
  }
}
void DengSample(benchmark::State& state) {
  pyramid();  // precomputed before the clock starts
  Inputs in;
  const double sigma = static_cast<double>(state.range(0));
  for (auto _ : state) {
    const glm::dvec3 c = in.next();
    benchmark::DoNotOptimize(sample_prefiltered_ndf(pyramid(), {64.0 * c.x, 64.0 * c.y}, sigma, in.next()));
  }
}

void YanEvaluate(benchmark::State& state) {
  elements();
  Inputs in;
  const double sigma = static_cast<double>(state.range(0));
  for (auto _ : state) {
    const glm::dvec3 r = in.next();
    benchmark::DoNotOptimize(elements().density(Footprint::isotropic({64.0 * r.x, 64.0 * r.y}, sigma), {0.6 * r.z - 0.3, 0.1}));
  }
}
void YanSample(benchmark::State& state) {
  elements();
  Inputs in;
  const double sigma = static_cast<double>(state.range(0));
  for (auto _ : state) {
    const glm::dvec3 c = in.next();
    benchmark::DoNotOptimize(sample_position_normal(elements(), Footprint::isotropic({64.0 * c.x, 64.0 * c.y}, sigma), in.next()));
  }
}

}  // namespace

BENCHMARK(GgxEvaluate);
BENCHMARK(GgxSample);
BENCHMARK(DengEvaluate)->Arg(2)->Arg(8);
BENCHMARK(DengSample)->Arg(2)->Arg(8);
BENCHMARK(YanEvaluate)->Arg(2)->Arg(8);
BENCHMARK(YanSample)->Arg(2)->Arg(8);
BENCHMARK_MAIN();
