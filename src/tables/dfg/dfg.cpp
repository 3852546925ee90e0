#include "tables/dfg/dfg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace glintlab {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// |w.z| Lambda(w) of the isotropic NDF from z = |w.z|, in brdf.glsl's smithLambdaCosOfS2 form
/// (Heitz 2014, eqs. 72 and 80; Beckmann by Walter et al. 2007's rational fit, eq. 27).
double lambda_cos(DfgNdf ndf, double z, double alpha) {
  const double s2 = alpha * alpha * std::max(0.0, 1 - z * z);
  if (ndf == DfgNdf::Beckmann) {
    const double s = std::sqrt(s2);
    if (z >= 1.6 * s) return 0;
    const double b = z / s;
    return s * (1 - 1.259 * b + 0.396 * b * b) / (3.535 + 2.181 * b);
  }
  const double d = z + std::sqrt(z * z + s2);
  return d > 0 ? 0.5 * s2 / d : 0;
}

/// Gauss-Legendre nodes and weights on [0, 1] (Newton's method on P_n from the Chebyshev guess).
struct GaussLegendre {
  std::vector<double> nodes, weights;
  explicit GaussLegendre(int n) {
    for (int k = 0; k < n; ++k) {
      double x = std::cos(kPi * (k + 0.75) / (n + 0.5)), derivative = 1;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1, p1 = x;  // P_0, P_1, then the recurrence (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1}
        for (int j = 1; j < n; ++j) {
          const double p2 = ((2 * j + 1) * x * p1 - j * p0) / (j + 1);
          p0 = p1;
          p1 = p2;
        }
        derivative = n * (x * p1 - p0) / (x * x - 1);
        const double step = p1 / derivative;
        x -= step;
        if (std::abs(step) < 1e-15) break;
      }
      nodes.push_back(0.5 * (1 - x));
      weights.push_back(1 / ((1 - x * x) * derivative * derivative));  // 2 / ((1 - x^2) P_n'^2), halved
    }
  }
};

/// The half vector's polar angle as theta_h = atan(alpha tan(pi q / 2)), q in [0, 1): uniform
/// steps in q resolve both the lobe's peak (q ~ 1/2 is tan(theta_h) = alpha) and its tail. Returns
/// tan(pi q / 2) and the density du/dq of the CDF u of D(h) (n.h) over theta_h (Walter et al.
/// 2007, eqs. 28 and 35: u = t^2 / (1 + t^2) for GGX, 1 - exp(-t^2) for Beckmann, t = tan / alpha).
double cdf_density(DfgNdf ndf, double q, double& t) {
  const double angle = 0.5 * kPi * q;
  t = std::tan(angle);
  if (ndf == DfgNdf::Ggx) return 0.5 * kPi * std::sin(kPi * q);
  return 2 * t * std::exp(-t * t) * 0.5 * kPi * (1 + t * t);
}

}  // namespace

DfgTerms dfg_terms(DfgNdf ndf, double cos_o, double alpha, int theta_points, int phi_points) {
  alpha = std::max(alpha, kDfgAlphaMin);
  cos_o = std::clamp(cos_o, 1e-6, 1.0);
  const double sin_o = std::sqrt(1 - cos_o * cos_o);
  const double lambda_o = lambda_cos(ndf, cos_o, alpha);
  const GaussLegendre rule(theta_points);
  // E = (1 / 2 pi) int dphi int du w with h ~ D(h) (n.h) (the CDF u), where l = reflect(-o, h) has
  // the density D (n.h) / (4 o.h), so that w = f cos_i / pdf = G2 (o.h) / (cos_o (n.h)), G2 / cos_o
  // as brdf.glsl's smithG2OverCosOfLambdaCos (Heitz 2014, eq. 99). At azimuth phi, l.z =
  // R cos(2 theta_h - delta) with tan(delta) = sin_o cos(phi) / cos_o, so l is above the horizon
  // (and o.h > 0) exactly for theta_h < delta / 2 + pi / 4: the inner integral ends there, where
  // w falls continuously to 0, and Gauss-Legendre meets no kink. The integrand is even in phi.
  DfgTerms sum;
  for (int p = 0; p < phi_points; ++p) {
    const double phi = kPi * (p + 0.5) / phi_points, cos_phi = std::cos(phi);
    const double theta_max = 0.5 * std::atan2(sin_o * cos_phi, cos_o) + 0.25 * kPi;
    const double q_max = 2 / kPi * std::atan(std::tan(theta_max) / alpha);
    for (int k = 0; k < theta_points; ++k) {
      double t;
      const double q = q_max * rule.nodes[static_cast<std::size_t>(k)];
      const double density = cdf_density(ndf, q, t) * q_max * rule.weights[static_cast<std::size_t>(k)];
      const double tan_h = alpha * t, cos_h = 1 / std::sqrt(1 + tan_h * tan_h), sin_h = tan_h * cos_h;
      const double o_dot_h = sin_o * sin_h * cos_phi + cos_o * cos_h;
      const double cos_i = 2 * o_dot_h * cos_h - cos_o;  // (2 (o.h) h - o).z
      if (o_dot_h <= 0 || cos_i <= 0) continue;
      const double g2_over_cos = 1 / (cos_o + lambda_o + lambda_cos(ndf, cos_i, alpha) * cos_o / cos_i);
      const double weight = density * o_dot_h / cos_h * g2_over_cos;
      const double m = 1 - o_dot_h, fresnel = m * m * m * m * m;
      sum.a += weight * (1 - fresnel);
      sum.b += weight * fresnel;
    }
  }
  return {sum.a / phi_points, sum.b / phi_points};
}

std::string dfg_table_settings() {
  char text[160];
  std::snprintf(text, sizeof text, "size=%d alpha_min=%.9g theta_points=%d phi_points=%d", kDfgTableSize, kDfgAlphaMin,
                kDfgThetaPoints, kDfgPhiPoints);
  return text;
}

std::vector<float> generate_dfg_table(const std::function<void(int, int)>& progress) {
  std::vector<float> values(dfg_table_value_count());
  for (int j = 0; j < kDfgTableSize; ++j) {
    for (int i = 0; i < kDfgTableSize; ++i) {
      const DfgTerms ggx = dfg_terms(DfgNdf::Ggx, dfg_cos_o(i), dfg_alpha(j));
      const DfgTerms beckmann = dfg_terms(DfgNdf::Beckmann, dfg_cos_o(i), dfg_alpha(j));
      float* texel = values.data() + dfg_texel(i, j);
      texel[0] = static_cast<float>(ggx.a);
      texel[1] = static_cast<float>(ggx.b);
      texel[2] = static_cast<float>(beckmann.a);
      texel[3] = static_cast<float>(beckmann.b);
    }
    if (progress) progress(j + 1, kDfgTableSize);
  }
  return values;
}

}  // namespace glintlab
