#include "render/raster_reference.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <set>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "gl/context.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/pass_tiles.hpp"
#include "render/render_target.hpp"
#include "render/renderer.hpp"
#include "render/subpixel_filter.hpp"
#include "tables/registry.hpp"

namespace glintlab {

RasterReference::RasterReference(const ReferenceBackendContext& context, std::string id, std::string module)
    : shaders_(context.shaders), scene_(context.scene), renderer_(context.renderer), id_(std::move(id)),
      module_(std::move(module)) {}

std::uint64_t RasterReference::estimator_hash() const {
  if (estimator_hash_ != 0) return estimator_hash_;
  Hasher h;
  std::set<MaterialVariant> variants;
  for (const auto& mesh : scene_.meshes()) variants.insert(material_variant(scene_, mesh.material));
  for (const MaterialVariant& v : variants) {
    const ShaderDefines defines = forward_variant(module_, scene_.light_ranges(), v);
    h.text(shaders_.expand("passes/forward.vert", defines));
    h.text(shaders_.expand("passes/forward.frag", defines));
  }
  h.text(shaders_.expand("passes/emitter.frag", {}));
  hash_pass_inputs(h, shaders_, scene_);
  estimator_hash_ = h.digest();
  return estimator_hash_;
}

int RasterReference::tile_side(int subpixels, const PixelFilter& filter) {
  constexpr int kMaxTileSide = 2048;  // sub-pixels per side of one high-resolution tile, margins included
  return std::max(1, kMaxTileSide / subpixels - 2 * filter.support_pixels());
}

Frame RasterReference::render_pass(const Camera& camera, int width, int height, const ReferencePass& pass,
                                   const ProgressFn& progress) {
  const int k = pass.subpixels;
  if (k < 1 || k > 32) throw InputError("reference sub-pixels per axis " + std::to_string(k) + ": allowed: 1 .. 32");
  const FilmRegion wanted = pass.region.within(width, height);
  const int tile = tile_side(k, pass.filter);
  // The pixels around a tile whose samples its filter weights too (none for the box).
  const int margin = pass.filter.support_pixels();
  const std::vector<PassTile> tiles = pass_tiles({width, height}, wanted, tile, margin);

  RenderTarget high(std::min(width, tile + 2 * margin) * k, std::min(height, tile + 2 * margin) * k);
  PassFilm out(width, height);
  SubpixelFilter filter(shaders_, pass.filter);
  const glm::ivec2 film(width, height);
  int done = 0;
  for (const PassTile& t : tiles) {
    const glm::ivec2 high_size = t.region_size * k;
    // The rasteriser samples each sub-pixel at its centre; moving the image by (0.5 - jitter)
    // sub-pixels makes that centre see the point `jitter` from the cell's corner instead.
    const glm::vec2 shift_ndc = 2.0f * (glm::vec2(0.5f) - pass.jitter) / glm::vec2(high_size);
    const glm::mat4 projection = glm::translate(glm::mat4(1.0f), glm::vec3(shift_ndc, 0.0f)) *
                                 camera.tile_projection_matrix(film, t.region_origin, t.region_size);
    high.bind_and_clear(high_size.x, high_size.y);
    renderer_.draw_view(module_, {}, camera, projection, {high_size.x, high_size.y, k, 0},
                        {t.region_origin.x * k, t.region_gl_y * k, pass.light_samples,
                         static_cast<int>(pass.seed & 0x7fffffffu)});
    filter.reduce(high, t.samples(k, pass.jitter, height), out.total(), out.specular());
    glFinish();  // one tile at a time keeps progress honest and the driver's queue short
    check_gl("rendering a reference tile");
    if (progress) progress(++done, static_cast<int>(tiles.size()));
  }
  return out.read(wanted);
}

}  // namespace glintlab
