#pragma once
// Image pairs on which glintlab's FLIP is checked against the authors' implementation (NVlabs/flip
// v1.6, built outside the repository: tools/flip-validation.sh). The same images feed the test
// (test_flip.cpp) and the files that tool writes (flip_validation_pairs.cpp), so the numbers the
// test pins are the authors' numbers for exactly these pictures.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/flip.hpp"
#include "core/image.hpp"

namespace glintlab::test {

struct FlipPair {
  std::string name;
  bool hdr = false;  ///< radiance in EXR (HDR-FLIP); otherwise a picture in an sRGB PNG (LDR-FLIP)
  Image test, reference;
  std::optional<flip::Exposures> exposures;  ///< HDR-FLIP's range given to both tools (else automatic)
};

inline constexpr int kFlipPairSide = 128;

// A smooth colour ramp: ((x + .5) / side, (y + .5) / side, 0.25), times `scale`.
inline Image flip_ramp(float scale = 1.0f) {
  Image image(kFlipPairSide, kFlipPairSide);
  for (int y = 0; y < kFlipPairSide; ++y)
    for (int x = 0; x < kFlipPairSide; ++x)
      image.at(x, y) = scale * glm::vec3((x + 0.5f) / kFlipPairSide, (y + 0.5f) / kFlipPairSide, 0.25f);
  return image;
}

// `value` on a lattice of single pixels (every 16th pixel from (8, 8), shifted by `dx`).
inline Image with_sparkles(Image image, glm::vec3 value, int dx = 0, int size = 1) {
  for (int y = 8; y < kFlipPairSide; y += 16)
    for (int x = 8; x < kFlipPairSide; x += 16)
      for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) image.at(x + dx + i - size / 2, y + j - size / 2) = value;
  return image;
}

// A 3 x 3 box blur (clamped borders): glints spread over their neighbours, their light kept.
inline Image box_blurred(const Image& image) {
  Image out(image.width(), image.height());
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      glm::vec3 sum(0.0f);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          sum += image.at(std::clamp(x + dx, 0, image.width() - 1), std::clamp(y + dy, 0, image.height() - 1));
      out.at(x, y) = sum / 9.0f;
    }
  return out;
}

inline std::vector<FlipPair> flip_validation_pairs() {
  const Image ramp = flip_ramp();
  Image hue(kFlipPairSide, kFlipPairSide);  // the ramp's channels rotated
  for (std::size_t i = 0; i < ramp.pixel_count(); ++i) {
    const glm::vec3 c = ramp.pixels()[i];
    hue.pixels()[i] = glm::vec3(c.g, c.b, c.r);
  }
  Image darker = ramp;
  for (glm::vec3& p : darker.pixels()) p *= 0.9f;
  const Image black(kFlipPairSide, kFlipPairSide);
  const Image glints_on_black = with_sparkles(black, glm::vec3(10.0f));
  std::vector<FlipPair> pairs;
  pairs.push_back({"ldr-identical", false, ramp, ramp, std::nullopt});
  pairs.push_back({"ldr-white-dots", false, with_sparkles(ramp, glm::vec3(1.0f), 0, 3), ramp, std::nullopt});
  pairs.push_back({"ldr-darker", false, darker, ramp, std::nullopt});
  pairs.push_back({"ldr-hue", false, hue, ramp, std::nullopt});
  pairs.push_back({"hdr-glints-missing", true, flip_ramp(4.0f), with_sparkles(flip_ramp(4.0f), glm::vec3(50.0f)),
                   std::nullopt});
  pairs.push_back({"hdr-glints-blurred", true, box_blurred(with_sparkles(flip_ramp(0.5f), glm::vec3(20.0f))),
                   with_sparkles(flip_ramp(0.5f), glm::vec3(20.0f)), std::nullopt});
  pairs.push_back({"hdr-glints-dimmer", true, with_sparkles(flip_ramp(0.5f), glm::vec3(10.0f)),
                   with_sparkles(flip_ramp(0.5f), glm::vec3(20.0f)), std::nullopt});
  // Glints on black: the reference's median luminance is 0, where the automatic range is undefined;
  // both tools get this range.
  pairs.push_back({"hdr-glints-on-black-shifted", true, with_sparkles(black, glm::vec3(10.0f), 1), glints_on_black,
                   flip::Exposures{-2.0, 2.0, 5}});
  return pairs;
}

}  // namespace glintlab::test
