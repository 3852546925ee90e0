#pragma once
// Ground truth with its own error. The reference renders independent passes (each a k x k
// jittered sub-pixel grid with its own sample seeds); their per-pixel mean is the estimate and
// their spread gives its standard error, so every metric measured against it can say how much of
// a difference is the reference's own noise.
#include <vector>

#include "core/image.hpp"

namespace glintlab {

/// One rendered frame: linear radiance and its specular part.
struct Frame {
  Image total;
  Image specular;
};

/// A reference frame: the mean of its passes, with what is needed to judge its noise.
struct ReferenceFrame {
  Frame mean;                ///< the estimate (mean of all passes)
  Image standard_error;      ///< of mean.total, per pixel and channel (0 with fewer than two passes)
  Image even_passes;         ///< mean total of passes 0, 2, 4, ...: an independent half-reference
  Image odd_passes;          ///< mean total of passes 1, 3, 5, ... (equals even_passes with one pass)
  std::vector<double> pass_luminance;           ///< each pass's mean luminance of total
  std::vector<double> pass_luminance_specular;  ///< each pass's mean luminance of specular
  int passes = 0;
  int spp = 0;               ///< samples per pixel in all, passes x k x k

  /// sqrt(mean over pixels and channels of standard_error^2): the RMSE that the estimate is
  /// expected to have against the converged image. NaN with fewer than two passes.
  [[nodiscard]] double noise_rmse() const;
  /// Relative standard error of the frame's mean luminance (of total, or of specular), from the
  /// spread of the passes' means: the noise of every energy ratio measured against this frame.
  [[nodiscard]] double relative_energy_error(bool specular = false) const;
};

/// Accumulates passes in double precision and turns them into a ReferenceFrame.
class ReferenceAccumulator {
 public:
  ReferenceAccumulator(int width, int height, int spp_per_pass);
  /// Starts from a frame that an earlier run accumulated (e.g. from the cache).
  explicit ReferenceAccumulator(const ReferenceFrame& earlier, int spp_per_pass);

  void add_pass(const Frame& pass);
  [[nodiscard]] int passes() const { return passes_; }
  [[nodiscard]] ReferenceFrame result() const;

 private:
  int width_, height_, spp_per_pass_;
  int passes_ = 0;
  std::vector<glm::dvec3> sum_, sum_squares_, specular_sum_, even_sum_;
  std::vector<double> pass_luminance_, pass_luminance_specular_;
};

}  // namespace glintlab
