#pragma once
// What the GPU reference backends share (raster_reference.cpp, path_reference.cpp): a pass drawn in
// tiles of the film, each rendered with the pixel filter's margin and reduced to its pixels, the
// wanted region read back, and the inputs every estimator hash holds besides the backend's own.
#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "core/hash.hpp"
#include "render/reference_backend.hpp"
#include "render/subpixel_filter.hpp"

namespace glintlab {

class GpuScene;
class ShaderLibrary;

/// One tile of a pass: its output pixels (film, y down) and the region rendered for them.
struct PassTile {
  glm::ivec2 origin, size;               ///< the tile's pixels
  glm::ivec2 region_origin, region_size;  ///< the tile and the filter's margin, inside the film
  int region_gl_y = 0;                    ///< the region's first row in GL's y-up rows

  /// Where the region's k x k samples per pixel are and where the tile's pixels go.
  [[nodiscard]] SubpixelTile samples(int subpixels, glm::vec2 jitter, int film_height) const;
};

/// The tiles of at most `side` pixels a side that cover `wanted` of a `film`-sized film, each
/// rendered with `margin` pixels around it (cut at the film's edges, not at the region's: a tile's
/// edge pixels see the same samples as in the whole film's pass).
std::vector<PassTile> pass_tiles(glm::ivec2 film, const FilmRegion& wanted, int side, int margin);

/// The film-sized targets a pass's tiles are reduced into, and the wanted region read back.
class PassFilm {
 public:
  PassFilm(int width, int height);
  [[nodiscard]] GLuint total() const { return total_.id(); }
  [[nodiscard]] GLuint specular() const { return specular_.id(); }
  [[nodiscard]] Frame read(const FilmRegion& wanted) const;

 private:
  int width_, height_;
  gl::Texture total_, specular_;
};

/// Adds what every GPU backend's estimator reads besides its own programs: the pixel filters'
/// programs and the resources the scene's kinds read (a new table generator, its settings or
/// another environment map is a new reference).
void hash_pass_inputs(Hasher& h, const ShaderLibrary& shaders, const GpuScene& scene);

}  // namespace glintlab
