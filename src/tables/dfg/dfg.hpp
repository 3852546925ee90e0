#pragma once
// The split-sum's second factor (Karis 2013, "Real Shading in Unreal Engine 4"): the directional
// albedo of glintlab's specular BRDF, f = D G2 F / (4 cos_o cos_i) with the height-correlated
// Smith G2 and Schlick's F of shaders/core/brdf.glsl (isotropic GGX or Beckmann). With
// F = f0 + (1 - f0)(1 - o.h)^5, its integral over the hemisphere of l is
//     E(cos_o, alpha, f0) = f0 A + B,
//     A = int f_{F=1} cos_i (1 - (1 - o.h)^5) d omega_i,  B = int f_{F=1} cos_i (1 - o.h)^5 d omega_i.
//
// Table layout (the contract with shaders/lobe/dfg.glsl): kDfgTableSize^2 RGBA texels, float
// (i, j, channel) at (j kDfgTableSize + i) 4 + channel, uploaded as a 2D texture with x = i, y = j:
// * texel centres: cos_o = (i + 0.5) / kDfgTableSize, perceptual roughness
//   r = (j + 0.5) / kDfgTableSize with alpha = max(r^2, kDfgAlphaMin), so that the texture
//   coordinate of (cos_o, alpha) is (cos_o, sqrt(alpha)) itself;
// * channels (A_ggx, B_ggx, A_beckmann, B_beckmann).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace glintlab {

enum class DfgNdf { Ggx, Beckmann };

inline constexpr int kDfgTableSize = 32;
/// The shaders' MIN_ALPHA (shaders/core/constants.glsl), below which the BRDF clamps alpha.
inline constexpr double kDfgAlphaMin = 1e-4;
/// Quadrature points per texel and NDF: kDfgThetaPoints (Gauss-Legendre, in theta_h) x
/// kDfgPhiPoints (midpoints over half the circle of azimuths).
inline constexpr int kDfgThetaPoints = 64;
inline constexpr int kDfgPhiPoints = 64;

struct DfgTerms {
  double a = 0;  ///< the Fresnel-weighted part, times f0
  double b = 0;  ///< the part independent of f0
};

/// A and B at (cos_o, alpha) by deterministic quadrature over the half vector h, in double: at
/// each of phi_points azimuths, Gauss-Legendre of theta_points nodes in
/// q = (2 / pi) atan(tan(theta_h) / alpha) up to the horizon of l = reflect(-o, h).
DfgTerms dfg_terms(DfgNdf ndf, double cos_o, double alpha, int theta_points = kDfgThetaPoints,
                   int phi_points = kDfgPhiPoints);

[[nodiscard]] constexpr std::size_t dfg_table_value_count() {
  return std::size_t{kDfgTableSize} * kDfgTableSize * 4;
}
/// The index of channel 0 of texel (i, j).
[[nodiscard]] constexpr std::size_t dfg_texel(int i, int j) {
  return (static_cast<std::size_t>(j) * kDfgTableSize + i) * 4;
}
[[nodiscard]] constexpr double dfg_cos_o(int i) { return (i + 0.5) / kDfgTableSize; }
[[nodiscard]] constexpr double dfg_alpha(int j) {
  const double r = (j + 0.5) / kDfgTableSize;
  return r * r > kDfgAlphaMin ? r * r : kDfgAlphaMin;
}

/// The settings the values depend on, "name=value ..." (what keys the table cache).
std::string dfg_table_settings();
/// The table in the layout above, reporting one step per roughness row.
std::vector<float> generate_dfg_table(const std::function<void(int done, int total)>& progress = {});

}  // namespace glintlab
