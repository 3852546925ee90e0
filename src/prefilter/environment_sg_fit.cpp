#include "prefilter/environment_sg_fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Dense>
#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/image.hpp"

namespace glintlab {

namespace {

constexpr double kPi = 3.14159265358979323846;

double luminance_of(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// min ||B a - y||_W over a >= 0, from the normal equations M = B^T W B and r = B^T W y, by cyclic
// coordinate descent (each step the exact minimiser along one coordinate, clamped at 0): converges
// for positive semidefinite M; stops when no amplitude moves by more than 1e-9 of the largest.
Eigen::VectorXd nonnegative_least_squares(const Eigen::MatrixXd& m, const Eigen::VectorXd& r) {
  const Eigen::Index n = r.size();
  Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd gradient = -r;  // M a - r
  for (int sweep = 0; sweep < 5000; ++sweep) {
    double largest_step = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (!(m(k, k) > 0.0)) continue;
      const double next = std::max(0.0, a(k) - gradient(k) / m(k, k));
      const double step = next - a(k);
      if (step == 0.0) continue;
      a(k) = next;
      gradient += step * m.col(k);
      largest_step = std::max(largest_step, std::abs(step));
    }
    if (largest_step <= 1e-9 * std::max(a.cwiseAbs().maxCoeff(), 1e-300)) break;
  }
  return a;
}

struct Grid {
  std::vector<glm::dvec3> directions, radiance;
  std::vector<double> weights;  // solid angles
};

// A map's compact sources far brighter than the rest (a sun), each as one lobe of its own sharpness
// taken out of `image` (its texels zeroed) before the lattice's lobes fit what remains: the L2
// fit of a sharp peak with lobes far wider than it puts power that belongs to the rest of the sky
// into the lobes about the peak. At most `count` peaks, each brighter than kPeakContrast times the
// map's mean luminance.
constexpr double kPeakContrast = 64.0;
// The fit's error is measured on the map's texels, at most this many rows (downsampled above).
constexpr int kErrorRows = 256;

std::vector<SphericalGaussian> extract_peaks(Image& image, int count, double lattice_lambda) {
  const int w = image.width(), h = image.height();
  std::vector<double> solid_angles(static_cast<std::size_t>(h));
  double mean = 0.0;
  for (int y = 0; y < h; ++y) {
    solid_angles[static_cast<std::size_t>(y)] = environment_row_solid_angle(y, h);
    for (int x = 0; x < w; ++x) mean += luminance_of(glm::dvec3(image.at(x, y))) * solid_angles[static_cast<std::size_t>(y)];
  }
  mean /= 4.0 * kPi;
  // A peak's texels: those within the lattice's spacing of its brightest one and above 1/64 of it.
  const double reach = std::cos(std::min(kPi, std::sqrt(4.0 * kPi / lattice_lambda)));
  std::vector<SphericalGaussian> peaks;
  for (int p = 0; p < count; ++p) {
    int best_x = 0, best_y = 0;
    double brightest = 0.0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (const double l = luminance_of(glm::dvec3(image.at(x, y))); l > brightest) {
          brightest = l;
          best_x = x;
          best_y = y;
        }
    if (!(brightest > kPeakContrast * mean)) break;
    const glm::dvec3 centre = environment_direction_precise((best_x + 0.5) / w, (best_y + 0.5) / h);
    glm::dvec3 power(0.0), moment(0.0);
    double weight = 0.0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const glm::dvec3 radiance(image.at(x, y));
        const double l = luminance_of(radiance);
        if (l < brightest / 64.0) continue;
        const glm::dvec3 d = environment_direction_precise((x + 0.5) / w, (y + 0.5) / h);
        if (glm::dot(d, centre) < reach) continue;
        const double dw = solid_angles[static_cast<std::size_t>(y)];
        power += radiance * dw;
        moment += l * dw * d;
        weight += l * dw;
        image.at(x, y) = glm::vec3(0.0f);
      }
    // An SG's mean cosine about its axis is coth(lambda) - 1 / lambda ~ 1 - 1 / lambda: the
    // sharpness of the source's own spread (at least the lattice's; a source within one texel
    // gets the texel's).
    const double mean_cosine = weight > 0.0 ? glm::length(moment) / weight : 1.0;
    const glm::dvec3 axis = weight > 0.0 ? glm::normalize(moment) : centre;
    const double lambda = std::clamp(1.0 / std::max(1.0 - mean_cosine, 1e-7), lattice_lambda, 1e6);
    SphericalGaussian g{axis, lambda, {}};
    g.amplitude = power / g.solid_angle();
    peaks.push_back(g);
  }
  return peaks;
}

Grid grid_of(const Image& full, int height) {
  const Image image = height == full.height() ? full : downsample_environment(full, height);
  Grid g;
  const int w = image.width(), h = image.height();
  for (int y = 0; y < h; ++y) {
    const double solid_angle = environment_row_solid_angle(y, h);
    for (int x = 0; x < w; ++x) {
      g.directions.push_back(environment_direction_precise((x + 0.5) / w, (y + 0.5) / h));
      g.radiance.push_back(glm::dvec3(image.at(x, y)));
      g.weights.push_back(solid_angle);
    }
  }
  return g;
}

}  // namespace

