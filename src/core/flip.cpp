#include "core/flip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/colour.hpp"

namespace glintlab::flip {

namespace {

constexpr double kPi = std::numbers::pi;

// FLIP's constants (paper sec. 4, table 1 of the release's FLIP.h).
constexpr double kColourExponent = 0.7;      // q_c: HyAB distance to the perceived difference
constexpr double kColourKnee = 0.4;          // p_c: share of the largest difference below the knee
constexpr double kColourKneeValue = 0.95;    // p_t: the error at the knee
constexpr double kFeatureWidthDegrees = 0.082;  // w: the feature detectors' width
constexpr double kFeatureExponent = 0.5;     // q_f

// The contrast sensitivity functions of sec. 4.1 as sums of Gaussians a sqrt(pi / b) exp(-pi^2 x^2 / b)
// (x in degrees), for the achromatic, red-green and blue-yellow channels of YCxCz.
struct Gaussian {
  double a, b;
  [[nodiscard]] double at(double x) const { return a * std::sqrt(kPi / b) * std::exp(-kPi * kPi * x * x / b); }
  // The 2D Gaussian a sqrt(pi / b) exp(-pi^2 (x^2 + y^2) / b) is factor(x) factor(y).
  [[nodiscard]] double factor(double x) const {
    return std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPi * kPi * x * x / b);
  }
};
constexpr Gaussian kAchromatic{1.0, 0.0047}, kRedGreen{1.0, 0.0053};
constexpr Gaussian kBlueYellow[2] = {{34.1, 0.04}, {13.5, 0.025}};
constexpr double kWidestCsf = 0.04;

// The D65 white of sRGB (XYZ), the white point of YCxCz and CIELab.
constexpr glm::dvec3 kWhite{0.950428545, 1.0, 1.088900371};

glm::dvec3 linear_rgb_to_xyz(const glm::dvec3& c) {
  return {(10135552.0 * c.r + 8788810.0 * c.g + 4435075.0 * c.b) / 24577794.0,
          (2613072.0 * c.r + 8788810.0 * c.g + 887015.0 * c.b) / 12288897.0,
          (1425312.0 * c.r + 8788810.0 * c.g + 70074185.0 * c.b) / 73733382.0};
}
glm::dvec3 xyz_to_linear_rgb(const glm::dvec3& c) {
  return {3.241003275 * c.x - 1.537398934 * c.y - 0.498615861 * c.z,
          -0.969224334 * c.x + 1.875930071 * c.y + 0.041554224 * c.z,
          0.055639423 * c.x - 0.204011202 * c.y + 1.057148933 * c.z};
}
// YCxCz (Zhang & Wandell's opponent space): linear in XYZ, so filtering commutes with it.
glm::dvec3 xyz_to_ycxcz(glm::dvec3 c) {
  c /= kWhite;
  return {116.0 * c.y - 16.0, 500.0 * (c.x - c.y), 200.0 * (c.y - c.z)};
}
glm::dvec3 ycxcz_to_xyz(const glm::dvec3& c) {
  const double y = (c.x + 16.0) / 116.0;
  return glm::dvec3(y + c.y / 500.0, y, y - c.z / 200.0) * kWhite;
}
glm::dvec3 xyz_to_lab(glm::dvec3 c) {
  constexpr double delta = 6.0 / 29.0;
  auto f = [](double t) { return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0; };
  c /= kWhite;
  const double fx = f(c.x), fy = f(c.y), fz = f(c.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}
// Hunt's effect: chroma is seen less in the dark (a*, b* scaled by 0.01 L*).
glm::dvec3 hunt(const glm::dvec3& lab) { return {lab.x, 0.01 * lab.x * lab.y, 0.01 * lab.x * lab.z}; }
// HyAB: city-block in lightness, Euclidean in the chromatic plane (sec. 4.1).
double hyab(const glm::dvec3& a, const glm::dvec3& b) {
  return std::abs(a.x - b.x) + std::hypot(a.y - b.y, a.z - b.z);
}
// The largest perceived colour difference, between pure green and pure blue.
double largest_colour_difference() {
  const auto perceived = [](glm::dvec3 rgb) { return hunt(xyz_to_lab(linear_rgb_to_xyz(rgb))); };
  return std::pow(hyab(perceived({0, 1, 0}), perceived({0, 0, 1})), kColourExponent);
}

// A 1D filter of 2 radius + 1 taps.
using Taps = std::vector<double>;

// Convolves a plane of `channels` floats per pixel along x (dx = 1) or y with one filter per
// channel; borders clamp to the edge.
std::vector<float> convolve(const std::vector<float>& plane, int width, int height, int channels,
                            const std::vector<const Taps*>& filters, bool along_x) {
  std::vector<float> out(plane.size());
  const int radius = static_cast<int>(filters[0]->size() / 2);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c) {
        const Taps& taps = *filters[c];
        double sum = 0;
        for (int k = -radius; k <= radius; ++k) {
          const int sx = along_x ? std::clamp(x + k, 0, width - 1) : x;
          const int sy = along_x ? y : std::clamp(y + k, 0, height - 1);
          sum += taps[k + radius] * plane[(static_cast<std::size_t>(sy) * width + sx) * channels + c];
        }
        out[(static_cast<std::size_t>(y) * width + x) * channels + c] = static_cast<float>(sum);
      }
  return out;
}

// The contrast sensitivity filters, separable: the achromatic and red-green ones are single
// Gaussians (each 1D factor sums to 1); the blue-yellow one is a sum of two 2D Gaussians, each the
// product of two 1D factors (Gaussian::factor), scaled together so the 2D sum is 1.
struct CsfFilters {
  Taps achromatic, red_green, blue_yellow[2];
};
CsfFilters csf_filters(double ppd) {
  const int radius = static_cast<int>(std::ceil(3.0 * std::sqrt(kWidestCsf / (2.0 * kPi * kPi)) * ppd));
  CsfFilters f;
  for (int k = -radius; k <= radius; ++k) {
    const double x = k / ppd;
    f.achromatic.push_back(kAchromatic.at(x));
    f.red_green.push_back(kRedGreen.at(x));
    for (int i = 0; i < 2; ++i) f.blue_yellow[i].push_back(kBlueYellow[i].factor(x));
  }
  auto sum = [](const Taps& t) { double s = 0; for (double v : t) s += v; return s; };
  for (Taps* t : {&f.achromatic, &f.red_green}) {
    const double s = sum(*t);
    for (double& v : *t) v /= s;
  }
  const double s0 = sum(f.blue_yellow[0]), s1 = sum(f.blue_yellow[1]);
  const double norm = std::sqrt(s0 * s0 + s1 * s1);
  for (Taps& t : f.blue_yellow)
    for (double& v : t) v /= norm;
  return f;
}

// The feature detectors of sec. 4.2: a Gaussian of standard deviation w/2 degrees, its first and
// second derivatives; the Gaussian sums to 1, each derivative's positive and negative taps to +1 and -1.
struct FeatureFilters {
  Taps gaussian, first, second;
};
FeatureFilters feature_filters(double ppd) {
  const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
  const int radius = static_cast<int>(std::ceil(3.0 * sigma));
  FeatureFilters f;
  for (int k = -radius; k <= radius; ++k) {
    const double g = std::exp(-double(k) * k / (2.0 * sigma * sigma));
    f.gaussian.push_back(g);
    f.first.push_back(-k * g);
    f.second.push_back((double(k) * k / (sigma * sigma) - 1.0) * g);
  }
  double g_sum = 0;
  for (double v : f.gaussian) g_sum += v;
  for (double& v : f.gaussian) v /= g_sum;
  for (Taps* t : {&f.first, &f.second}) {
    double positive = 0, negative = 0;
    for (double v : *t) (v > 0 ? positive : negative) += std::abs(v);
    for (double& v : *t) v /= v > 0 ? positive : negative;
  }
  return f;
}

void require_same_size(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height())
    throw std::invalid_argument("FLIP: image sizes differ (" + std::to_string(a.width()) + "x" +
                                std::to_string(a.height()) + " vs " + std::to_string(b.width()) + "x" +
                                std::to_string(b.height()) + ")");
}

