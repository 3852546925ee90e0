#include "render/subpixel_filter.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "gl/context.hpp"
#include "gl/shader_library.hpp"
#include "render/render_target.hpp"

namespace glintlab {

namespace {

void set_int(GLuint program, const char* name, int v) { glProgramUniform1i(program, glGetUniformLocation(program, name), v); }
void set_ivec2(GLuint program, const char* name, glm::ivec2 v) {
  glProgramUniform2i(program, glGetUniformLocation(program, name), v.x, v.y);
}
void set_float(GLuint program, const char* name, float v) {
  glProgramUniform1f(program, glGetUniformLocation(program, name), v);
}

void bind_images(GLuint in_total, GLuint in_specular, GLuint out_total, GLuint out_specular) {
  glBindImageTexture(0, in_total, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(1, in_specular, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(2, out_total, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(3, out_specular, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
}

GLuint groups(int n) { return static_cast<GLuint>((n + 7) / 8); }

}  // namespace

void SubpixelFilter::reduce(const RenderTarget& high, const SubpixelTile& tile, GLuint out_total, GLuint out_specular) {
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  if (filter_.is_box()) box(high, tile, out_total, out_specular);
  else gaussian(high, tile, out_total, out_specular);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

void SubpixelFilter::box(const RenderTarget& high, const SubpixelTile& tile, GLuint out_total, GLuint out_specular) {
  if (tile.region_origin != tile.out_origin || tile.region_size != tile.out_size)
    throw RuntimeFailure("the box pixel filter reads no margin around its tile");
  const GLuint program = shaders_.compute("passes/downsample.comp");
  glUseProgram(program);
  bind_images(high.total(), high.specular(), out_total, out_specular);
  set_int(program, "uSubpixels", tile.subpixels);
  set_ivec2(program, "uTileSize", tile.out_size);
  set_ivec2(program, "uOutOrigin", tile.out_origin);
  glDispatchCompute(groups(tile.out_size.x), groups(tile.out_size.y), 1);
}

void SubpixelFilter::gaussian(const RenderTarget& high, const SubpixelTile& tile, GLuint out_total,
                              GLuint out_specular) {
  const int k = tile.subpixels;
  const glm::ivec2 rows(tile.out_size.x, tile.region_size.y * k);  // tile columns x sample rows
  if (glm::any(glm::greaterThan(rows, rows_size_))) {
    rows_size_ = glm::max(rows, rows_size_);
    rows_total_ = gl::make_texture(GL_TEXTURE_2D);
    rows_specular_ = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(rows_total_.id(), 1, GL_RGBA32F, rows_size_.x, rows_size_.y);
    glTextureStorage2D(rows_specular_.id(), 1, GL_RGBA32F, rows_size_.x, rows_size_.y);
  }
  const glm::ivec2 offset = tile.out_origin - tile.region_origin;  // pixels of margin before the tile
  const GLuint program = shaders_.compute("passes/filter_gaussian.comp");
  glUseProgram(program);
  set_int(program, "uSubpixels", k);
  set_float(program, "uSigma", filter_.sigma);
  set_float(program, "uReach", std::max(PixelFilter::kTruncation * filter_.sigma, 0.5f / static_cast<float>(k)));
  set_int(program, "uSupport", filter_.support_pixels());
  // Along x: every sample row of the region, tile columns out.
  bind_images(high.total(), high.specular(), rows_total_.id(), rows_specular_.id());
  set_ivec2(program, "uAxis", {1, 0});
  set_int(program, "uSamples", tile.region_size.x * k);
  set_float(program, "uJitter", tile.jitter.x);
  set_int(program, "uPixelOffset", offset.x);
  set_ivec2(program, "uOutSize", rows);
  set_ivec2(program, "uOutOrigin", {0, 0});
  glDispatchCompute(groups(rows.x), groups(rows.y), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  // Along y: those rows into the tile's pixels.
  bind_images(rows_total_.id(), rows_specular_.id(), out_total, out_specular);
  set_ivec2(program, "uAxis", {0, 1});
  set_int(program, "uSamples", rows.y);
  set_float(program, "uJitter", tile.jitter.y);
  set_int(program, "uPixelOffset", offset.y);
  set_ivec2(program, "uOutSize", tile.out_size);
  set_ivec2(program, "uOutOrigin", tile.out_origin);
  glDispatchCompute(groups(tile.out_size.x), groups(tile.out_size.y), 1);
}

}  // namespace glintlab
