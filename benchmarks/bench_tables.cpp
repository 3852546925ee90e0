// How long each precomputed table takes to generate and to load from the cache (Google
// Benchmark; `make bench-tables`). Not a test: timings depend on the machine. Needs no GL context
// (upload time is what `glintlab info` reports). The cache is a temporary directory, removed
// afterwards.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "tables/registry.hpp"
#include "tables/table_cache.hpp"

namespace glintlab {
namespace {

void set_size_counters(benchmark::State& state, const Table& table) {
  state.counters["values_bytes"] = static_cast<double>(table.source.value_count * sizeof(float));
  state.counters["gpu_bytes"] = static_cast<double>(table.gpu_bytes.base);
  state.counters["gpu_bytes_with_mips"] = static_cast<double>(table.gpu_bytes.with_mips);
}

void generate(benchmark::State& state, const Table& table) {
  for (auto _ : state) benchmark::DoNotOptimize(table.source.generate({}));
  set_size_counters(state, table);
}

void load(benchmark::State& state, const Table& table, const std::filesystem::path& cache_dir) {
  const TableCache cache(cache_dir);
  (void)cache.load_or_generate(table.source);  // the entry the loop reads
  for (auto _ : state) {
    BuiltTable t = cache.load_or_generate(table.source);
    if (t.build.generated) state.SkipWithError("the cache entry was not read");
    benchmark::DoNotOptimize(t.values.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * table.source.value_count * sizeof(float)));
  set_size_counters(state, table);
}

}  // namespace
}  // namespace glintlab

int main(int argc, char** argv) {
  using namespace glintlab;
  std::string pattern = (std::filesystem::temp_directory_path() / "glintlab-bench-tables-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary directory");
  const std::filesystem::path cache_dir = pattern;
  for (const Table& table : all_tables()) {
    // Generation runs on every hardware thread: wall clock, not this thread's CPU time.
    benchmark::RegisterBenchmark(("generate/" + table.source.id).c_str(), generate, std::cref(table))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(("load_from_cache/" + table.source.id).c_str(), load, std::cref(table), cache_dir)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::filesystem::remove_all(cache_dir);
  return 0;
}