void require_ppd(double ppd) {
  if (!(ppd > 0.0) || !std::isfinite(ppd))
    throw std::invalid_argument("FLIP: pixels per degree " + std::to_string(ppd) + " (must be > 0)");
}

}  // namespace

double pixels_per_degree(double distance, double pixels, double width) {
  return distance * (pixels / width) * kPi / 180.0;
}

double default_pixels_per_degree() { return pixels_per_degree(0.7, 3840.0, 0.7); }

Perception::Perception(const Image& linear_rgb, double ppd) : width_(linear_rgb.width()), height_(linear_rgb.height()) {
  require_ppd(ppd);
  const std::size_t n = linear_rgb.pixel_count();
  // YCxCz of the clamped input; the blue-yellow channel twice, once per Gaussian of its filter.
  std::vector<float> opponent(n * 4), lightness(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 c = xyz_to_ycxcz(linear_rgb_to_xyz(glm::clamp(glm::dvec3(linear_rgb.pixels()[i]), 0.0, 1.0)));
    opponent[4 * i + 0] = static_cast<float>(c.x);
    opponent[4 * i + 1] = static_cast<float>(c.y);
    opponent[4 * i + 2] = opponent[4 * i + 3] = static_cast<float>(c.z);
    lightness[i] = static_cast<float>((c.x + 16.0) / 116.0);  // the achromatic channel in [0, 1]
  }
  const CsfFilters csf = csf_filters(ppd);
  const std::vector<const Taps*> csf_taps{&csf.achromatic, &csf.red_green, &csf.blue_yellow[0], &csf.blue_yellow[1]};
  const std::vector<float> filtered =
      convolve(convolve(opponent, width_, height_, 4, csf_taps, true), width_, height_, 4, csf_taps, false);
  hunt_lab_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 ycxcz(filtered[4 * i], filtered[4 * i + 1], double(filtered[4 * i + 2]) + filtered[4 * i + 3]);
    // Back to the display's gamut before CIELab: the filters can leave it.
    const glm::dvec3 rgb = glm::clamp(xyz_to_linear_rgb(ycxcz_to_xyz(ycxcz)), 0.0, 1.0);
    hunt_lab_[i] = glm::vec3(hunt(xyz_to_lab(linear_rgb_to_xyz(rgb))));
  }

  // Edges (first derivative) and points (second derivative) of the achromatic channel, each as the
  // magnitude of its x and y responses; the derivative along one axis, the Gaussian along the other.
  const FeatureFilters f = feature_filters(ppd);
  std::vector<float> triple(n * 3);
  for (std::size_t i = 0; i < n; ++i) triple[3 * i] = triple[3 * i + 1] = triple[3 * i + 2] = lightness[i];
  // Along x: (d/dx, d2/dx2, Gaussian) of the lightness.
  const std::vector<float> along_x =
      convolve(triple, width_, height_, 3, {&f.first, &f.second, &f.gaussian}, true);
  std::vector<float> quad(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    quad[4 * i] = along_x[3 * i];
    quad[4 * i + 1] = along_x[3 * i + 1];
    quad[4 * i + 2] = quad[4 * i + 3] = along_x[3 * i + 2];
  }
  // Along y: the x derivatives smoothed, the x-smoothed lightness differentiated.
  const std::vector<float> d =
      convolve(quad, width_, height_, 4, {&f.gaussian, &f.gaussian, &f.first, &f.second}, false);
  edge_.resize(n);
  point_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    edge_[i] = std::hypot(d[4 * i], d[4 * i + 2]);
    point_[i] = std::hypot(d[4 * i + 1], d[4 * i + 3]);
  }
}

