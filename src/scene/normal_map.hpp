#pragma once
// Tangent-space normal maps (+z out of the surface, +y along +v, which is up in an image file: the
// OpenGL/glTF convention), loaded from an image or generated procedurally. Procedural maps are periodic so they tile.
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace glintlab {

struct NormalMap {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> normals;  ///< unit vectors, row 0 at v = 0 (an image file's bottom row)
  std::string description;         ///< where it came from (file or generator and parameters)
};

/// Decodes n = 2c - 1 from an RGB image and renormalises. Throws InputError naming the file.
NormalMap load_normal_map(const std::filesystem::path& path);

/// Periodic Gaussian random surface (random-phase cosine waves, after Heitz's procedural Beckmann
/// surfaces) whose slopes have standard deviation `slope_sigma` / sqrt(2) per axis, i.e. a
/// Beckmann-like NDF with roughness alpha = slope_sigma. Frequencies are integers so it tiles.
/// anisotropy > 1 narrows the wave directions about `angle_degrees` (from +u towards +v) by that
/// factor: ridges across that direction, slopes elongated along it (correlated in uv when the
/// angle is not a multiple of 90 degrees); the total slope variance is unchanged.
NormalMap generate_bumps(int resolution, float slope_sigma, int waves, int max_frequency, std::uint32_t seed,
                         float anisotropy = 1.0f, float angle_degrees = 0.0f);

/// Voronoi "flakes": each cell tilted by a normal drawn from a Beckmann distribution of roughness
/// `alpha`; toroidal, so it tiles. `cells` is the number of cells along one edge.
NormalMap generate_flakes(int resolution, int cells, float alpha, std::uint32_t seed);

}  // namespace glintlab
