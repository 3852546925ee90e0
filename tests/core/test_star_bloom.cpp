// The star bloom of displayed pictures (src/core/star_bloom.hpp).
#include <gtest/gtest.h>

#include "core/star_bloom.hpp"

using namespace glintlab;

TEST(StarBloom, LeavesImagesWithinTheDisplayRangeUnchanged) {
  Image img(32, 16, glm::vec3(0.3f));
  img.at(5, 5) = glm::vec3(1.0f);
  const Image out = star_bloom(img, 2.0f, 4.0f);
  for (std::size_t i = 0; i < img.pixel_count(); ++i) EXPECT_EQ(out.pixels()[i], img.pixels()[i]);
}

TEST(StarBloom, AGlintStreaksAlongEightRaysWithTheStatedEnergy) {
  Image img(201, 201);
  img.at(100, 100) = glm::vec3(101.0f);  // 100 above white
  const float strength = 0.5f;
  const Image out = star_bloom(img, strength, 5.0f);
  double added = 0.0;
  for (std::size_t i = 0; i < img.pixel_count(); ++i) added += out.pixels()[i].r - img.pixels()[i].r;
  EXPECT_NEAR(added, strength * 100.0, 1e-3 * strength * 100.0);  // rays of 5 px e-folding end well inside
  // Light along the rays, none off them; the rays are symmetric.
  EXPECT_GT(out.at(110, 100).r, 0.0f);
  EXPECT_GT(out.at(107, 107).r, 0.0f);
  EXPECT_EQ(out.at(110, 103).r, 0.0f);
  EXPECT_FLOAT_EQ(out.at(110, 100).r, out.at(90, 100).r);
  EXPECT_FLOAT_EQ(out.at(100, 110).r, out.at(100, 90).r);
  EXPECT_FLOAT_EQ(out.at(107, 93).r, out.at(93, 107).r);
  EXPECT_GT(out.at(101, 100).r, out.at(110, 100).r) << "decays away from the glint";
}
