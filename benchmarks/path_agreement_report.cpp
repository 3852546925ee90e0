// The path tracer against the raster reference on every built-in scene: the table of docs/results.md's
// section "The path tracer against the raster reference" (tools/results.py path-tracer, about two
// minutes on 2 cores; the prose is tools/results/templates/path-tracer.md). Per scene, at 96x54 and
// 64 samples per pixel with the raster reference's seeds: `path-unshadowed` (every shadow ray
// unblocked: the raster reference's light transport, traced) against `raster`, which must agree
// within their noise; then what the path tracer adds: shadows (`path` at --max-depth 1 against
// `raster`) and interreflection (`path` at --max-depth 4 against 1). Exits 1 when a scene disagrees.
// Not a test: the suite holds a few scenes to the same agreement (tests/render/test_path_reference.cpp).
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "core/cache_directory.hpp"
#include "core/flip.hpp"
#include "gl/context.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/reference_backend.hpp"
#include "render/renderer.hpp"
#include "render/shader_contract.hpp"
#include "scene/scene_loader.hpp"
#include "tables/registry.hpp"

namespace {

using namespace glintlab;

constexpr int kWidth = 96, kHeight = 54, kSpp = 64;

// Mean over pixels and channels.
double mean(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) sum += image.at(x, y).x + image.at(x, y).y + image.at(x, y).z;
  return sum / (3.0 * image.width() * image.height());
}

double rmse(const Image& a, const Image& b) {
  double sum = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      const glm::vec3 d = a.at(x, y) - b.at(x, y);
      sum += d.x * d.x + d.y * d.y + d.z * d.z;
    }
  return std::sqrt(sum / (3.0 * a.width() * a.height()));
}

}  // namespace

int main() {
  auto context = GlContext::create_headless();
  ShaderLibrary shaders(choose_driver_profile(*context));
  add_contract_sources(shaders);
  std::printf("device: %s; films %dx%d, %d samples per pixel\n\n", context->info().renderer.c_str(), kWidth, kHeight,
              kSpp);
  std::printf("| scene | unshadowed / raster energy | stated error (both) | unshadowed vs raster RMSE / raster noise | "
              "unshadowed vs raster HDR-FLIP | raster halves' HDR-FLIP | path vs raster HDR-FLIP (shadows) | "
              "path / raster energy (shadows) | 4 vertices / 1 (interreflection) |\n"
              "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  int agreeing = 0, scenes = 0;
  for (const BuiltinScene& builtin : builtin_scenes()) {
    const Scene scene = load_scene("builtin:" + builtin.name);
    GpuScene gpu(scene, TableCache(default_table_cache_directory()));
    Renderer renderer(shaders, gpu);
    auto reference = [&](const std::string& id, int max_depth) {
      const auto backend = make_reference_backend(id, {shaders, gpu, renderer});
      ReferenceSettings settings;
      settings.spp = kSpp;
      settings.max_depth = max_depth;
      return render_reference(*backend, scene.camera, kWidth, kHeight, settings);
    };
    const ReferenceFrame raster = reference("raster", 1), unshadowed = reference("path-unshadowed", 1);
    const ReferenceFrame direct = reference("path", 1), bounced = reference("path", 4);
    const double ratio = mean(unshadowed.mean.total) / mean(raster.mean.total);
    const double stated = std::hypot(raster.relative_energy_error(), unshadowed.relative_energy_error());
    const double noise_share = rmse(unshadowed.mean.total, raster.mean.total) / raster.noise_rmse();
    const bool agree = std::abs(ratio - 1.0) <= 2.0 * stated && noise_share < 1.0;
    agreeing += agree;
    ++scenes;
    // HDR-FLIP (core/flip.hpp) at the raster reference's exposures: the perceived difference, and
    // what the raster reference's two halves (its even and odd passes) show of its own noise.
    const double ppd = flip::default_pixels_per_degree();
    const flip::HdrReference perceived(raster.mean.total, ppd, flip::automatic_exposures(raster.mean.total));
    const double flip_unshadowed = flip::mean(perceived.error_map(unshadowed.mean.total));
    const double flip_shadows = flip::mean(perceived.error_map(direct.mean.total));
    const double flip_halves = flip::mean(
        flip::HdrReference(raster.odd_passes, ppd, perceived.exposures()).error_map(raster.even_passes));
    std::printf("| %s | %.4f | %.4f | %.3f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", builtin.name.c_str(), ratio, stated,
                noise_share, flip_unshadowed, flip_halves, flip_shadows, mean(direct.mean.total) / mean(raster.mean.total),
                mean(bounced.mean.total) / mean(direct.mean.total));
    std::fflush(stdout);
  }
  std::printf("\n%d of %d scenes: `path-unshadowed` within two stated energy errors of `raster` and its RMSE "
              "against it below the raster reference's noise.\n",
              agreeing, scenes);
  return agreeing == scenes ? 0 : 1;
}
