#pragma once
// Our fitter of linearly transformed cosines to a target lobe (Heitz, Dupuy, Hill, Neubelt 2016,
// sec. 4): per cell of a (roughness, view angle) grid, the matrix M whose LTC, scaled by the
// lobe's magnitude, best matches the lobe (src/tables/ltc/ltc_targets.hpp).
//
// * Parameters: M = [X Y Z] diag-ish S with Z the lobe's average direction (in the xz plane),
//   X = Y x Z, and S = ((a, 0, a s), (0, c, 0), (0, 0, 1)) (rows); Nelder-Mead over (ln a, ln c, s).
//   At normal incidence the lobe is isotropic: c = a, s = 0, one parameter.
// * Error (sec. 4.3): sum over samples of |f - f_ltc|^3 / (pdf_ltc + pdf_target), f_ltc =
//   magnitude * D_o, with samples drawn from both the LTC and the target's sampler (n x n
//   stratified each, multiple importance sampling).
// * Order: the normal-incidence column from rough to smooth, each cell started from the rougher
//   one; then, per roughness, the view angles in order, each started from the previous one. The
//   roughnesses are independent chains, fitted in parallel; the result does not depend on the
//   thread count.
#include <array>
#include <functional>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "tables/ltc/ltc.hpp"
#include "tables/ltc/ltc_targets.hpp"

namespace glintlab {

struct LtcFitSettings {
  int size = 64;               ///< grid cells per side (roughness x view angle)
  int samples = 32;            ///< n: n x n stratified samples per strategy in the fitting error
  int moment_samples = 64;     ///< m x m samples for magnitude, Fresnel term and average direction
  double alpha_min = 1e-4;     ///< alpha = max(r^2, alpha_min): the shaders' MIN_ALPHA
  double cos_theta_min = 1e-3; ///< the grazing row is fitted at this cos(theta_v) (theta < 89.95 deg)
  int max_evaluations = 150;   ///< Nelder-Mead budget per cell
  double tolerance = 1e-4;     ///< Nelder-Mead stops when the simplex's errors agree to this (relative)
};

/// The cell grid's coordinates (the tables' contract, src/tables/ltc/ltc_table.hpp): roughness index i
/// gives r = i / (size - 1) and alpha = max(r^2, alpha_min); view index j gives
/// cos(theta_v) = 1 - (j / (size - 1))^2, at least cos_theta_min.
double ltc_grid_alpha(int i, const LtcFitSettings& settings);
double ltc_grid_cos_theta(int j, const LtcFitSettings& settings);

/// The lobe's integrals the tables store next to the matrix: by m x m target samples, except the ndf
/// lobe's magnitude (ggx_ndf_lobe_magnitude).
struct LobeMoments {
  double magnitude = 0.0;        ///< integral over l.z > 0 of the lobe
  double fresnel = 0.0;          ///< the same weighted by (1 - v.h)^5 (Schlick's term; sampled, ggx only stores it)
  glm::dvec3 average_direction;  ///< normalize(integral of the lobe times l)
};
LobeMoments lobe_moments(const LtcTarget& target, int samples);

struct LtcCell {
  std::array<double, 3> params{0.0, 0.0, 0.0};  ///< (ln a, ln c, s), see the file comment
  glm::dmat3 matrix{1.0};                       ///< M
  LobeMoments moments;
  double error = 0.0;  ///< the fitting error at the optimum (samples-dependent; not the fit error)
  [[nodiscard]] Ltc ltc() const { return Ltc(matrix); }
};

/// M of the parameters in the frame of the average direction.
glm::dmat3 ltc_matrix(const std::array<double, 3>& params, const glm::dvec3& average_direction);

/// Fits one cell, started from `start` (a neighbour's parameters), or from the identity.
LtcCell fit_ltc_cell(const LtcTarget& target, const LtcFitSettings& settings, const LtcCell* start = nullptr);

struct LtcFit {
  LtcTargetKind kind = LtcTargetKind::Ggx;
  LtcFitSettings settings;
  std::vector<LtcCell> cells;  ///< cell (i, j) at j * size + i
  [[nodiscard]] const LtcCell& cell(int i, int j) const { return cells[static_cast<std::size_t>(j * settings.size + i)]; }
};

/// (cells done, cells): called one call at a time, from any thread.
using LtcProgressFn = std::function<void(int done, int total)>;
/// The whole grid, on every hardware thread (`threads` > 0: that many).
LtcFit fit_ltc_grid(LtcTargetKind kind, const LtcFitSettings& settings, const LtcProgressFn& progress = {},
                    int threads = 0);

/// The fit error of an LTC lobe against its target: the relative L1 distance
///   int_{l.z > 0} |f(l) - magnitude D_o(l)| dl / magnitude,
/// integrated by 2 x n x n stratified samples of both lobes (balance heuristic), independent of the
/// fitting samples. Over the upper hemisphere: the runtime clips lights to the horizon.
double ltc_fit_error(const LtcTarget& target, const Ltc& ltc, double magnitude, int samples = 128);
/// Every cell's fit error, j * size + i (on every hardware thread).
std::vector<double> ltc_fit_error_grid(const LtcFit& fit, int samples = 128);

}  // namespace glintlab
