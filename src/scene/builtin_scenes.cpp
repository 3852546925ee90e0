// Built-in scenes: classic specular-aliasing cases, written as scene-format TOML so that
// `glintlab scenes --print NAME` doubles as a template for users' own scenes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>

#include "core/error.hpp"
#include "scene/scene_loader.hpp"

namespace glintlab {

namespace {

/// Portable uniform [0,1) from mt19937 (std distributions differ between standard libraries).
float uniform(std::mt19937& rng) { return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f); }

std::string spheres() {
  std::ostringstream s;
  s << R"(# Rows of spheres shrinking with distance: curvature aliasing of highlights from small lights.
# (Lights are not drawn: their edges would alias the same for every method and mask the highlights.)
[film]
width = 640
height = 360

[camera]
position = [0.0, 1.1, 4.2]
target = [0.0, 0.35, -3.0]
fov = 38

[camera.path]
type = "orbit"
degrees = 6
frames = 24

[[material]]
name = "floor"
ndf = "ggx"
alpha = 0.5
f0 = 0.04
diffuse = 0.18

[[material]]
name = "mirror"
alpha = 0.002
f0 = [0.95, 0.93, 0.88]

[[material]]
name = "glossy"
alpha = 0.03
f0 = [0.91, 0.78, 0.42]

[[material]]
name = "plastic"
alpha = 0.08
f0 = 0.04
diffuse = [0.35, 0.05, 0.04]

[[shape]]
type = "plane"
material = "floor"
size = 40
translate = [0, 0, -10]
)";
  const char* rows[] = {"mirror", "glossy", "plastic"};
  for (int row = 0; row < 3; ++row)
    for (int i = 0; i < 12; ++i) {
      const float r = 0.3f * std::pow(0.78f, static_cast<float>(i));
      const float fi = static_cast<float>(i);
      const float z = 1.0f - 0.9f * fi - 0.12f * fi * fi;
      const float x = (static_cast<float>(row) - 1.0f) * (0.8f + 0.05f * static_cast<float>(i));
      // Tessellation follows the size on screen: the chord error stays under ~0.2 px at 1080p.
      const int segments = std::max(12, static_cast<int>(std::lround(64.0f * r / 0.3f)));
      s << "\n[[shape]]\ntype = \"sphere\"\nmaterial = \"" << rows[row] << "\"\nradius = " << r
        << "\nsegments = " << segments << "\ntranslate = [" << x << ", " << r << ", " << z << "]\n";
    }
  s << R"(
[[light]]
type = "sphere"
position = [-3.0, 4.0, 2.0]
radius = 0.08
radiance = [900, 850, 800]
visible = false

[[light]]
type = "disk"
position = [4.0, 3.0, -6.0]
direction = [-0.6, -0.45, 0.65]
radius = 0.12
radiance = [300, 360, 450]
visible = false

[[light]]
type = "directional"
direction = [0.3, -1.0, -0.4]
irradiance = 0.4
)";
  return s.str();
}

std::string tubes() {
  std::ostringstream s;
  s << R"(# A hairball-like bundle of thin curved metal tubes: highlights thinner than a pixel.
[film]
width = 640
height = 360

[camera]
position = [0.0, 0.2, 3.2]
target = [0.0, 0.0, 0.0]
fov = 35

[camera.path]
type = "orbit"
degrees = 8
frames = 24

[[material]]
name = "metal"
alpha = 0.02
f0 = [0.95, 0.64, 0.54]

[[material]]
name = "backdrop"
alpha = 0.6
f0 = 0.04
diffuse = 0.1

[[shape]]
type = "plane"
material = "backdrop"
size = 20
rotate = [90, 0, 0]
translate = [0, 0, -3]
)";
  std::mt19937 rng(7);
  for (int t = 0; t < 90; ++t) {
    s << "\n[[shape]]\ntype = \"tube\"\nmaterial = \"metal\"\nradius = " << 0.006 + 0.006 * uniform(rng)
      << "\nsegments = 12\nsides = 8\npoints = [";
    // A random walk on a ball of radius ~0.9, bent smoothly.
    float theta = 6.2831853f * uniform(rng), phi = std::acos(2.0f * uniform(rng) - 1.0f);
    float dtheta = 1.2f * (uniform(rng) - 0.5f), dphi = 1.2f * (uniform(rng) - 0.5f);
    for (int k = 0; k < 6; ++k) {
      const float r = 0.55f + 0.35f * uniform(rng);
      s << (k ? ", " : "") << "[" << r * std::sin(phi) * std::cos(theta) << ", " << r * std::cos(phi) << ", "
        << r * std::sin(phi) * std::sin(theta) << "]";
      theta += dtheta;
      phi += dphi;
      dtheta += 0.3f * (uniform(rng) - 0.5f);
      dphi += 0.3f * (uniform(rng) - 0.5f);
    }
    s << "]\n";
  }
  s << R"(
