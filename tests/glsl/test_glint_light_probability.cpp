// The probability that one facet reflects a light (shaders/glints/binomial/light_probability.glsl,
// Kneiphof & Klein 2024), p = integral over the light of D(h) / (4 |l.h|) dl / T, on the device
// against quadrature over the light in double precision, written here independently of the
// shaders: the D-only LTC estimate, the small-cap estimate, the blend kneiphof2024 uses, and the
// reference's numerical integral, over a sweep of light kinds, sizes, roughnesses and view and
// light angles. Prints the error table of docs/methods.md#kneiphof2024 ("Where the estimates switch").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "gl_fixture.hpp"
#include "tables/gpu_tables.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
const double kGl4Nodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
const double kGl4Weights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};

const std::vector<std::string> kKinds = {"sphere", "disk", "quad"};
const std::vector<double> kSolidAngles = {1e-4, 1e-3, 1e-2, 0.05, 0.2, 0.6};
const std::vector<double> kViewAngles = {0, 40, 70};  // degrees from the normal
const std::vector<double> kOffsets = {0, 15};          // the light's centre this far towards the normal from the mirror direction
const std::vector<double> kAlphas = {0.05, 0.1, 0.2, 0.4, 0.8};
constexpr double kDistance = 5;

struct Light {
  std::string kind;
  double solid_angle, view_deg, offset_deg;
  glm::dvec3 centre;  // from the shading point at the origin, normal +z
  double half_angle;  // of the cone of the light's solid angle
  double side;        // quads: the side of the square
};

std::vector<Light> sweep_lights() {
  std::vector<Light> lights;
  for (const auto& kind : kKinds)
    for (double omega : kSolidAngles)
      for (double view : kViewAngles)
        for (double offset : kOffsets) {
          const double elevation = (view - offset) * kPi / 180;
          const glm::dvec3 c = kDistance * glm::dvec3(-std::sin(elevation), 0, std::cos(elevation));
          const double gamma = std::acos(1 - omega / (2 * kPi));
          // A facing square of side a subtends 4 asin(a^2 / (a^2 + 4 d^2)).
          const double s4 = std::sin(omega / 4);
          lights.push_back({kind, omega, view, offset, c, gamma, 2 * kDistance * std::sqrt(s4 / (1 - s4))});
        }
  return lights;
}

std::string toml_of(const Light& l) {
  char buf[512];
  const glm::dvec3 c = l.centre, n = -glm::normalize(c);
  if (l.kind == "sphere")
    std::snprintf(buf, sizeof buf, "[[light]]\ntype = \"sphere\"\nposition = [%.9g, %.9g, %.9g]\nradius = %.9g\n", c.x, c.y, c.z,
                  kDistance * std::sin(l.half_angle));
  else if (l.kind == "disk")
    std::snprintf(buf, sizeof buf,
                  "[[light]]\ntype = \"disk\"\nposition = [%.9g, %.9g, %.9g]\ndirection = [%.9g, %.9g, %.9g]\nradius = %.9g\n",
                  c.x, c.y, c.z, n.x, n.y, n.z, kDistance * std::tan(l.half_angle));
  else
    std::snprintf(buf, sizeof buf,
                  "[[light]]\ntype = \"quad\"\nposition = [%.9g, %.9g, %.9g]\ndirection = [%.9g, %.9g, %.9g]\nsize = [%.9g, "
                  "%.9g]\nup = [0, 1, 0]\n",
                  c.x, c.y, c.z, n.x, n.y, n.z, l.side, l.side);
  return buf;
}

double ggx(double cos_h, double alpha) {
  const double a2 = alpha * alpha, t = cos_h * cos_h * (a2 - 1) + 1;
  return a2 / (kPi * t * t);
}

/// T = integral over the hemisphere of D, by quadrature in cos theta (independent of the closed form).
double total_ndf(double alpha) {
  double sum = 0;
  const int cells = 4096;
  for (int i = 0; i < cells; ++i)
    for (int a = 0; a < 4; ++a) {
      const double mu = (i + 0.5 + 0.5 * kGl4Nodes[a]) / cells;
      sum += 0.5 * kGl4Weights[a] * ggx(mu, alpha) / cells;
    }
  return 2 * kPi * sum;
}

