#pragma once
// The last step of a reference pass: one tile of k x k sub-pixel samples per pixel reduced to
// film pixels with the reference's pixel filter (render/pixel_filter.hpp). The box averages each
// pixel's own samples (passes/downsample.comp); the Gaussian weights the samples of the pixels
// around it too, so its tile is rendered with a margin of PixelFilter::support_pixels() pixels
// (cut at the film's edges) and reduced in two separable passes (passes/filter_gaussian.comp).
#include <glm/vec2.hpp>

#include "gl/objects.hpp"
#include "render/pixel_filter.hpp"

namespace glintlab {

class RenderTarget;
class ShaderLibrary;

/// Where a tile's samples are and where its pixels go, in film pixels with GL's y up.
struct SubpixelTile {
  int subpixels = 1;         ///< k
  glm::vec2 jitter{0.5f};    ///< each sample's offset from its sub-pixel cell's corner, in sub-pixels
  glm::ivec2 region_origin;  ///< the film pixel whose k x k samples are (0, 0) .. (k-1, k-1) of the target
  glm::ivec2 region_size;    ///< pixels rendered: the tile and its margin inside the film
  glm::ivec2 out_origin;     ///< the tile's first film pixel
  glm::ivec2 out_size;       ///< the tile's pixels, inside the region
};

class SubpixelFilter {
 public:
  SubpixelFilter(ShaderLibrary& shaders, PixelFilter filter) : shaders_(shaders), filter_(filter) {}
  /// Writes the tile's pixels of `out_total` and `out_specular` (RGBA32F, film size) from the
  /// samples in `high`.
  void reduce(const RenderTarget& high, const SubpixelTile& tile, GLuint out_total, GLuint out_specular);

 private:
  void box(const RenderTarget& high, const SubpixelTile& tile, GLuint out_total, GLuint out_specular);
  void gaussian(const RenderTarget& high, const SubpixelTile& tile, GLuint out_total, GLuint out_specular);

  ShaderLibrary& shaders_;
  PixelFilter filter_;
  // The horizontal pass's result (tile columns x sample rows), kept for the next tile.
  gl::Texture rows_total_, rows_specular_;
  glm::ivec2 rows_size_{0};
};

}  // namespace glintlab