[[light]]
type = "sphere"
position = [2.5, 3.0, 2.5]
radius = 0.1
radiance = 500

[[light]]
type = "point"
position = [-3.0, 1.0, 2.0]
intensity = [6, 7, 9]
)";
  return s.str();
}

std::string bumpy_plane() {
  return R"(# A metal plane with a procedural bumpy normal map seen at grazing angles to the horizon.
[film]
width = 640
height = 360

[camera]
position = [0.0, 0.6, 4.0]
target = [0.0, 0.0, -6.0]
fov = 45

[camera.path]
type = "dolly"
to = [0.0, 0.6, 3.0]
frames = 24

[[material]]
name = "bumpy-metal"
ndf = "ggx"
alpha = 0.04
f0 = [0.9, 0.9, 0.92]
diffuse = 0.02
normal_map = { generator = "bumps", resolution = 512, alpha = 0.25, waves = 96, max_frequency = 24, seed = 3 }
normal_map_tiling = 1

[[shape]]
type = "plane"
material = "bumpy-metal"
size = 60
uv_scale = 60
translate = [0, 0, -20]

[[light]]
type = "sphere"
position = [0.0, 2.5, -30.0]
radius = 1.0
radiance = 60
visible = false

[[light]]
type = "directional"
direction = [0.2, -0.3, 1.0]
irradiance = 0.5
angular_radius = 0.5
)";
}

std::string mirror_disk() {
  return R"(# Near-mirror objects under one small disk light: highlights are a fraction of a pixel.
[film]
width = 640
height = 360

[camera]
position = [0.0, 1.6, 5.5]
target = [0.0, 0.4, 0.0]
fov = 30

[camera.path]
type = "orbit"
degrees = 5
frames = 24

[[material]]
name = "chrome"
alpha = 0.001
f0 = [0.95, 0.95, 0.95]

[[material]]
name = "gold"
alpha = 0.003
f0 = [1.0, 0.78, 0.34]

[[material]]
name = "ground"
alpha = 0.4
f0 = 0.04
diffuse = 0.15

[[shape]]
type = "plane"
material = "ground"
size = 30

[[shape]]
type = "sphere"
material = "chrome"
radius = 0.5
translate = [-1.2, 0.5, 0.0]

[[shape]]
type = "torus"
material = "gold"
major_radius = 0.45
minor_radius = 0.12
rotate = [70, 0, 20]
translate = [0.2, 0.6, 0.3]

[[shape]]
type = "cylinder"
material = "chrome"
radius = 0.25
height = 1.2
translate = [1.3, 0.6, -0.4]

[[shape]]
type = "sphere"
material = "gold"
radius = 0.12
translate = [0.6, 0.12, 1.2]

[[light]]
type = "disk"
position = [2.0, 5.0, 3.0]
direction = [-0.35, -0.8, -0.5]
radius = 0.15
radiance = 2500
)";
}

std::string mirror_bumps() {
  return R"(# A normal-mapped mirror under one small disk light: each bump reflects its own sub-pixel highlight.
# Frame 0 is close: a bump spans several pixels. The camera path pulls back until a pixel holds
# many bumps (the last frame): high normal variation inside the pixel.
[film]
width = 640
height = 360

[camera]
position = [0.0, 0.9, 2.2]
target = [0.0, 0.0, -1.5]
fov = 40

[camera.path]
type = "dolly"
to = [0.0, 5.0, 16.0]
frames = 24

[[material]]
name = "hammered-chrome"
ndf = "ggx"
alpha = 0.002
f0 = [0.95, 0.95, 0.95]
normal_map = { generator = "bumps", resolution = 512, alpha = 0.12, waves = 96, max_frequency = 12, seed = 5 }
normal_map_tiling = 1

[[shape]]
type = "plane"
material = "hammered-chrome"
size = 12
uv_scale = 6
translate = [0, 0, -2]

[[light]]
type = "disk"
position = [0.6, 3.0, -7.0]
direction = [-0.1, -0.55, 0.83]
radius = 0.25
radiance = 400
visible = false
)";
}