/// D(h) / (4 |l.h|) for unit l above the horizon, view wo.
double integrand(const glm::dvec3& wo, const glm::dvec3& l, double alpha) {
  if (l.z <= 0) return 0;
  const glm::dvec3 h = glm::normalize(wo + l);
  return ggx(h.z, alpha) / (4 * std::abs(glm::dot(l, h)));
}

/// The integral over the light: its cone of directions for spheres and disks facing the point
/// (both subtend exactly the cone), the square's surface for quads.
double exact_integral(const Light& light, const glm::dvec3& wo, double alpha) {
  const int cells = 96;
  double sum = 0;
  const glm::dvec3 axis = glm::normalize(light.centre);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, glm::dvec3(0, 1, 0))), w = glm::cross(axis, u);
  if (light.kind != "quad") {
    // theta in [0, gamma] by 1 - cos (uniform in solid angle), phi in [0, 2 pi).
    const double one_minus_cos = 1 - std::cos(light.half_angle);
    for (int i = 0; i < cells; ++i)
      for (int j = 0; j < 2 * cells; ++j)
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b) {
            const double t = one_minus_cos * (i + 0.5 + 0.5 * kGl4Nodes[a]) / cells;
            const double phi = 2 * kPi * (j + 0.5 + 0.5 * kGl4Nodes[b]) / (2 * cells);
            const double cos_t = 1 - t, sin_t = std::sqrt(std::max(0.0, t * (2 - t)));
            const glm::dvec3 l = cos_t * axis + sin_t * (std::cos(phi) * u + std::sin(phi) * w);
            sum += 0.25 * kGl4Weights[a] * kGl4Weights[b] * integrand(wo, l, alpha);
          }
    return sum * 2 * kPi * one_minus_cos / (2.0 * cells * cells);
  }
  const glm::dvec3 up(0, 1, 0);
  const glm::dvec3 n = -axis;
  const glm::dvec3 x = glm::normalize(glm::cross(up, n)), y = glm::cross(n, x);
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const double s = light.side * (-0.5 + (i + 0.5 + 0.5 * kGl4Nodes[a]) / cells);
          const double t = light.side * (-0.5 + (j + 0.5 + 0.5 * kGl4Nodes[b]) / cells);
          const glm::dvec3 q = light.centre + s * x + t * y;
          const double r2 = glm::dot(q, q);
          const glm::dvec3 l = q / std::sqrt(r2);
          sum += 0.25 * kGl4Weights[a] * kGl4Weights[b] * integrand(wo, l, alpha) * std::abs(glm::dot(l, n)) / r2;
        }
  return sum * light.side * light.side / (cells * cells);
}

/// GLSL: the shading point at the origin (normal +z, view normalize(a.yzw), isotropic GGX of alpha
/// a.x, f0 = 1, no diffuse) and light b.x of the scene's buffer, for the evaluate() bodies below.
const char* kShadingPointAndLight = R"(
void shadingPointAndLight(vec4 a, vec4 b, out Surface s, out LightData L, out vec3 wo, out vec3 centreDir) {
  s.position = vec3(0.0);
  s.normal = vec3(0.0, 0.0, 1.0);
  s.tangent = vec3(1.0, 0.0, 0.0);
  s.bitangent = vec3(0.0, 1.0, 0.0);
  s.view = normalize(a.yzw);
  s.alpha = vec2(a.x);
  s.ndf = NDF_GGX;
  s.f0 = vec3(1.0);
  s.diffuse = vec3(0.0);
  L = lights[int(b.x)];
  wo = toLocal(s, s.view);
  centreDir = lightCentreDirection(L, s.position);
}
)";

/// Runs `body` on every (a, b) with the lights of `light_toml` in the scene's buffer (a light far
/// away from a tiny sphere: the scene exists for its lights) and the LTC tables bound.
std::vector<glm::vec4> evaluate_under_lights(const std::string& light_toml, const std::string& includes,
                                             const std::string& body, const std::vector<glm::vec4>& a,
                                             const std::vector<glm::vec4>& b) {
  TestScene scene;
  scene.material("m").sphere("m", {{"radius", 0.01}, {"translate", {0, -100, 0}}});
  scene.raw(light_toml);
  SceneFixture f(scene);
  f.gpu->bind_buffers();
  static GpuTables tables(test_table_cache());
  tables.require(std::vector<std::string>{"ltc-ggx", "ltc-ndf"});
  tables.bind();
  return evaluate_glsl(includes + kShadingPointAndLight, body, a, b);
}

