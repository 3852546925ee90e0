#pragma once
// A procedural environment for scenes that ship no map (`generator = "studio"`): a sky that
// brightens to the horizon over a dark ground, two soft boxes and a small, very bright sun, so
// that lobes of every width reflect something and the sun is a hot spot a pixel's lobe can miss.
#include "scene/lights/environment_map.hpp"

namespace glintlab {

/// The studio map, `width` x width/2 texels (a power of two >= 64), in the lat-long convention of
/// environment_map.hpp. The sun: 1.5 degrees of angular radius, 35 degrees above the horizon.
EnvironmentMap studio_environment_map(int width = 512);

}  // namespace glintlab