std::string glint_tubes() {
  std::ostringstream s;
  s << R"(# Curved metal tubes with sparkles (after Chermain et al. 2021, fig. 8): glints on surfaces
# whose curvature turns the half vector by more than a lobe's width inside one pixel.
[film]
width = 640
height = 360
bloom = 0.3

[camera]
position = [0.0, 0.25, 2.6]
target = [0.0, 0.0, 0.0]
fov = 30

[camera.path]
type = "orbit"
degrees = 6
frames = 24

[[material]]
name = "sparkly-gold"
type = "glinty"
sigma = 0.12
log_density = 13
relative_area = 0.5
f0 = [0.95, 0.8, 0.45]
diffuse = 0.01

[[material]]
name = "backdrop"
alpha = 0.6
f0 = 0.04
diffuse = 0.08

[[shape]]
type = "plane"
material = "backdrop"
size = 20
rotate = [90, 0, 0]
translate = [0, 0, -2]
)";
  std::mt19937 rng(11);
  for (int t = 0; t < 9; ++t) {
    s << "\n[[shape]]\ntype = \"tube\"\nmaterial = \"sparkly-gold\"\nradius = " << 0.05 + 0.03 * uniform(rng)
      << "\nsegments = 24\nsides = 32\npoints = [";
    // Gentle arcs across the view.
    const float y = 0.9f * (uniform(rng) - 0.5f), z = 0.6f * (uniform(rng) - 0.5f);
    const float bend = 0.5f * (uniform(rng) - 0.5f), tilt = 0.6f * (uniform(rng) - 0.5f);
    for (int k = 0; k < 5; ++k) {
      const float x = -1.1f + 0.55f * static_cast<float>(k);
      s << (k ? ", " : "") << "[" << x << ", " << y + tilt * x + bend * (1.0f - x * x) << ", "
        << z + 0.3f * std::sin(2.0f * x + static_cast<float>(t)) << "]";
    }
    s << "]\n";
  }
  s << R"(
[[light]]
type = "point"
position = [1.5, 2.0, 3.0]
intensity = 12

[[light]]
type = "point"
position = [-2.5, 0.5, 2.0]
intensity = [3, 4, 6]
)";
  return s.str();
}

std::string glint_sphere() {
  return R"(# A sparkly sphere with an anisotropic normal map (ridges at 45 degrees in uv): LEAN + glints
# needs the slope correlation rho to keep the distant lobe's orientation (Chermain et al. 2021, fig. 7).
[film]
width = 640
height = 360
bloom = 0.3

[camera]
position = [0.0, 0.4, 3.6]
target = [0.0, 0.0, 0.0]
fov = 35

[camera.path]
type = "orbit"
degrees = 8
frames = 24

[[material]]
name = "sparkly-steel"
type = "glinty"
sigma = 0.08
log_density = 18
relative_area = 0.6
f0 = [0.9, 0.9, 0.95]
diffuse = 0.02
normal_map = { generator = "bumps", resolution = 512, alpha = 0.2, waves = 96, max_frequency = 32, anisotropy = 6, angle = 45, seed = 9 }
normal_map_tiling = 6

[[material]]
name = "backdrop"
alpha = 0.6
f0 = 0.04
diffuse = 0.08

[[shape]]
type = "sphere"
material = "sparkly-steel"
radius = 1.0
segments = 256

[[shape]]
type = "plane"
material = "backdrop"
size = 20
rotate = [90, 0, 0]
translate = [0, 0, -3]

[[light]]
type = "point"
position = [2.0, 2.5, 3.0]
intensity = 20

[[light]]
type = "point"
position = [-3.0, -0.5, 2.0]
intensity = [4, 5, 8]
)";
}