struct Result {
  double exact, ltc, cap, used, numerical;
  double reused_ltc, reused_used;  // light_probability = ggx-ltc: the LTC estimate, and blended
};

/// Every light x roughness: (exact, LTC, cap, blend, the reference's numerical integral, the
/// reused GGX shape's LTC and blend) p.
const std::vector<std::pair<Light, std::vector<Result>>>& sweep() {
  static const auto results = [] {
    const auto lights = sweep_lights();
    std::string text;
    for (const auto& l : lights) text += toml_of(l);
    std::vector<glm::vec4> a, b;
    for (std::size_t i = 0; i < lights.size(); ++i)
      for (double alpha : kAlphas) {
        const double v = lights[i].view_deg * kPi / 180;
        a.emplace_back(static_cast<float>(alpha), static_cast<float>(std::sin(v)), 0.0f, static_cast<float>(std::cos(v)));
        b.emplace_back(static_cast<float>(i), 0, 0, 0);
      }
    const char* kIncludes = "#include \"glints/binomial/area_shading.glsl\"\n#include \"glints/binomial/light_ndf_integral.glsl\"\n";
    const char* kBody = R"(
vec4 evaluate(vec4 a, vec4 b) {
  Surface s;
  LightData L;
  vec3 wo, centreDir;
  shadingPointAndLight(a, b, s, L, wo, centreDir);
  GlintLtc ltc = glintLtc(s);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  if (b.y > 0.5) {  // the GGX lobe's LTC integral with the D-only magnitude (light_probability = ggx-ltc)
    vec3 p = glintProbabilityEstimates(s, ltc, L, wo, centreDir, solidAngle, ltcLightIntegral(ltcLightForm(s, L), L, ltc.ggxMinv));
    return vec4(p.x, mix(p.x, p.y, p.z), 0.0, 0.0);
  }
  vec3 p = glintProbabilityEstimates(s, ltc, L, wo, centreDir, solidAngle, ltcLightIntegral(ltcLightForm(s, L), L, ltc.ndfMinv));
  uint seed = hash3(uvec3(uint(b.x), uint(a.x * 1000.0), 7u));
  float numerical = lightNdfIntegral(s, L, wo, 0u, 128u, hashToUnit2(seed), hashToUnit2(pcgHash(seed + 1u))) /
                    ggxTotalNdf(a.x);
  return vec4(p.x, p.y, mix(p.x, p.y, p.z), numerical);
})";
    const auto got = evaluate_under_lights(text, kIncludes, kBody, a, b);
    for (auto& v : b) v.y = 1;
    const auto reused = evaluate_under_lights(text, kIncludes, kBody, a, b);
    std::vector<std::pair<Light, std::vector<Result>>> out;
    std::size_t k = 0;
    for (const auto& l : lights) {
      std::vector<Result> r;
      const double v = l.view_deg * kPi / 180;
      const glm::dvec3 wo(std::sin(v), 0, std::cos(v));
      for (double alpha : kAlphas) {
        const double exact = exact_integral(l, wo, alpha) / total_ndf(alpha);
        r.push_back({exact, got[k].x, got[k].y, got[k].z, got[k].w, reused[k].x, reused[k].y});
        ++k;
      }
      out.emplace_back(l, r);
    }
    return out;
  }();
  return results;
}

/// |estimate - exact| relative to the exact p, with a floor where the light misses the lobe.
double relative_error(double estimate, double exact) { return std::abs(estimate - exact) / std::max(exact, 1e-5); }

}  // namespace

