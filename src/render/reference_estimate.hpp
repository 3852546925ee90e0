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
  Image standard_error;      ///< of mean.total, per pixel and channel, from the passes' spread (0 with
                             ///< fewer than two passes; intervals widen it by interval_scale())
  Image even_passes;         ///< mean total of passes 0, 2, 4, ...: an independent half-reference
  Image odd_passes;          ///< mean total of passes 1, 3, 5, ... (equals even_passes with one pass)
  std::vector<double> pass_luminance;           ///< each pass's mean luminance of total
  std::vector<double> pass_luminance_specular;  ///< each pass's mean luminance of specular
  int passes = 0;
  int spp = 0;               ///< samples per pixel in all, passes x k x k

  /// sqrt(mean over pixels and channels of standard_error^2): the RMSE that the estimate is
  /// expected to have against the converged image. NaN with fewer than two passes.
  [[nodiscard]] double noise_rmse() const;
  /// The stated error of the frame's mean luminance (of total, or of specular), relative to it:
  /// the standard error from the spread of the passes' means, widened by interval_scale(), so
  /// that an energy ratio measured against this frame is within 2 of it of the truth for about
  /// 95% of references. NaN with fewer than two passes.
  [[nodiscard]] double relative_energy_error(bool specular = false) const;
  /// How much a standard error estimated from `passes` independent passes is widened so that +-2
  /// of it is a 95% interval: t_{0.975, passes - 1} / 1.96 (Student's t: 1.62 for 4 passes, 1.09
  /// for 16, towards 1 as passes grow). NaN with fewer than two passes.
  [[nodiscard]] double interval_scale() const;
  /// The stated error of each pixel (and channel): interval_scale() times the larger of its own
  /// standard error and the root mean square of its 3 x 3 neighbourhood's, so that the truth is
  /// within 2 of it for about 95% of references. A pixel's few passes can all miss a rare bright
  /// sample (its own estimate then too small); its neighbours see the same light.
  [[nodiscard]] Image stated_error() const;
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
