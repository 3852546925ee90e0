#include <gtest/gtest.h>

#include "scene/camera.hpp"

using namespace glintlab;

TEST(Camera, TileProjectionOfTheWholeFilmIsTheFullProjection) {
  Camera c;
  const glm::mat4 full = c.projection_matrix(2.0f);
  const glm::mat4 tile = c.tile_projection_matrix({200, 100}, {0, 0}, {200, 100});
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(full[i][j], tile[i][j], 1e-6f);
}

TEST(Camera, TilesMapTheirCornerPixelsToTheCornersOfNdc) {
  Camera c;
  c.projection = Projection::Orthographic;
  const glm::ivec2 film(100, 50), origin(20, 10), size(30, 20);
  const glm::mat4 full = c.projection_matrix(2.0f), tile = c.tile_projection_matrix(film, origin, size);
  // A point at the tile's top-left corner in the full film's NDC...
  const glm::vec4 p = glm::inverse(full) * glm::vec4(-1.0f + 2.0f * 20 / 100, 1.0f - 2.0f * 10 / 50, 0.0f, 1.0f);
  const glm::vec4 q = tile * p;
  EXPECT_NEAR(q.x / q.w, -1.0f, 1e-5f);
  EXPECT_NEAR(q.y / q.w, 1.0f, 1e-5f);
}

TEST(CameraPath, OrbitKeepsDistanceAndDollyEndsWhereAsked) {
  Camera c;
  CameraPath orbit{CameraPathType::Orbit, 10, 90.0f};
  const Camera last = orbit.at(c, 9);
  EXPECT_NEAR(glm::length(last.position - c.target), glm::length(c.position - c.target), 1e-5f);
  EXPECT_NEAR(last.position.x, 5.0f, 1e-4f);  // (0,1,5) rotated 90 degrees about +y
  CameraPath dolly;
  dolly.type = CameraPathType::Dolly;
  dolly.frames = 5;
  dolly.dolly_to = {0, 1, 2};
  EXPECT_NEAR(dolly.at(c, 4).position.z, 2.0f, 1e-6f);
  EXPECT_NEAR(dolly.at(c, 0).position.z, 5.0f, 1e-6f);
}
