#include "tables/ltc/ltc_fit.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>
#include <span>
#include <stdexcept>
#include <thread>

#include <glm/geometric.hpp>

#include "tables/ltc/nelder_mead.hpp"

namespace glintlab {
namespace {

/// The centre of stratum k of an n x n grid over [0, 1)^2.
glm::dvec2 stratum(int k, int n) { return {(k % n + 0.5) / n, (k / n + 0.5) / n}; }

/// A point of stratum k shifted by a fixed hash: independent of the fitting samples' centres.
glm::dvec2 jittered_stratum(int k, int n) {
  auto hash = [](std::uint32_t x) {  // a 32-bit integer mix (lowbias32)
    x ^= x >> 16, x *= 0x7feb352dU, x ^= x >> 15, x *= 0x846ca68bU, x ^= x >> 16;
    return static_cast<double>(x) / 4294967296.0;
  };
  const auto u = static_cast<std::uint32_t>(k);
  return {(k % n + hash(2 * u + 1)) / n, (k / n + hash(2 * u + 2)) / n};
}

std::vector<glm::dvec3> half_vectors(const LtcTarget& target, int n) {
  std::vector<glm::dvec3> h(static_cast<std::size_t>(n * n));
  for (int k = 0; k < n * n; ++k) h[static_cast<std::size_t>(k)] = target.sample_half_vector(stratum(k, n));
  return h;
}

const std::vector<glm::dvec3>& cosine_directions(int n) {
  // One set per thread and n (the fitter uses one n): no locking.
  thread_local int cached_n = 0;
  thread_local std::vector<glm::dvec3> directions;
  if (cached_n != n) {
    directions.resize(static_cast<std::size_t>(n * n));
    for (int k = 0; k < n * n; ++k) directions[static_cast<std::size_t>(k)] = sample_cosine(stratum(k, n));
    cached_n = n;
  }
  return directions;
}

/// The target's samples with the lobe and its pdf there (fixed while M is fitted).
struct TargetSamples {
  std::vector<glm::dvec3> l;
  std::vector<LobeSample> lobe;
};

TargetSamples target_samples(const LtcTarget& target, std::span<const glm::dvec3> h) {
  TargetSamples s;
  s.l.reserve(h.size());
  s.lobe.reserve(h.size());
  for (const auto& hk : h) {
    s.l.push_back(target.reflect_view(hk));
    s.lobe.push_back(target.evaluate(s.l.back()));
  }
  return s;
}

LobeMoments moments_of(const LtcTarget& target, std::span<const glm::dvec3> h) {
  double magnitude = 0.0, fresnel = 0.0;
  glm::dvec3 direction(0.0);
  for (const auto& hk : h) {
    const glm::dvec3 l = target.reflect_view(hk);
    const LobeSample s = target.evaluate(l);
    if (!(s.value > 0.0)) continue;
    const double weight = s.value / s.pdf;
    const double schlick = std::pow(1.0 - std::clamp(glm::dot(target.view(), glm::normalize(target.view() + l)), 0.0, 1.0), 5.0);
    magnitude += weight;
    fresnel += weight * schlick;
    direction += weight * l;
  }
  const double count = static_cast<double>(h.size());
  LobeMoments m;
  // The ndf lobe's samples estimate its magnitude poorly (a count of samples inside the horizon, and
  // at normal incidence the horizon follows a row of strata): it has a smooth 1D form instead.
  m.magnitude = target.kind() == LtcTargetKind::Ndf ? ggx_ndf_lobe_magnitude(target.alpha(), target.view().z)
                                                     : magnitude / count;
  m.fresnel = fresnel / count;
  // The lobe is symmetric in y: its average direction lies in the xz plane.
  direction.y = 0.0;
  m.average_direction = glm::length(direction) > 0.0 ? glm::normalize(direction) : glm::dvec3(0.0, 0.0, 1.0);
  return m;
}

/// Sec. 4.3 of Heitz et al. 2016: the MIS-weighted cubic error of magnitude * D_o against the lobe.
double fitting_error(const LtcTarget& target, const TargetSamples& samples, std::span<const glm::dvec3> cosines,
                     const glm::dmat3& m, double magnitude) {
  const Ltc ltc(m);
  double error = 0.0;
  for (std::size_t k = 0; k < samples.l.size(); ++k) {
    const double d = ltc.density(samples.l[k]);
    const double e = std::abs(samples.lobe[k].value - magnitude * d);
    error += e * e * e / (d + samples.lobe[k].pdf);
  }
  for (const auto& w_o : cosines) {
    const glm::dvec3 l = glm::normalize(m * w_o);
    const double d = ltc.density_of_cosine_direction(w_o);
    const LobeSample s = target.evaluate(l);
    const double e = std::abs(s.value - magnitude * d);
    error += e * e * e / (d + s.pdf);
  }
  return error / static_cast<double>(samples.l.size() + cosines.size());
}

LtcCell fit_cell(const LtcTarget& target, const LtcFitSettings& settings, const LtcCell* start,
                 std::span<const glm::dvec3> fit_h, std::span<const glm::dvec3> moment_h) {
  LtcCell cell;
  cell.moments = moments_of(target, moment_h);
  const bool isotropic = target.view().z >= 1.0;
  if (isotropic) cell.moments.average_direction = {0.0, 0.0, 1.0};
  const TargetSamples samples = target_samples(target, fit_h);
  const std::vector<glm::dvec3>& cosines = cosine_directions(settings.samples);
  const glm::dvec3 z = cell.moments.average_direction;
  const double magnitude = cell.moments.magnitude;

  auto error_of = [&](const std::array<double, 3>& p) {
    // Outside these bounds M is degenerate for doubles; the simplex is pushed back.
    if (!(p[0] > -25.0 && p[0] < 5.0 && p[1] > -25.0 && p[1] < 5.0 && std::abs(p[2]) < 100.0))
      return std::numeric_limits<double>::max();
    const double e = fitting_error(target, samples, cosines, ltc_matrix(p, z), magnitude);
    return std::isfinite(e) ? e : std::numeric_limits<double>::max();
  };
  const std::array<double, 3> from = start ? start->params : std::array<double, 3>{0.0, 0.0, 0.0};
  constexpr double kStep = 0.1;
  if (isotropic) {
    const auto best = nelder_mead<1>([&](const std::array<double, 1>& p) { return error_of({p[0], p[0], 0.0}); },
                                     {from[0]}, kStep, settings.max_evaluations, settings.tolerance, &cell.error);
    cell.params = {best[0], best[0], 0.0};
  } else {
    cell.params = nelder_mead<3>(error_of, from, kStep, settings.max_evaluations, settings.tolerance, &cell.error);
  }
  cell.matrix = ltc_matrix(cell.params, z);
  return cell;
}

}  // namespace

double ltc_grid_alpha(int i, const LtcFitSettings& settings) {
  const double r = static_cast<double>(i) / (settings.size - 1);
  return std::max(r * r, settings.alpha_min);
}

double ltc_grid_cos_theta(int j, const LtcFitSettings& settings) {
  const double x = static_cast<double>(j) / (settings.size - 1);
  return std::max(1.0 - x * x, settings.cos_theta_min);
}

LobeMoments lobe_moments(const LtcTarget& target, int samples) { return moments_of(target, half_vectors(target, samples)); }

glm::dmat3 ltc_matrix(const std::array<double, 3>& params, const glm::dvec3& average_direction) {
  const glm::dvec3 z = average_direction;
  const glm::dvec3 x = glm::normalize(glm::dvec3(z.z, 0.0, -z.x));  // Y x Z with Y = (0, 1, 0)
  const double a = std::exp(params[0]), c = std::exp(params[1]);
  // Columns: M e_x = a X, M e_y = c Y, M e_z = a s X + Z.
  return {a * x, glm::dvec3(0.0, c, 0.0), a * params[2] * x + z};
}

LtcCell fit_ltc_cell(const LtcTarget& target, const LtcFitSettings& settings, const LtcCell* start) {
  return fit_cell(target, settings, start, half_vectors(target, settings.samples),
                  half_vectors(target, settings.moment_samples));
}

LtcFit fit_ltc_grid(LtcTargetKind kind, const LtcFitSettings& settings, const LtcProgressFn& progress, int threads) {
  if (settings.size < 2 || settings.samples < 1 || settings.moment_samples < 1)
    throw std::invalid_argument("LTC fit: size must be at least 2 and the sample counts at least 1");
  const int n = settings.size;
  LtcFit fit{kind, settings, std::vector<LtcCell>(static_cast<std::size_t>(n * n))};
  auto cell = [&](int i, int j) -> LtcCell& { return fit.cells[static_cast<std::size_t>(j * n + i)]; };
  const int total = n * n;
  std::mutex progress_mutex;
  int done = 0;
  auto report = [&](int cells) {
    if (!progress) return;
    const std::lock_guard lock(progress_mutex);
    done += cells;
    progress(done, total);
  };

  // The ndf lobe's half vectors follow D alone: one set per roughness, shared by its view angles.
  struct HalfVectors {
    std::vector<glm::dvec3> fit, moments;
  };
  auto ndf_half_vectors = [&](int i) {
    const LtcTarget t(kind, ltc_grid_alpha(i, settings), 1.0);
    return HalfVectors{half_vectors(t, settings.samples), half_vectors(t, settings.moment_samples)};
  };
  auto fit_one = [&](int i, int j, const LtcCell* start, const HalfVectors* ndf) {
    const LtcTarget t(kind, ltc_grid_alpha(i, settings), ltc_grid_cos_theta(j, settings));
    if (ndf) return fit_cell(t, settings, start, ndf->fit, ndf->moments);
    return fit_cell(t, settings, start, half_vectors(t, settings.samples), half_vectors(t, settings.moment_samples));
  };

  // Normal incidence, rough to smooth: each roughness starts from the rougher one.
  for (int i = n - 1; i >= 0; --i) {
    const HalfVectors ndf = kind == LtcTargetKind::Ndf ? ndf_half_vectors(i) : HalfVectors{};
    cell(i, 0) = fit_one(i, 0, i == n - 1 ? nullptr : &cell(i + 1, 0), kind == LtcTargetKind::Ndf ? &ndf : nullptr);
  }
  report(n);

  // Each roughness along the view angles: independent chains.
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&] {
    try {
      for (int i; (i = next.fetch_add(1)) < n;) {
        const HalfVectors ndf = kind == LtcTargetKind::Ndf ? ndf_half_vectors(i) : HalfVectors{};
        for (int j = 1; j < n; ++j)
          cell(i, j) = fit_one(i, j, &cell(i, j - 1), kind == LtcTargetKind::Ndf ? &ndf : nullptr);
        report(n - 1);
      }
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = n;
    }
  };
  const int workers = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return fit;
}

