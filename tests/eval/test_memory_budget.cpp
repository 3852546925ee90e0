// The memory estimate made before a run allocates its films (src/eval/memory_budget.hpp).
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/error.hpp"
#include "eval/memory_budget.hpp"
#include "scene/normal_maps/normal_map.hpp"
#include "scene/scene.hpp"

using namespace glintlab;

namespace {

Scene sphere_scene() {
  Scene s;
  s.materials.emplace_back();
  s.shapes.push_back({"sphere", std::make_shared<Mesh>(make_sphere(1.0f, 64, 32)), glm::mat4(1.0f), 0});
  return s;
}

std::string error_of(const MemoryEstimate& need, const Workload& w, int width, int height, std::uint64_t available) {
  try {
    require_memory(need, w, width, height, available);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MemoryBudget, FilmsGrowWithPixelsMethodsAndTheReference) {
  const Scene scene = sphere_scene();
  const Workload one{.methods = 1}, eleven{.methods = 11, .reference = true, .outputs = true};
  const MemoryEstimate small = estimate_run_memory(one, 64, 64, scene);
  const MemoryEstimate big = estimate_run_memory(one, 128, 128, scene);
  EXPECT_EQ(big.film, 4 * small.film);
  EXPECT_EQ(big.scene, small.scene);
  EXPECT_GT(small.scene, 0u);
  // 3 spheres at 4096x4096 compared with every method (the std::bad_alloc): several GiB.
  const MemoryEstimate all = estimate_run_memory(eleven, 4096, 4096, scene);
  EXPECT_GT(all.per_pixel, 11u * 24u);  // at least every method's total and specular images
  EXPECT_GT(all.total(), 6ull << 30);
  EXPECT_LT(all.total(), 16ull << 30);
  Workload progressive = eleven;
  progressive.progressive = true;
  EXPECT_GE(estimate_run_memory(progressive, 4096, 4096, scene).film, all.film);
}

TEST(MemoryBudget, NormalMapsCountTheirUpload) {
  Scene scene = sphere_scene();
  const MemoryEstimate without = estimate_run_memory({}, 64, 64, scene);
  scene.materials[0].normal_map = std::make_shared<NormalMap>(generate_flakes(256, 4, 0.2f, 1));
  scene.materials.push_back(scene.materials[0]);  // a map shared by two materials is uploaded for each
  // A staging copy (RGBA and R float: 36 bytes a texel) and the GPU's mipmapped textures (4/3 of that).
  EXPECT_EQ(estimate_run_memory({}, 64, 64, scene).scene - without.scene, 2u * 256u * 256u * (36u + 48u));
}

TEST(MemoryBudget, TooLargeIsAnInputErrorSayingWhatWouldFit) {
  const Scene scene = sphere_scene();
  const Workload w{.methods = 11, .reference = true, .outputs = true};
  const MemoryEstimate need = estimate_run_memory(w, 4096, 4096, scene);
  EXPECT_EQ(error_of(need, w, 4096, 4096, need.total()), "");
  const std::string msg = error_of(need, w, 4096, 4096, need.total() - 1);
  for (const char* f : {"film 4096x4096 with 11 methods and a reference", "GiB", "available:", "--width/--height",
                        "method count"})
    EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
}

TEST(MemoryBudget, TheEnvironmentCapsWhatMayBeUsed) {
  ::setenv("GLINTLAB_MEMORY_MIB", "300", 1);
  EXPECT_EQ(available_memory(), std::optional<std::uint64_t>(300ull << 20));
  ::setenv("GLINTLAB_MEMORY_MIB", "lots", 1);
  EXPECT_THROW(available_memory(), InputError);
  ::unsetenv("GLINTLAB_MEMORY_MIB");
  const auto machine = available_memory();  // /proc/meminfo on Linux
  ASSERT_TRUE(machine.has_value());
  EXPECT_GT(*machine, 0u);
}