glm::dvec3 SphericalGaussian::value(const glm::dvec3& d) const {
  return amplitude * std::exp(sharpness * (glm::dot(axis, d) - 1.0));
}

double SphericalGaussian::solid_angle() const { return 2.0 * kPi * -std::expm1(-2.0 * sharpness) / sharpness; }

double SphericalGaussian::cone_half_angle_sine() const {
  const double cos_half = std::max(1.0 - solid_angle() / (2.0 * kPi), -1.0);
  return std::sqrt(1.0 - cos_half * cos_half);
}

std::array<SphericalGaussian::Cone, 3> SphericalGaussian::nested_cones() const {
  constexpr std::array<double, 3> quantiles = {1.0 / 3.0, 2.0 / 3.0, 0.95};
  std::array<double, 3> omega{}, ring_mean{};
  double previous_q = 0.0, previous_omega = 0.0;
  for (std::size_t j = 0; j < 3; ++j) {
    // 1 - cos theta = -ln(1 - q) / lambda, written so that a sharp lobe keeps its digits.
    const double one_minus_cos = std::min(-std::log1p(-quantiles[j]) / sharpness, 2.0);
    omega[j] = 2.0 * kPi * one_minus_cos;
    ring_mean[j] = (quantiles[j] - previous_q) / (omega[j] - previous_omega);
    previous_q = quantiles[j];
    previous_omega = omega[j];
  }
  std::array<Cone, 3> cones{};
  for (std::size_t j = 0; j < 3; ++j) {
    const double height = ring_mean[j] - (j < 2 ? ring_mean[j + 1] : 0.0);
    const double one_minus_cos = omega[j] / (2.0 * kPi);
    cones[j] = {std::sqrt(std::max(one_minus_cos * (2.0 - one_minus_cos), 0.0)), height * omega[j] / quantiles[2]};
  }
  return cones;
}

double SphericalGaussian::support_angle(double epsilon) const {
  const double a = luminance_of(amplitude);
  if (!(a > epsilon)) return 0.0;
  const double c = 1.0 + std::log(epsilon / a) / sharpness;
  return c <= -1.0 ? kPi : std::acos(c);
}

glm::dvec3 SphericalGaussianFit::radiance(const glm::dvec3& d) const {
  glm::dvec3 sum(0.0);
  for (const SphericalGaussian& g : lobes) sum += g.value(d);
  return sum;
}

SphericalGaussianFit SphericalGaussianFit::without_peaks() const {
  SphericalGaussianFit lattice = *this;
  lattice.lobes.erase(lattice.lobes.begin(), lattice.lobes.begin() + peaks);
  lattice.peaks = 0;
  return lattice;
}

std::vector<double> SphericalGaussianFit::lobe_probabilities() const {
  std::vector<double> p;
  double total = 0.0;
  for (const SphericalGaussian& g : lobes) {
    p.push_back(luminance_of(g.integral()));
    total += p.back();
  }
  for (double& v : p) v = total > 0.0 ? v / total : 1.0 / static_cast<double>(p.size());
  return p;
}

EnvironmentMap SphericalGaussianFit::to_map(int height) const {
  EnvironmentMap map{Image(2 * height, height), "spherical Gaussians"};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < 2 * height; ++x)
      map.radiance.at(x, y) =
          glm::vec3(glm::max(radiance(environment_direction_precise((x + 0.5) / (2 * height), (y + 0.5) / height)), 0.0));
  return map;
}

std::vector<glm::dvec3> fibonacci_directions(int count) {
  std::vector<glm::dvec3> out;
  const double golden = kPi * (3.0 - std::sqrt(5.0));  // the golden angle
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = golden * i;
    out.emplace_back(r * std::cos(phi), z, r * std::sin(phi));  // +y is the map's zenith
  }
  return out;
}