namespace {

/// ltc_fit_error with the target's jittered half vectors given (one set per roughness for ndf).
double fit_error_with(const LtcTarget& target, const Ltc& ltc, double magnitude, int samples,
                      std::span<const glm::dvec3> h) {
  if (!(magnitude > 0.0)) return 0.0;
  // Balance heuristic over N target samples and N LTC samples: sum of |g| / (N (pdf_t + pdf_ltc)).
  const int count = samples * samples;
  double sum = 0.0;
  auto add = [&](const glm::dvec3& l) {
    if (!(l.z > 0.0)) return;
    const LobeSample s = target.evaluate(l);
    const double d = ltc.density(l);
    const double pdf = s.pdf + d;
    if (pdf > 0.0) sum += std::abs(s.value - magnitude * d) / (count * pdf);
  };
  for (int k = 0; k < count; ++k) {
    const glm::dvec2 u = jittered_stratum(k, samples);
    add(target.reflect_view(h.empty() ? target.sample_half_vector(u) : h[static_cast<std::size_t>(k)]));
    add(ltc.sample(u));
  }
  return sum / magnitude;
}

std::vector<glm::dvec3> jittered_half_vectors(const LtcTarget& target, int n) {
  std::vector<glm::dvec3> h(static_cast<std::size_t>(n * n));
  for (int k = 0; k < n * n; ++k) h[static_cast<std::size_t>(k)] = target.sample_half_vector(jittered_stratum(k, n));
  return h;
}

}  // namespace

double ltc_fit_error(const LtcTarget& target, const Ltc& ltc, double magnitude, int samples) {
  return fit_error_with(target, ltc, magnitude, samples, {});
}

std::vector<double> ltc_fit_error_grid(const LtcFit& fit, int samples) {
  const int n = fit.settings.size;
  std::vector<double> errors(static_cast<std::size_t>(n * n));
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i; (i = next.fetch_add(1)) < n;) {  // one roughness at a time: ndf's half vectors shared
      const double alpha = ltc_grid_alpha(i, fit.settings);
      const std::vector<glm::dvec3> ndf_h = fit.kind == LtcTargetKind::Ndf
                                                ? jittered_half_vectors(LtcTarget(fit.kind, alpha, 1.0), samples)
                                                : std::vector<glm::dvec3>{};
      for (int j = 0; j < n; ++j) {
        const LtcTarget t(fit.kind, alpha, ltc_grid_cos_theta(j, fit.settings));
        const LtcCell& c = fit.cell(i, j);
        errors[static_cast<std::size_t>(j * n + i)] = fit_error_with(t, c.ltc(), c.moments.magnitude, samples, ndf_h);
      }
    }
  };
  const int workers = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  return errors;
}

}  // namespace glintlab