std::vector<float> error_map(const Perception& test, const Perception& reference) {
  if (test.width_ != reference.width_ || test.height_ != reference.height_)
    throw std::invalid_argument("FLIP: image sizes differ (" + std::to_string(test.width_) + "x" +
                                std::to_string(test.height_) + " vs " + std::to_string(reference.width_) + "x" +
                                std::to_string(reference.height_) + ")");
  const double largest = largest_colour_difference();
  const double knee = kColourKnee * largest;
  std::vector<float> out(test.hunt_lab_.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    // Colour: HyAB^q_c mapped to [0, 1], most of the range below the knee (eq. 4 of the paper).
    double colour = std::pow(hyab(glm::dvec3(test.hunt_lab_[i]), glm::dvec3(reference.hunt_lab_[i])), kColourExponent);
    colour = colour < knee ? colour * kColourKneeValue / knee
                           : kColourKneeValue + (colour - knee) / (largest - knee) * (1.0 - kColourKneeValue);
    // Features: the larger of the edge and point differences, normalised by sqrt(2) (eq. 7).
    const double feature =
        std::pow(std::max(std::abs(double(test.edge_[i]) - reference.edge_[i]),
                          std::abs(double(test.point_[i]) - reference.point_[i])) / std::sqrt(2.0),
                 kFeatureExponent);
    // Feature differences raise the colour error towards 1 (eq. 8).
    out[i] = static_cast<float>(std::pow(colour, 1.0 - feature));
  }
  return out;
}