namespace {

// ||fit - map|| / ||map||, solid-angle weighted L2 over RGB, on the map's texels (at most 256 rows).
double relative_error_of(const SphericalGaussianFit& fit, const EnvironmentMap& map) {
  const Grid g = grid_of(map.radiance, std::min(map.radiance.height(), kErrorRows));
  double residual2 = 0.0, norm2 = 0.0;
  for (std::size_t i = 0; i < g.directions.size(); ++i) {
    const glm::dvec3 d = fit.radiance(g.directions[i]) - g.radiance[i];
    residual2 += g.weights[i] * glm::dot(d, d);
    norm2 += g.weights[i] * glm::dot(g.radiance[i], g.radiance[i]);
  }
  return norm2 > 0.0 ? std::sqrt(residual2 / norm2) : 0.0;
}

}  // namespace

SphericalGaussianFit fit_spherical_gaussians(const EnvironmentMap& map, int lobes, int grid_height) {
  if (lobes < 1 || lobes > 1024)
    throw InputError("spherical Gaussian lobes is " + std::to_string(lobes) + "; allowed: 1 .. 1024");
  if (grid_height < 2 || grid_height > map.radiance.height())
    throw InputError("the spherical Gaussian fit's grid height is " + std::to_string(grid_height) +
                     "; allowed: 2 .. the map's " + std::to_string(map.radiance.height()) + " rows");
  // The peaks first (up to an eighth of the lobes), then the lattice on what they leave.
  Image residual = map.radiance;
  const std::vector<SphericalGaussian> peaks =
      extract_peaks(residual, lobes / 8, static_cast<double>(lobes) / kPi);
  const int lattice = lobes - static_cast<int>(peaks.size());
  const Grid g = grid_of(residual, grid_height);
  const std::vector<glm::dvec3> axes = fibonacci_directions(lattice);
  const Eigen::Index n = static_cast<Eigen::Index>(g.directions.size()), k = lattice;
  Eigen::MatrixXd cosines(n, k);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < k; ++j) cosines(i, j) = glm::dot(g.directions[i], axes[j]);
  Eigen::MatrixXd target(n, 3);
  Eigen::VectorXd sqrt_w(n);
  double norm2 = 0.0;
  glm::dvec3 map_power(0.0);
  for (Eigen::Index i = 0; i < n; ++i) {
    map_power += g.radiance[i] * g.weights[i];
    sqrt_w(i) = std::sqrt(g.weights[i]);
    for (int c = 0; c < 3; ++c) target(i, c) = sqrt_w(i) * g.radiance[i][c];
    norm2 += target.row(i).squaredNorm();
  }

  // Sharpness: angular deviation 1 / sqrt(lambda) at most half the lattice's spacing sqrt(4 pi / K)
  // (lambda_0 = K / pi), then a geometric grid of sqrt(2) steps above it: no lobe wider than its
  // share of the sphere, which its shading as one cone (sec. 5.4's range query) needs.
  SphericalGaussianFit best;
  best.relative_error = HUGE_VAL;
  best.grid_height = grid_height;
  const double lambda0 = static_cast<double>(lattice) / kPi;
  for (int step = 0; step <= 8; ++step) {
    const double lambda = lambda0 * std::pow(2.0, 0.5 * step);
    const Eigen::MatrixXd basis = sqrt_w.asDiagonal() * ((cosines.array() - 1.0) * lambda).exp().matrix();
    const Eigen::MatrixXd normal = basis.transpose() * basis;
    const Eigen::MatrixXd rhs = basis.transpose() * target;
    Eigen::MatrixXd amplitudes(k, 3);
    for (int c = 0; c < 3; ++c) {
      amplitudes.col(c) = nonnegative_least_squares(normal, rhs.col(c));
      // Scaled so that the fit's power is the map's: the L2 fit is ruled by the brightest texels
      // (a small sun puts too much power into the lobes about it).
      const double fit_power = amplitudes.col(c).sum() * SphericalGaussian{{0, 0, 1}, lambda, {}}.solid_angle();
      if (fit_power > 0.0) amplitudes.col(c) *= map_power[c] / fit_power;
    }
    const double residual2 = (basis * amplitudes - target).squaredNorm();
    const double error = norm2 > 0.0 ? std::sqrt(residual2 / norm2) : 0.0;
    if (error < best.relative_error) {
      best.relative_error = error;
      best.lobes = peaks;
      best.peaks = static_cast<int>(peaks.size());
      for (Eigen::Index j = 0; j < k; ++j)
        best.lobes.push_back({axes[j], lambda, glm::dvec3(amplitudes(j, 0), amplitudes(j, 1), amplitudes(j, 2))});
    }
  }
  best.relative_error = relative_error_of(best, map);
  return best;
}

}  // namespace glintlab
