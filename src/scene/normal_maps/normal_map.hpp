#pragma once
// Tangent-space normal maps (+z out of the surface, +y along +v, which is up in an image file: the
// OpenGL/glTF convention), loaded from an image or generated procedurally. Procedural maps are periodic so they tile.
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

namespace glintlab {

/// A surface of Wang tiles (Deng et al. 2022 sec. 5.5; scene/normal_maps/wang_tiles.hpp): `tiles` x
/// `tiles` cells of tile_size^2 texels, each cell's tile chosen by the hashed lattice of tile corners
/// (period `tiles`, so that the surface repeats with the map as a plain map does).
struct WangTiling {
  int tile_size = 0;       ///< T: texels along a tile's side
  int tiles = 0;           ///< P: tiles along the surface's side; the surface is P T texels square
  std::uint32_t seed = 0;  ///< the diamonds' offsets in the input and the lattice's hash
  bool operator==(const WangTiling&) const = default;
};

struct NormalMap {
  int width = 0;   ///< texels stored (with `wang`: the atlas, 4 T)
  int height = 0;
  std::vector<glm::vec3> normals;  ///< unit vectors, row 0 at v = 0 (an image file's bottom row)
  std::string description;         ///< where it came from (file or generator and parameters)
  /// Set: `normals` is the atlas of the 16 Wang tiles (tile t at column t mod 4, row t / 4) and the
  /// surface is the implicit tiling they make, surface_size() texels a side.
  std::optional<WangTiling> wang;

  /// Texels along the surface's side per repeat of the map: the map's own, or P T.
  [[nodiscard]] int surface_width() const { return wang ? wang->tiles * wang->tile_size : width; }
  [[nodiscard]] int surface_height() const { return wang ? wang->tiles * wang->tile_size : height; }
};

/// An image file. PNG/JPEG/TGA/BMP (8 or 16 bits): n = 2c - 1, renormalised. EXR (by its magic number): the
/// channels R, G, B are the normal's components themselves (Yan et al.'s convention), renormalised;
/// a texel that is not finite, has z <= 0 or a length outside 0.5 .. 1.5 is refused. Throws
/// InputError naming the file (and the texel and its value).
NormalMap load_normal_map(const std::filesystem::path& path);

/// Periodic Gaussian random surface (random-phase cosine waves, after Heitz's procedural Beckmann
/// surfaces) whose slopes have standard deviation `slope_sigma` / sqrt(2) per axis, i.e. a
/// Beckmann-like NDF with roughness alpha = slope_sigma. Frequencies are integers so it tiles.
/// anisotropy > 1 narrows the wave directions about `angle_degrees` (from +u towards +v) by that
/// factor: ridges across that direction, slopes elongated along it (correlated in uv when the
/// angle is not a multiple of 90 degrees); the total slope variance is unchanged.
NormalMap generate_bumps(int resolution, float slope_sigma, int waves, int max_frequency, std::uint32_t seed,
                         float anisotropy = 1.0f, float angle_degrees = 0.0f);

/// Brushed metal: long thin streaks along `angle_degrees` (from +u towards +v), a periodic Gaussian
/// surface (choose_brushed_waves) whose slopes have variance alpha^2 / 2 across the brushing and
/// along_alpha^2 / 2 along it.
NormalMap generate_brushed(int resolution, float alpha, float along_alpha, float angle_degrees, int waves,
                           int max_frequency, std::uint32_t seed);

/// Voronoi "flakes": each cell tilted by a normal drawn from a Beckmann distribution of roughness
/// `alpha`; toroidal, so it tiles. `cells` is the number of cells along one edge. A cell's feature
/// point is its centre + jitter (U - 1/2) per axis (jitter 1: anywhere in the cell); a fraction
/// `flat_fraction` of the cells, drawn independently of everything else, stays flat (+z).
NormalMap generate_flakes(int resolution, int cells, float alpha, std::uint32_t seed, float jitter = 1.0f,
                          float flat_fraction = 0.0f);

/// Random straight scratches (Gaussian grooves) on a flat or `bumps` base (generate_scratches).
struct ScratchParams {
  int resolution = 512;
  int count = 300;
  float length = 0.25f;       ///< mean length, fraction of the tile; each is uniform in [0.5, 1.5] x this
  float width = 1.5f;         ///< the groove's Gaussian profile sigma, texels
  float slope = 0.4f;         ///< the largest slope of a groove's walls (central differences, across it)
  float angle = 0.0f;         ///< mean direction, degrees from +u towards +v
  float angle_spread = 180.0f;  ///< directions uniform in angle +- spread / 2
  float base_alpha = 0.0f;    ///< roughness of a `bumps` base under the scratches; 0: flat
  std::uint32_t seed = 1;
};

/// height = -depth sum_s profile(distance to segment s), distances toroidal so it tiles; normals
/// from central differences of the height. Each segment is rasterised only near itself.
NormalMap generate_scratches(const ScratchParams& params);

/// "scratches(resolution=..., ...)": every parameter, as NormalMap::description.
std::string describe(const ScratchParams& params);

}  // namespace glintlab
