#pragma once
// Image metrics against a reference, on linear radiance (never on tonemapped values).
#include <optional>
#include <vector>

#include "core/flip.hpp"
#include "core/image.hpp"

namespace glintlab {

/// Root-mean-square error over all pixels and RGB channels.
double rmse(const Image& test, const Image& reference);
/// PSNR in dB with peak 1 (display white at exposure 0); +inf for identical images.
double psnr(double rmse_value);
/// Largest absolute channel difference.
double max_abs_error(const Image& test, const Image& reference);
/// mean luminance(test) / mean luminance(reference); 1 is unbiased, < 1 lost energy.
/// Returns 1 when both are black, +inf when only the reference is.
double energy_ratio(const Image& test, const Image& reference);
/// Per-pixel |luminance(test) - luminance(reference)| in the red channel (for error maps).
Image abs_error_map(const Image& test, const Image& reference);
/// The value below which `fraction` of an error map's pixels lie; 0 for an empty map.
float error_percentile(const Image& error_map, double fraction);
/// The percentile that is the top of an error map's colour ramp (compare's maps, the viewer's
/// overlay): a few outliers do not wash out the rest.
inline constexpr double kErrorMapPercentile = 0.995;

/// Statistics that hold against an independent realisation of a stochastic surface (glints): a
/// method that draws its own glints cannot match another realisation's pixel by pixel, and the
/// per-pixel RMSE against one rewards blurring the glints away (for independent images it is the
/// bias plus both variances).
/// RMSE between the images' means over the full `block` x `block` tiles (RGB): where a tile holds
/// many glints their randomness averages out, and what remains is the error in where the light goes.
double block_rmse(const Image& test, const Image& reference, int block);
/// How strong an image's glints are: the root mean square of luminance minus its 3 x 3 mean
/// (detail at the pixel's scale, where linear shading gradients cancel), over the pixels with a
/// full neighbourhood; 0 for a smooth image. Of an estimate with a per-pixel `standard_error` the
/// noise's share (8/9 of its variance, for white noise) is taken out: the truth's detail.
double glint_detail(const Image& image, const Image* standard_error = nullptr);
/// The tile size of compare's block_rmse.
inline constexpr int kStatisticsBlock = 8;

/// How far an image's sparkles are from the truth's in number, size and brightness, wherever they
/// fall inside a region: in every full `block` x `block` tile, the Wasserstein-1 distance between
/// the two images' distributions of pixel luminance (the mean absolute difference of their sorted
/// values), averaged over tiles and divided by the reference's mean luminance there. Positions
/// inside a tile do not count, so an independent realisation of the same glints scores only the
/// randomness of their count per tile, while an image that keeps the light but spreads it (a
/// smooth highlight where the truth sparkles) scores about twice the glints' share of it.
double sparkle_distance(const Image& test, const Image& reference, int block);
/// The tile size of sparkle_distance in compare and animate.
inline constexpr int kSparkleBlock = 16;

/// Everything `compare` reports for one method.
struct ImageMetrics {
  double rmse = 0, rmse_specular = 0, psnr = 0, energy_ratio = 0, energy_ratio_specular = 0,
         max_error = 0, block_rmse = 0, glint_detail = 0;
  double flip_ldr = 0;  ///< mean LDR-FLIP of the displayed pictures (the film's exposure, ACES, no bloom)
  double flip_hdr = 0;  ///< mean HDR-FLIP of the radiance, exposures from the reference
  double sparkle_distance = 0;  ///< sparkle_distance(total, reference, kSparkleBlock)
};

/// How the metrics look at images: the film's exposure of the displayed picture (LDR-FLIP), the
/// viewer's pixels per degree (both FLIPs).
struct MetricsViewing {
  float display_exposure = 0.0f;
  double pixels_per_degree = flip::default_pixels_per_degree();
};

/// The linear picture a display shows of `radiance`: 2^exposure, then the ACES curve the PNGs
/// use (colour.hpp), in [0, 1] before the sRGB encoding; LDR-FLIP's input.
Image displayed_linear(const Image& radiance, float exposure);

/// A reference prepared once for measuring many images against it (FLIP perceives it once per
/// exposure).
class MetricsReference {
 public:
  MetricsReference(const Image& total, const Image& specular, const MetricsViewing& viewing);
  /// `flip_ldr_map_out`: also the LDR-FLIP map the mean was taken of (compare writes it).
  [[nodiscard]] ImageMetrics measure(const Image& total, const Image& specular,
                                     std::vector<float>* flip_ldr_map_out = nullptr) const;
  /// LDR-FLIP's and HDR-FLIP's error maps of one image.
  [[nodiscard]] std::vector<float> flip_ldr_map(const Image& total) const;
  [[nodiscard]] std::vector<float> flip_hdr_map(const Image& total) const;
  [[nodiscard]] const flip::Exposures& hdr_exposures() const { return hdr_.exposures(); }
  [[nodiscard]] const MetricsViewing& viewing() const { return viewing_; }

 private:
  Image total_, specular_;
  MetricsViewing viewing_;
  flip::Perception displayed_;
  flip::HdrReference hdr_;
};

/// Flicker: the mean over pixels, RGB channels and frames t >= 1 of
///   |(m_t - r_t) - (m_{t-1} - r_{t-1})|,
/// zero for a method whose error against the reference does not change between frames.
class FlickerAccumulator {
 public:
  void add_frame(const Image& method, const Image& reference);
  /// 0 until two frames were added.
  [[nodiscard]] double flicker() const;
  /// The same mean for each frame t >= 1 alone (frames() - 1 values; flicker() is their mean).
  [[nodiscard]] const std::vector<double>& per_frame() const { return per_frame_; }
  [[nodiscard]] int frames() const { return frames_; }

 private:
  Image previous_error_;
  std::vector<double> per_frame_;
  double sum_ = 0;
  double count_ = 0;
  int frames_ = 0;
};

}  // namespace glintlab
