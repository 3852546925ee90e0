#pragma once
// The scene and reference the tests of yan2016 and deng2022 share: a receding normal-map-glints
// floor (a 64^2 bumps map, `tiling` repeats over the 4 m plane) under a point light, or a sphere
// and a disk light, and its reference filtered by the methods' footprint Gaussian.
#include "gl_fixture.hpp"

namespace glintlab::test {

/// The methods' default footprint_sigma, and the reference's Gaussian pixel filter.
inline constexpr float kNormalGlintsFootprint = 0.5f;

/// The floor's material: `tiling` repeats of the map over a plane's uv.
inline TomlKeys normal_glints_steel(double tiling) {
  return {{"type", "normal-map-glints"},
          {"intrinsic_roughness", 0.02},
          {"f0", 0.9},
          {"normal_map", TomlKeys{{"generator", "bumps"}, {"resolution", 64}, {"alpha", 0.25},
                                  {"waves", 48}, {"max_frequency", 8}, {"seed", 3}}},
          {"normal_map_tiling", tiling}};
}

/// The floor alone, without lights.
inline TestScene normal_glints_floor_unlit(double tiling, int width = 48, int height = 32) {
  TestScene s;
  s.film(width, height).camera({0, 0.6, 1.6}, {0, 0, -0.8}, 40).material("steel", normal_glints_steel(tiling)).plane("steel", {{"size", 4}});
  return s;
}

inline TestScene normal_glints_floor(double tiling, bool area_lights, int width = 48, int height = 32) {
  TestScene s = normal_glints_floor_unlit(tiling, width, height);
  if (area_lights)
    s.sphere_light({0.4, 0.9, -1.6}, 0.08, {300, 300, 300}, {{"visible", false}})
        .disk_light({-0.6, 0.7, -1.2}, {0.3, -1, 0.4}, 0.1, {200, 250, 300}, {{"visible", false}});
  else
    s.point_light({0.3, 1.0, -1.8}, 3);
  return s;
}

/// The scene's reference with the Gaussian pixel filter of the methods' footprint.
inline ReferenceFrame footprint_filtered_reference(SceneFixture& f, int spp) {
  ReferenceSettings settings;
  settings.spp = spp;
  settings.filter = PixelFilter::gaussian(kNormalGlintsFootprint);
  return f.reference_at(f.scene.camera, f.scene.film.width, f.scene.film.height, settings);
}

}  // namespace glintlab::test
