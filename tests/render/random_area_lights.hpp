#pragma once
// Random lights with extent for the NaN sweeps of the area-light tests.
#include <algorithm>
#include <cmath>
#include <random>

#include "test_scenes.hpp"

namespace glintlab::test {

/// Adds three lights with extent around a scene at the origin, a quad, a disk and a sphere in turn
/// from `trial`: centres from below the plane y = 0 to 1.8 above it (some below the plane, some
/// grazing it, some spheres around the shaded points), random orientations, sizes 10^-2.5 .. 10^0.5
/// (spheres up to 0.5), unseen by the camera.
inline void add_random_area_lights(TestScene& scene, std::mt19937& rng, int trial) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int l = 0; l < 3; ++l) {
    const double y = -0.2 + 2.0 * u01(rng);
    const TomlValue position{-1.5 + 3 * u01(rng), y, -2.0 + 2.5 * u01(rng)};
    const TomlValue direction{u01(rng) - 0.5, u01(rng) - 0.7, u01(rng) - 0.5};
    const double size = std::pow(10.0, -2.5 + 3.0 * u01(rng));
    switch ((trial + l) % 3) {
      case 0:
        scene.light("quad", {{"position", position}, {"direction", direction}, {"size", {size, 0.5 * size}},
                             {"up", {0, 1, 0.3}}, {"radiance", 1}, {"visible", false}});
        break;
      case 1: scene.disk_light(position, direction, size, 1, {{"visible", false}}); break;
      default: scene.sphere_light(position, std::min(size, 0.5), 1, {{"visible", false}});
    }
  }
}

}  // namespace glintlab::test