TEST(GlintLightProbability, ErrorTableOverLightSizesAndRoughnesses) {
  // Mean relative error over kinds, view and light angles, per solid angle and roughness.
  std::printf("\n| solid angle (sr) |");
  for (double alpha : kAlphas) std::printf(" alpha %.2g: LTC / cap / used |", alpha);
  std::printf("\n| --- |");
  for (std::size_t i = 0; i < kAlphas.size(); ++i) std::printf(" --- |");
  std::printf("\n");
  std::map<std::pair<double, int>, std::array<double, 4>> sums;
  std::map<std::pair<double, int>, int> counts;
  for (const auto& [light, results] : sweep())
    for (std::size_t i = 0; i < results.size(); ++i) {
      const auto& r = results[i];
      auto& s = sums[{light.solid_angle, static_cast<int>(i)}];
      s[0] += relative_error(r.ltc, r.exact);
      s[1] += relative_error(r.cap, r.exact);
      s[2] += relative_error(r.used, r.exact);
      s[3] = std::max(s[3], relative_error(r.used, r.exact));
      ++counts[{light.solid_angle, static_cast<int>(i)}];
    }
  for (double omega : kSolidAngles) {
    std::printf("| %g |", omega);
    for (std::size_t i = 0; i < kAlphas.size(); ++i) {
      const auto& s = sums[{omega, static_cast<int>(i)}];
      const int n = counts[{omega, static_cast<int>(i)}];
      std::printf(" %.3f / %.3f / **%.3f** |", s[0] / n, s[1] / n, s[2] / n);
    }
    std::printf("\n");
  }
  // light_probability = ggx-ltc: the GGX lobe's LTC integral with the D-only magnitude.
  std::printf("\nggx-ltc (the GGX lobe's LTC integral, D-only magnitude):\n\n| solid angle (sr) |");
  for (double alpha : kAlphas) std::printf(" alpha %.2g: LTC / used |", alpha);
  std::printf("\n| --- |");
  for (std::size_t i = 0; i < kAlphas.size(); ++i) std::printf(" --- |");
  std::printf("\n");
  std::map<std::pair<double, int>, std::array<double, 2>> reused;
  for (const auto& [light, results] : sweep())
    for (std::size_t i = 0; i < results.size(); ++i) {
      auto& s = reused[{light.solid_angle, static_cast<int>(i)}];
      s[0] += relative_error(results[i].reused_ltc, results[i].exact);
      s[1] += relative_error(results[i].reused_used, results[i].exact);
    }
  double reused_total = 0, dedicated_total = 0;
  for (double omega : kSolidAngles) {
    std::printf("| %g |", omega);
    for (std::size_t i = 0; i < kAlphas.size(); ++i) {
      const auto key = std::make_pair(omega, static_cast<int>(i));
      const double n = counts[key];
      std::printf(" %.3f / **%.3f** |", reused[key][0] / n, reused[key][1] / n);
      reused_total += reused[key][1] / n;
      dedicated_total += sums[key][2] / n;
    }
    std::printf("\n");
  }
  const double cells = double(kSolidAngles.size() * kAlphas.size());
  std::printf("\nmean over the table of the used p's error: ndf-ltc %.4f, ggx-ltc %.4f\n", dedicated_total / cells,
              reused_total / cells);
  // The GGX lobe's shape is not D / (4 |l.h|)'s: the dedicated table is the more accurate (the test
  // can fail if the reuse were free).
  EXPECT_LT(dedicated_total, reused_total);
  // The mean errors (LTC, cap, used) of one cell of the table.
  const auto mean = [&](double omega, std::size_t i) {
    const auto key = std::make_pair(omega, static_cast<int>(i));
    const double n = counts[key];
    return glm::dvec3(sums[key][0] / n, sums[key][1] / n, sums[key][2] / n);
  };
  for (std::size_t i = 0; i < kAlphas.size(); ++i) {
    // The cap is exact in the limit of a small light; the LTC wins for large lights on sharp lobes.
    EXPECT_LT(mean(kSolidAngles.front(), i).y, 0.005) << "alpha " << kAlphas[i];
    for (std::size_t j = 1; j < kSolidAngles.size(); ++j)
      EXPECT_GE(mean(kSolidAngles[j], i).y, mean(kSolidAngles[j - 1], i).y) << "the cap's error grows, alpha " << kAlphas[i];
    for (double omega : kSolidAngles) {
      const glm::dvec3 e = mean(omega, i);
      // The blend is never much worse than the better estimate, and within 11% on average anywhere.
      EXPECT_LE(e.z, std::min(e.x, e.y) + 0.015) << "alpha " << kAlphas[i] << " solid angle " << omega;
      EXPECT_LT(e.z, 0.11) << "alpha " << kAlphas[i] << " solid angle " << omega;
      if (omega >= 0.05 && kAlphas[i] <= 0.2) {
        EXPECT_LT(e.x, e.y) << "alpha " << kAlphas[i] << " solid angle " << omega;
      }
    }
  }
}

