#include "render/pass_tiles.hpp"

#include <algorithm>

#include "gl/shader_library.hpp"
#include "render/gpu_scene.hpp"
#include "render/render_target.hpp"
#include "tables/registry.hpp"

namespace glintlab {

SubpixelTile PassTile::samples(int subpixels, glm::vec2 jitter, int film_height) const {
  return {.subpixels = subpixels,
          .jitter = jitter,
          .region_origin = {region_origin.x, region_gl_y},
          .region_size = region_size,
          .out_origin = {origin.x, film_height - origin.y - size.y},
          .out_size = size};
}

std::vector<PassTile> pass_tiles(glm::ivec2 film, const FilmRegion& wanted, int side, int margin) {
  std::vector<PassTile> tiles;
  for (int y = wanted.y; y < wanted.y + wanted.height; y += side)
    for (int x = wanted.x; x < wanted.x + wanted.width; x += side) {
      PassTile t;
      t.origin = {x, y};
      t.size = {std::min(side, wanted.x + wanted.width - x), std::min(side, wanted.y + wanted.height - y)};
      t.region_origin = glm::max(t.origin - margin, glm::ivec2(0));
      t.region_size = glm::min(t.origin + t.size + margin, film) - t.region_origin;
      t.region_gl_y = film.y - t.region_origin.y - t.region_size.y;
      tiles.push_back(t);
    }
  return tiles;
}

PassFilm::PassFilm(int width, int height)
    : width_(width), height_(height), total_(gl::make_texture(GL_TEXTURE_2D)), specular_(gl::make_texture(GL_TEXTURE_2D)) {
  glTextureStorage2D(total_.id(), 1, GL_RGBA32F, width, height);
  glTextureStorage2D(specular_.id(), 1, GL_RGBA32F, width, height);
}

Frame PassFilm::read(const FilmRegion& wanted) const {
  const Image total = RenderTarget::read(total_.id(), width_, height_);
  const Image specular = RenderTarget::read(specular_.id(), width_, height_);
  if (wanted == FilmRegion{0, 0, width_, height_}) return {total, specular};
  return {total.crop(wanted.x, wanted.y, wanted.width, wanted.height),
          specular.crop(wanted.x, wanted.y, wanted.width, wanted.height)};
}

void hash_pass_inputs(Hasher& h, const ShaderLibrary& shaders, const GpuScene& scene) {
  h.text(shaders.expand("passes/downsample.comp", {}));
  h.text(shaders.expand("passes/filter_gaussian.comp", {}));
  for (const auto& id : scene.scene_resource_ids()) {
    h.text(id);
    h.text(find_resource_type(id).key(scene.resource_context()));
  }
}

}  // namespace glintlab
