#pragma once
// FLIP, the perceptual difference of two images as a viewer flips between them:
//   LDR-FLIP: Andersson, Nilsson, Akenine-Moeller, Oskarsson, Astroem, Fairchild, "FLIP: A Difference
//     Evaluator for Alternating Images", HPG 2020;
//   HDR-FLIP: Andersson, Nilsson, Shirley, Akenine-Moeller, "Visualizing Errors in Rendered High
//     Dynamic Range Images", Eurographics 2021 short paper.
// Written from the papers' definitions with the constants of the authors' public release (v1.6):
// its separable filters, its D65 white, its clamp-to-edge borders. docs/methods.md ("FLIP") states
// what was followed and where the authors' automatic exposure range is undefined; docs/results.md
// ("Metrics") has the check against their implementation.
#include <vector>

#include "core/image.hpp"

namespace glintlab::flip {

/// Pixels per degree of visual angle for a viewer `distance` metres from a display `width` metres
/// wide with `pixels` columns.
double pixels_per_degree(double distance, double pixels, double width);
/// The authors' default viewing: 0.7 m from a 0.7 m wide 3840-pixel display (67.02).
double default_pixels_per_degree();

/// What LDR-FLIP keeps of one image in linear RGB (clamped to [0, 1]): per pixel the colour after
/// the contrast sensitivity filters, in CIELab with the Hunt adjustment (paper sec. 4.1), and the
/// strengths of edges and points in its achromatic channel (sec. 4.2). FLIP's error is a per-pixel
/// function of two of these, so a reference is perceived once and compared with many images.
class Perception {
 public:
  Perception(const Image& linear_rgb, double pixels_per_degree);
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }

  friend std::vector<float> error_map(const Perception& test, const Perception& reference);

 private:
  int width_ = 0, height_ = 0;
  std::vector<glm::vec3> hunt_lab_;  ///< L*, 0.01 L* a*, 0.01 L* b*
  std::vector<float> edge_, point_;
};

/// LDR-FLIP's error map in [0, 1], one value per pixel (row-major).
std::vector<float> error_map(const Perception& test, const Perception& reference);

/// LDR-FLIP's error map of two images in linear RGB (values outside [0, 1] are clamped).
std::vector<float> ldr_error_map(const Image& test, const Image& reference, double pixels_per_degree);

/// HDR-FLIP's exposures: `count` stops evenly from `start` to `stop` (2^stop multiplies the image).
struct Exposures {
  double start = 0, stop = 0;
  int count = 2;
  [[nodiscard]] double at(int i) const { return count < 2 ? start : start + (stop - start) * i / (count - 1); }
};
/// The automatic range of HDR-FLIP (sec. 3), from the reference alone: the exposure that takes its
/// brightest pixel to the tone map's 0.85 (start) and the one that takes its median luminance there
/// (stop), ceil(stop - start) exposures (at least 2). Where the median is 0 (more than half the
/// reference black: glints on black) the authors' range is undefined (stop infinite); the median of
/// the non-zero luminances takes its place. An all-black reference gives the range [0, 0].
Exposures automatic_exposures(const Image& reference);
/// The tone map HDR-FLIP shows each exposure through: Narkowicz's ACES fit after a 0.6 pre-exposure,
/// clamped to [0, 1].
float tone_map(float x);

/// HDR-FLIP: the reference perceived at every exposure once; error_map() is the per-pixel maximum
/// over exposures of LDR-FLIP between the tone-mapped images.
class HdrReference {
 public:
  HdrReference(const Image& reference, double pixels_per_degree, const Exposures& exposures);
  [[nodiscard]] std::vector<float> error_map(const Image& test) const;
  [[nodiscard]] const Exposures& exposures() const { return exposures_; }

 private:
  double pixels_per_degree_;
  Exposures exposures_;
  std::vector<Perception> perceived_;
};

/// The tone-mapped image HDR-FLIP compares at one exposure.
Image expose_and_tone_map(const Image& radiance, double exposure);

/// FLIP's pooled score: the mean of an error map (0 for an empty one).
double mean(const std::vector<float>& error_map);

}  // namespace glintlab::flip
