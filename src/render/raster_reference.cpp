#include "render/raster_reference.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <set>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "gl/context.hpp"
#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
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
  h.text(shaders_.expand("passes/downsample.comp", {}));
  h.text(shaders_.expand("passes/filter_gaussian.comp", {}));
  // The resources the reference reads (the scene's kinds'): a new table generator version or
  // settings, or another environment map, is a new reference.
  for (const auto& id : scene_.scene_resource_ids()) {
    h.text(id);
    h.text(find_resource_type(id).key(scene_.resource_context()));
  }
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
  const int tiles_x = (wanted.width + tile - 1) / tile, tiles_y = (wanted.height + tile - 1) / tile;
  // The pixels around a tile whose samples its filter weights too (none for the box).
  const int margin = pass.filter.support_pixels();

  RenderTarget high(std::min(width, tile + 2 * margin) * k, std::min(height, tile + 2 * margin) * k);
  gl::Texture out_total = gl::make_texture(GL_TEXTURE_2D), out_specular = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(out_total.id(), 1, GL_RGBA32F, width, height);
  glTextureStorage2D(out_specular.id(), 1, GL_RGBA32F, width, height);

  SubpixelFilter filter(shaders_, pass.filter);
  const glm::ivec2 film(width, height);
  int done = 0;
  for (int ty = 0; ty < tiles_y; ++ty)
    for (int tx = 0; tx < tiles_x; ++tx) {
      // Tile in output pixels, y down (film convention), and the region rendered for it: the
      // tile and its margin inside the film (beyond the wanted region too: the filter sees the
      // same samples as in the whole film's pass).
      const glm::ivec2 origin(wanted.x + tx * tile, wanted.y + ty * tile);
      const glm::ivec2 size(std::min(tile, wanted.x + wanted.width - origin.x),
                            std::min(tile, wanted.y + wanted.height - origin.y));
      const glm::ivec2 region_origin = glm::max(origin - margin, glm::ivec2(0));
      const glm::ivec2 region_size = glm::min(origin + size + margin, film) - region_origin;
      const int gl_y = height - origin.y - size.y;  // the same tile in GL's y-up pixel rows
      const int region_gl_y = height - region_origin.y - region_size.y;
      const glm::ivec2 high_size = region_size * k;
      // The rasteriser samples each sub-pixel at its centre; moving the image by (0.5 - jitter)
      // sub-pixels makes that centre see the point `jitter` from the cell's corner instead.
      const glm::vec2 shift_ndc = 2.0f * (glm::vec2(0.5f) - pass.jitter) / glm::vec2(high_size);
      const glm::mat4 projection = glm::translate(glm::mat4(1.0f), glm::vec3(shift_ndc, 0.0f)) *
                                   camera.tile_projection_matrix(film, region_origin, region_size);
      high.bind_and_clear(high_size.x, high_size.y);
      renderer_.draw_view(module_, {}, camera, projection, {high_size.x, high_size.y, k, 0},
                          {region_origin.x * k, region_gl_y * k, pass.light_samples,
                           static_cast<int>(pass.seed & 0x7fffffffu)});
      filter.reduce(high,
                    {.subpixels = k,
                     .jitter = pass.jitter,
                     .region_origin = {region_origin.x, region_gl_y},
                     .region_size = region_size,
                     .out_origin = {origin.x, gl_y},
                     .out_size = size},
                    out_total.id(), out_specular.id());
      glFinish();  // one tile at a time keeps progress honest and the driver's queue short
      check_gl("rendering a reference tile");
      if (progress) progress(++done, tiles_x * tiles_y);
    }
  const Image total = RenderTarget::read(out_total.id(), width, height);
  const Image specular = RenderTarget::read(out_specular.id(), width, height);
  if (wanted == FilmRegion{0, 0, width, height}) return {total, specular};
  return {total.crop(wanted.x, wanted.y, wanted.width, wanted.height),
          specular.crop(wanted.x, wanted.y, wanted.width, wanted.height)};
}

}  // namespace glintlab