TEST(GlintLightProbability, TheReferencesNumericalIntegralIsConverged) {
  // The binomial-glints reference's p (128 samples of each strategy, shaders/passes/reference.glsl)
  // against quadrature, wherever a facet reflects with p >= 1e-4 (sparser glints are ~invisible).
  double worst = 0, sum = 0;
  int n = 0;
  for (const auto& [light, results] : sweep())
    for (const auto& r : results) {
      if (r.exact < 1e-4) continue;
      const double e = relative_error(r.numerical, r.exact);
      worst = std::max(worst, e);
      sum += e;
      ++n;
    }
  std::printf("reference p: mean relative error %.2g, max %.2g over %d cases with p >= 1e-4\n", sum / n, worst, n);
  EXPECT_LT(sum / n, 0.01);
  EXPECT_LT(worst, 0.1);
}

namespace {

// A planar light that is small in solid angle but long in one direction, or a disk seen nearly
// edge-on, at distance 2 in the mirror direction of a view 40 degrees from the normal.
struct ThinLight {
  std::string name, kind;      // quad or disk
  glm::dvec3 centre, normal;   // from the shading point at the origin (normal +z)
  glm::dvec2 size;             // quads: the sides along (u, v); disks: the radius twice
};

const glm::dvec3 kThinView(std::sin(40 * kPi / 180), 0, std::cos(40 * kPi / 180));

std::vector<ThinLight> thin_lights() {
  const glm::dvec3 c = 2.0 * glm::dvec3(-kThinView.x, 0, kThinView.z), facing = -glm::normalize(c);
  // Tilted 80 degrees about y from facing the point: seen nearly edge-on.
  const double t = 80 * kPi / 180;
  const glm::dvec3 tilted(facing.x * std::cos(t) + facing.z * std::sin(t), 0, -facing.x * std::sin(t) + facing.z * std::cos(t));
  // In the GPU scene's order, kind by kind as registered (src/render/gpu_scene.cpp): disks first.
  return {{"disk of radius 0.5 seen 80 degrees off its axis", "disk", c, tilted, {1.0, 1.0}},
          {"quad 2 x 0.02 along the plane of incidence", "quad", c, facing, {2.0, 0.02}},
          {"quad 2 x 0.05 along the plane of incidence", "quad", c, facing, {2.0, 0.05}},
          {"quad 0.02 x 2 across it", "quad", c, facing, {0.02, 2.0}}};
}

// The quad's half-edge directions as the scene parser builds them with up = +y (src/scene/lights/quad.cpp).
void planar_axes(const ThinLight& l, glm::dvec3& u, glm::dvec3& v) {
  u = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), l.normal));
  v = glm::cross(l.normal, u);
}

// GGX's height-correlated Smith G2, written here from its definition (Heitz 2014, eq. 99).
double smith_g2(const glm::dvec3& wo, const glm::dvec3& wi, double alpha) {
  const auto lambda = [&](const glm::dvec3& w) {
    const double tan2 = std::max(0.0, 1 - w.z * w.z) / (w.z * w.z);
    return 0.5 * (-1 + std::sqrt(1 + alpha * alpha * tan2));
  };
  return 1 / (1 + lambda(wo) + lambda(wi));
}

// Over the light's surface: (p x T, the integral of f cos with F = 1), Gauss-Legendre on a fine grid.
glm::dvec2 thin_light_integrals(const ThinLight& l, double alpha) {
  glm::dvec3 u, v;
  planar_axes(l, u, v);
  const int cells = 400;
  glm::dvec2 sum(0);
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const double x = (i + 0.5 + 0.5 * kGl4Nodes[a]) / cells, y = (j + 0.5 + 0.5 * kGl4Nodes[b]) / cells;
          glm::dvec3 q;
          double area;  // per unit of (x, y)
          if (l.kind == "quad") {
            q = l.centre + (x - 0.5) * l.size.x * u + (y - 0.5) * l.size.y * v;
            area = l.size.x * l.size.y;
          } else {  // polar: r = R x, phi = 2 pi y
            const double r = 0.5 * l.size.x * x, phi = 2 * kPi * y;
            q = l.centre + r * (std::cos(phi) * u + std::sin(phi) * v);
            area = 2 * kPi * r * 0.5 * l.size.x;
          }
          const double r2 = glm::dot(q, q);
          const glm::dvec3 wi = q / std::sqrt(r2);
          if (wi.z <= 0) continue;
          const double dl = 0.25 * kGl4Weights[a] * kGl4Weights[b] * area * std::abs(glm::dot(wi, l.normal)) / r2;
          const glm::dvec3 h = glm::normalize(kThinView + wi);
          sum.x += dl * integrand(kThinView, wi, alpha);
          sum.y += dl * ggx(h.z, alpha) * smith_g2(kThinView, wi, alpha) / (4 * kThinView.z);
        }
  return sum / double(cells * cells);
}

}  // namespace

