#pragma once
// The radiance of an environment light (`[[light]] type = "environment"`): a latitude-longitude
// map, piecewise constant per texel. The map IS the light: no filtering anywhere reads between
// texels, so that the sampler (environment_sampling.hpp), the reference and the real-time methods
// (environment_prefilter.hpp) see one and the same radiance.
//
// The convention, which the GLSL side (shaders/lights/environment.glsl) relies on exactly:
// * W x H texels with W = 2H, row 0 at the top; texel (x, y) covers u in [x/W, (x+1)/W) and
//   v in [y/H, (y+1)/H).
// * Polar angle from +y: theta = pi v; azimuth phi = 2 pi (u - 0.5).
// * Map-space direction d = (sin(theta) sin(phi), cos(theta), -sin(theta) cos(phi)): the image
//   centre (u = 0.5, v = 0.5) is -z and u = 0.75 is +x, so the map seen from inside is not
//   mirrored. Inverse: theta = acos(clamp(d.y, -1, 1)), phi = atan2(d.x, -d.z),
//   u = phi / (2 pi) + 0.5.
// * Texel (x, y) subtends the solid angle (2 pi / W)(cos(pi y / H) - cos(pi (y + 1) / H)).
// * A rotation of the map about +y is the GPU's (the light's record), not the map's.
#include <filesystem>
#include <string>

#include "core/image.hpp"

namespace glintlab {

/// Maps wider than this are box-downsampled (by a power of two) when loaded, and the light is
/// then the downsampled map: its CDF and its texture hold at most 2048 x 1024 texels.
inline constexpr int kMaxEnvironmentWidth = 2048;
/// The narrowest map accepted (4 x 2: at least two rows, so that both poles have a row).
inline constexpr int kMinEnvironmentWidth = 4;
/// The size of uniform_environment_map()'s map.
inline constexpr int kUniformEnvironmentWidth = 64;

struct EnvironmentMap {
  Image radiance;      ///< W x H, W = 2H, linear RGB radiance [W/(m^2 sr)], every channel >= 0 and finite
  std::string source;  ///< the file it was read from, or "uniform"
};

/// Reads an OpenEXR lat-long map. Throws InputError naming the file, the problem, the value and
/// what is allowed when the file is missing or unreadable, not twice as wide as high, narrower
/// than kMinEnvironmentWidth, or has a NaN, infinite or negative channel (the first such texel's
/// x, y and value). A map wider than kMaxEnvironmentWidth is downsampled by the smallest power of
/// two that fits (downsample_environment, which keeps its power).
EnvironmentMap load_environment_map(const std::filesystem::path& path);

/// A kUniformEnvironmentWidth x kUniformEnvironmentWidth/2 map of one radiance ("uniform").
EnvironmentMap uniform_environment_map(glm::vec3 radiance);

/// The map-space direction of lat-long coordinates (u, v) in [0, 1]^2 (the convention above).
glm::vec3 environment_direction(double u, double v);
glm::dvec3 environment_direction_precise(double u, double v);  ///< the same in double
/// The lat-long coordinates of a map-space direction (any length but 0); u in [0, 1], v in [0, 1].
glm::dvec2 environment_uv(glm::dvec3 d);

/// The solid angle of any texel of row y of a map of `height` rows.
double environment_row_solid_angle(int y, int height);

/// The map resampled to `height` rows (and 2 height columns; height <= the map's), each texel the
/// mean of the radiance over its own solid angle: the box filter in u, weighted by the exact
/// solid angle of each source texel's overlap in v (d omega = dphi d(cos theta)). The integral of
/// the radiance over the sphere, the light's power, is kept exactly (to rounding) for any sizes;
/// when height divides the map's, each texel is a weighted mean of whole source texels.
Image downsample_environment(const Image& radiance, int height);

}  // namespace glintlab