std::string glint_terrain() {
  return R"(# Glittery, normal-mapped ground seen to the horizon under a low sun: near, single sparkles;
# far, thousands of microfacets and bumps per pixel, where glints must become the filtered lobe.
[film]
width = 640
height = 360
bloom = 0.3

[camera]
position = [0.0, 0.8, 4.0]
target = [0.0, 0.0, -8.0]
fov = 45

[camera.path]
type = "dolly"
to = [0.0, 0.8, 3.0]
frames = 24

[[material]]
name = "glitter-ground"
type = "glinty"
sigma = 0.15
log_density = 15
relative_area = 0.3
f0 = [0.9, 0.9, 0.9]
diffuse = 0.04
normal_map = { generator = "bumps", resolution = 512, alpha = 0.25, waves = 128, max_frequency = 24, seed = 4 }
normal_map_tiling = 0.25

[[shape]]
type = "plane"
material = "glitter-ground"
size = 80
uv_scale = 80
translate = [0, 0, -30]

[[light]]
type = "directional"
direction = [0.15, -0.3, 1.0]
irradiance = 2
)";
}

std::string quad_light() {
  return R"(# Glossy spheres and a normal-mapped plane under one wide rectangular (quad) light, high behind
# them: its reflection is a long highlight on the plane and small bright bars on the spheres.
[film]
width = 640
height = 360

[camera]
position = [0.0, 1.2, 4.5]
target = [0.0, 0.2, -2.0]
fov = 45

[camera.path]
type = "orbit"
degrees = 8
frames = 24

[[material]]
name = "brushed-floor"
ndf = "ggx"
alpha = 0.06
f0 = [0.9, 0.9, 0.92]
diffuse = 0.02
normal_map = { generator = "bumps", resolution = 512, alpha = 0.15, waves = 96, max_frequency = 24, seed = 7 }
normal_map_tiling = 1

[[material]]
name = "glossy-copper"
ndf = "ggx"
alpha = 0.02
f0 = [0.95, 0.64, 0.54]

[[material]]
name = "satin"
ndf = "beckmann"
alpha = 0.15
f0 = 0.04
diffuse = [0.1, 0.2, 0.45]

[[shape]]
type = "plane"
material = "brushed-floor"
size = 30
uv_scale = 30
translate = [0, 0, -8]

[[shape]]
type = "sphere"
material = "glossy-copper"
radius = 0.5
translate = [-0.9, 0.5, -0.5]

[[shape]]
type = "sphere"
material = "satin"
radius = 0.35
translate = [0.8, 0.35, 0.2]

[[shape]]
type = "sphere"
material = "glossy-copper"
radius = 0.15
translate = [0.1, 0.15, 1.0]

[[light]]
type = "quad"
position = [0.0, 4.0, -5.0]
direction = [0.0, -4.0, 6.0]
size = [3.0, 0.5]
up = [0, 1, 0]
radiance = 6
visible = false
)";
}

}  // namespace

const std::vector<BuiltinScene>& builtin_scenes() {
  static const std::vector<BuiltinScene> scenes = {
      {"spheres", "rows of mirror, glossy and plastic spheres shrinking with distance under small lights (default)"},
      {"tubes", "a hairball-like bundle of thin curved metal tubes"},
      {"bumpy-plane", "a normal-mapped metal plane with procedural bumps, seen at grazing angles"},
      {"mirror-disk", "near-mirror objects under one small disk light"},
      {"mirror-bumps", "a normal-mapped mirror under one small disk light, pulled back until bumps are sub-pixel"},
      {"glint-tubes", "curved tubes of a glinty gold under point lights"},
      {"glint-sphere", "a glinty sphere with an anisotropic normal map (ridges at 45 degrees)"},
      {"glint-terrain", "glittery normal-mapped ground seen to the horizon under a low sun"},
      {"quad-light", "glossy spheres and a normal-mapped plane under one rectangular (quad) light"},
  };
  return scenes;
}

std::string builtin_scene_toml(const std::string& name) {
  if (name == "spheres") return spheres();
  if (name == "tubes") return tubes();
  if (name == "bumpy-plane") return bumpy_plane();
  if (name == "mirror-disk") return mirror_disk();
  if (name == "mirror-bumps") return mirror_bumps();
  if (name == "glint-tubes") return glint_tubes();
  if (name == "glint-sphere") return glint_sphere();
  if (name == "glint-terrain") return glint_terrain();
  if (name == "quad-light") return quad_light();
  std::string known;
  for (const auto& s : builtin_scenes()) known += (known.empty() ? "" : ", ") + s.name;
  throw InputError("builtin:" + name + ": no such built-in scene; allowed: " + known);
}

}  // namespace glintlab