std::vector<float> ldr_error_map(const Image& test, const Image& reference, double ppd) {
  require_same_size(test, reference);
  return error_map(Perception(test, ppd), Perception(reference, ppd));
}

float tone_map(float x) { return aces_filmic(0.6f * x); }

namespace {
// The exposure at which the tone map reaches 0.85: ACES's curve solved for x (a quadratic).
double exposure_at_085() {
  constexpr double t = 0.85, a = 2.51 * 0.36, b = 0.03 * 0.6, c = 2.43 * 0.36, d = 0.59 * 0.6, e = 0.14;
  // (a x^2 + b x) = t (c x^2 + d x + e)  ->  (a - t c) x^2 + (b - t d) x - t e = 0, the larger root.
  const double qa = a - t * c, qb = b - t * d, qc = -t * e;
  return (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
}
}  // namespace

Exposures automatic_exposures(const Image& reference) {
  std::vector<float> lum;
  lum.reserve(reference.pixel_count());
  float largest = 0.0f;
  for (const glm::vec3& p : reference.pixels()) {
    lum.push_back(luminance(p));
    largest = std::max(largest, lum.back());
  }
  if (lum.empty() || largest <= 0.0f) return {0.0, 0.0, 2};
  auto median_of = [](std::vector<float>& v) {
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
  };
  float median = median_of(lum);
  if (median <= 0.0f) {
    std::erase_if(lum, [](float y) { return y <= 0.0f; });
    median = median_of(lum);
  }
  const double x = exposure_at_085();
  Exposures e;
  e.start = std::log2(x / largest);
  e.stop = std::log2(x / median);
  e.count = static_cast<int>(std::max(2.0, std::ceil(e.stop - e.start)));
  return e;
}

Image expose_and_tone_map(const Image& radiance, double exposure) {
  const float gain = static_cast<float>(std::exp2(exposure));
  Image out(radiance.width(), radiance.height());
  for (std::size_t i = 0; i < radiance.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) out.pixels()[i][c] = tone_map(gain * radiance.pixels()[i][c]);
  return out;
}

HdrReference::HdrReference(const Image& reference, double ppd, const Exposures& exposures)
    : pixels_per_degree_(ppd), exposures_(exposures) {
  require_ppd(ppd);
  if (exposures.count < 1 || !(exposures.start <= exposures.stop))
    throw std::invalid_argument("HDR-FLIP: exposures " + std::to_string(exposures.start) + " .. " +
                                std::to_string(exposures.stop) + " (" + std::to_string(exposures.count) +
                                "): need start <= stop and at least one");
  for (int i = 0; i < exposures.count; ++i)
    perceived_.emplace_back(expose_and_tone_map(reference, exposures.at(i)), ppd);
}

std::vector<float> HdrReference::error_map(const Image& test) const {
  std::vector<float> out;
  for (int i = 0; i < exposures_.count; ++i) {
    const Perception exposed(expose_and_tone_map(test, exposures_.at(i)), pixels_per_degree_);
    const std::vector<float> e = flip::error_map(exposed, perceived_[static_cast<std::size_t>(i)]);
    if (out.empty()) out = e;
    for (std::size_t p = 0; p < e.size(); ++p) out[p] = std::max(out[p], e[p]);
  }
  return out;
}

double mean(const std::vector<float>& error_map) {
  if (error_map.empty()) return 0.0;
  double sum = 0;
  for (float v : error_map) sum += v;
  return sum / static_cast<double>(error_map.size());
}

}  // namespace glintlab::flip