TEST(GlintLightProbability, ALongThinLightIsNotSmall) {
  // Small in solid angle (0.01-0.03 sr) but long against the lobe: the small-cap estimate and the
  // point form (the BRDF at the centre x solid angle) are wrong there, by the NDF across the light.
  // The method decides from the light's largest angular extent, so it takes the LTC's p and
  // integral; against quadrature over the light's surface.
  const auto lights = thin_lights();
  const std::vector<double> alphas = {0.1, 0.2};
  std::string text;
  char buf[512];
  for (const auto& l : lights) {
    if (l.kind == "quad")
      std::snprintf(buf, sizeof buf,
                    "[[light]]\ntype = \"quad\"\nposition = [%.9g, %.9g, %.9g]\ndirection = [%.9g, %.9g, %.9g]\nsize = "
                    "[%.9g, %.9g]\nup = [0, 1, 0]\n",
                    l.centre.x, l.centre.y, l.centre.z, l.normal.x, l.normal.y, l.normal.z, l.size.x, l.size.y);
    else
      std::snprintf(buf, sizeof buf,
                    "[[light]]\ntype = \"disk\"\nposition = [%.9g, %.9g, %.9g]\ndirection = [%.9g, %.9g, %.9g]\nradius = %.9g\n",
                    l.centre.x, l.centre.y, l.centre.z, l.normal.x, l.normal.y, l.normal.z, 0.5 * l.size.x);
    text += buf;
  }
  std::vector<glm::vec4> a, b;
  for (std::size_t i = 0; i < lights.size(); ++i)
    for (double alpha : alphas) {
      a.emplace_back(static_cast<float>(alpha), glm::vec3(kThinView));
      b.emplace_back(static_cast<float>(i), 0, 0, 0);
    }
  const auto got = evaluate_under_lights(text, "#include \"glints/binomial/area_shading.glsl\"\n", R"(
vec4 evaluate(vec4 a, vec4 b) {
  Surface s;
  LightData L;
  vec3 wo, centreDir;
  shadingPointAndLight(a, b, s, L, wo, centreDir);
  float solidAngle = lightSolidAngle(L, s.position, centreDir);
  GlintLtc ltc = glintLtc(s);
  vec3 p = glintProbabilityEstimates(s, ltc, L, wo, centreDir, solidAngle, ltcLightIntegral(ltcLightForm(s, L), L, ltc.ndfMinv));
  GlintLightIntegral g = glintLightIntegral(s, ltc, L, ltcLightForm(s, L), wo, centreDir, solidAngle, false);
  return vec4(g.p, p.y, p.z, g.specular.r);
})", a, b);
  std::size_t k = 0;
  for (const auto& l : lights)
    for (double alpha : alphas) {
      const glm::dvec2 exact = thin_light_integrals(l, alpha);
      const double p = exact.x / total_ndf(alpha);
      const auto& r = got[k++];
      std::printf("%s, alpha %.2g: p %.4g (cap %.4g, weight of the cap %.2f) against %.4g; specular %.4g against %.4g\n",
                  l.name.c_str(), alpha, r.x, r.y, r.z, p, r.w, exact.y);
      EXPECT_LT(r.z, 0.05) << l.name << ", alpha " << alpha << ": the LTC decides";
      EXPECT_LT(relative_error(r.x, p), 0.1) << l.name << ", alpha " << alpha;
      EXPECT_NEAR(r.w, exact.y, 0.1 * exact.y) << l.name << ", alpha " << alpha;
      // The small cap is far off here (the test can fail when the decision is the solid angle's).
      EXPECT_GT(relative_error(r.y, p), 0.2) << l.name << ", alpha " << alpha;
    }
}
