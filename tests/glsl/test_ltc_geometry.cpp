// The LTC integrals of shaders/ltc/ltc.glsl on the GL device against quadrature over the
// light's surface in double precision, written here independently of the shaders: polygons above
// and across the horizon, and disks (circular and elliptic cones), for the identity (Lambert form
// factors) and for lobes as sharp as the tables hold.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/glm.hpp>
#include <random>
#include <string>
#include <vector>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const double kGl4Nodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
const double kGl4Weights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};

/// The LTC distribution of the clamped cosine mapped by M (given M^-1), at the unit direction w
/// (Heitz et al. 2016, eq. 3): D_o(w) = D_cos(M^-1 w / |M^-1 w|) |det M^-1| / |M^-1 w|^3, above the
/// surface's horizon (the disks tested lie above it).
double ltc_density(const glm::dmat3& Minv, const glm::dvec3& w) {
  const glm::dvec3 m = Minv * w;
  if (w.z < 0) return 0;  // below the surface's horizon, where the runtime clips polygons too
  const double len = glm::length(m);
  return std::max(m.z / len, 0.0) / M_PI * std::abs(glm::determinant(Minv)) / (len * len * len);
}

/// Integral of D_o over the directions of the parallelogram c + s u + t w (s, t in [-1, 1]) seen
/// from the origin: 96 x 96 cells of 4 x 4 Gauss-Legendre points of D_o cos / r^2 dA.
double parallelogram_integral(const glm::dmat3& Minv, glm::dvec3 c, glm::dvec3 u, glm::dvec3 w) {
  const glm::dvec3 n = glm::normalize(glm::cross(u, w));
  const double area = 4 * glm::length(glm::cross(u, w));
  const int cells = 96;
  double sum = 0;
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const double s = -1 + (2 * i + 1 + kGl4Nodes[a]) / cells, t = -1 + (2 * j + 1 + kGl4Nodes[b]) / cells;
          const glm::dvec3 p = c + s * u + t * w;
          const double r2 = glm::dot(p, p);
          const glm::dvec3 dir = p / std::sqrt(r2);
          sum += kGl4Weights[a] * kGl4Weights[b] / 4 * ltc_density(Minv, dir) * std::abs(glm::dot(dir, n)) / r2;
        }
  return sum * area / (cells * cells);
}

/// The same over the disk c + r (cos phi u + sin phi w), u, w orthonormal: polar cells.
double disk_integral(const glm::dmat3& Minv, glm::dvec3 c, glm::dvec3 u, glm::dvec3 w, double radius) {
  const glm::dvec3 n = glm::cross(u, w);
  const int rings = 96, sectors = 192;
  double sum = 0;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sectors; ++j)
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const double rho = radius * (i + 0.5 + 0.5 * kGl4Nodes[a]) / rings;
          const double phi = 2 * M_PI * (j + 0.5 + 0.5 * kGl4Nodes[b]) / sectors;
          const glm::dvec3 p = c + rho * (std::cos(phi) * u + std::sin(phi) * w);
          const double r2 = glm::dot(p, p);
          const glm::dvec3 dir = p / std::sqrt(r2);
          const double dA = rho * (radius / rings) * (2 * M_PI / sectors) * kGl4Weights[a] * kGl4Weights[b] / 4;
          sum += ltc_density(Minv, dir) * std::abs(glm::dot(dir, n)) / r2 * dA;
        }
  return sum;
}

/// Inverse matrices of lobes from the identity to sharp (1 / 0.02) and skewed, with det > 0, and a
/// mirror-like one.
std::vector<glm::dmat3> lobe_matrices() {
  std::vector<glm::dmat3> out = {glm::dmat3(1.0)};
  for (double sharp : {2.0, 10.0, 50.0})
    for (double skew : {0.0, 0.7}) {
      glm::dmat3 m(1.0);
      m[0][0] = sharp;         // column 0, row 0
      m[1][1] = sharp * 0.8;   // column 1, row 1
      m[2][0] = -skew * sharp; // column 2, row 0: tilts the lobe towards -x
      out.push_back(m);
    }
  // A mirror-like lobe as the tables store it (M^-1 / m11 = diag(1, 1, ~alpha)): a light off the
  // mirror direction maps to a sliver of a cone along the horizon.
  glm::dmat3 mirror(1.0);
  mirror[2][2] = 1e-4;
  out.push_back(mirror);
  return out;
}

struct Polygon {
  glm::dvec3 c, u, w;
};

}  // namespace

TEST(LtcGeometry, PolygonIntegralsMatchQuadratureAboveAndAcrossTheHorizon) {
  const std::vector<Polygon> quads = {
      {{0.0, 0.0, 2.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}},      // overhead, facing down
      {{1.5, 0.5, 1.0}, {0.3, 0.4, 0.0}, {0.0, 0.2, 0.5}},      // tilted, off axis
      {{0.8, -0.3, 0.2}, {0.0, 0.6, 0.0}, {0.3, 0.0, 0.5}},     // crossing the horizon
      {{-3.0, 1.0, 0.05}, {0.0, 2.0, 0.0}, {0.0, 0.0, 0.4}},    // grazing, mostly below
      {{0.2, 0.1, 0.3}, {0.05, 0.0, 0.0}, {0.0, 0.05, 0.0}},    // small
  };
  std::vector<glm::vec4> a, b;
  std::vector<double> expected;
  for (const auto& Minv : lobe_matrices())
    for (const auto& q : quads) {
      // Pass M^-1's columns and the quad; the shader rebuilds both.
      a.push_back(glm::vec4(glm::dvec3(q.c), 0.0));
      b.push_back(glm::vec4(0.0));
      expected.push_back(parallelogram_integral(Minv, q.c, q.u, q.w));
    }
  // Two vec4 inputs carry less than a matrix and a polygon: index the data by the invocation.
  std::string data = "const mat3 kMinv[" + std::to_string(lobe_matrices().size()) + "] = mat3[](";
  bool first = true;
  for (const auto& m : lobe_matrices()) {
    data += first ? "" : ", ";
    first = false;
    data += "mat3(";
    for (int i = 0; i < 9; ++i) data += (i ? ", " : "") + std::to_string(m[i / 3][i % 3]);
    data += ")";
  }
  data += ");\nconst vec3 kQuad[" + std::to_string(3 * quads.size()) + "] = vec3[](";
  for (std::size_t i = 0; i < quads.size(); ++i)
    for (const glm::dvec3& v : {quads[i].c, quads[i].u, quads[i].w})
      data += std::string(i || v != quads[i].c ? ", " : "") + "vec3(" + std::to_string(v.x) + ", " +
              std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
  data += ");\n";
  for (std::size_t i = 0; i < a.size(); ++i) a[i].w = static_cast<float>(i);
  const auto got = evaluate_glsl("#include \"ltc/ltc.glsl\"\n" + data, R"(
vec4 evaluate(vec4 a, vec4 b) {
  int i = int(a.w), q = i % )" + std::to_string(quads.size()) + R"(, m = i / )" + std::to_string(quads.size()) + R"(;
  vec3 c = kQuad[3 * q], u = kQuad[3 * q + 1], w = kQuad[3 * q + 2];
  vec3 v[LIGHT_POLYGON_MAX_VERTICES];
  v[0] = c - u - w; v[1] = c + u - w; v[2] = c + u + w; v[3] = c - u + w;
  return vec4(ltcPolygonIntegral(kMinv[m], v, 4));
})",
                                  a, b);
  // The mirror-like lobe's peak (along z) inside the overhead quad is too narrow for the
  // quadrature: there the whole lobe is inside, and the integral is 1.
  const std::size_t mirror = lobe_matrices().size() - 1;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const bool peak_inside = i / quads.size() == mirror && i % quads.size() == 0;
    EXPECT_NEAR(got[i].x, peak_inside ? 1.0 : expected[i], 2e-4 * expected[i] + 2e-6)
        << "matrix " << i / quads.size() << ", quad " << i % quads.size();
  }
}

namespace {

std::string matrices_glsl() {
  const std::vector<glm::dmat3> matrices = lobe_matrices();
  std::string data = "const mat3 kMinv[" + std::to_string(matrices.size()) + "] = mat3[](";
  for (std::size_t k = 0; k < matrices.size(); ++k) {
    const glm::dmat3& m = matrices[k];
    data += std::string(k ? ", " : "") + "mat3(";
    for (int i = 0; i < 9; ++i) data += (i ? ", " : "") + std::to_string(m[i / 3][i % 3]);
    data += ")";
  }
  return data + ");\n";
}

struct Disk {
  glm::dvec3 c, n;
  double radius;
};

void disk_frame(glm::dvec3 n, glm::dvec3& u, glm::dvec3& w) {
  u = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, glm::dvec3(1, 0, 0)) : glm::cross(n, glm::dvec3(0, 1, 0)));
  w = glm::cross(n, u);
}

}  // namespace

// Disks entirely above the horizon of the lobe's space: the z component of the vector form factor
// is the integral. Exact for circular cones (the identity, and a disk facing the origin); the
// elliptic cone of a sharp or skewed lobe is replaced by the cap of equal form factor, whose
// error is bounded here and stated in docs/methods.md.
TEST(LtcGeometry, FixedSlotClippingEqualsAVertexListClipper) {
  // ltc.glsl clips in fixed edge slots; a Sutherland-Hodgman vertex list, written here, clips the
  // same polygon by appending at a running count. Random quads around the shading point (most
  // crossing the surface's horizon, some the cosine's after M^-1) and random matrices: the same
  // integral within rounding, and the same bits where neither clip cuts the polygon.
  constexpr int kCases = 4096;
  std::vector<glm::vec4> a(kCases), b(kCases);
  for (int i = 0; i < kCases; ++i) a[i] = glm::vec4(static_cast<float>(i));
  const auto got = evaluate_glsl("#include \"ltc/ltc.glsl\"\n#include \"core/sampling.glsl\"\n", R"(
int listClip(inout vec3 v[6], int count) {
  vec3 clipped[6];
  int n = 0;
  for (int i = 0; i < 5; ++i) {
    if (i >= count) break;
    vec3 a = v[i], b = v[i + 1 < count ? i + 1 : 0];
    if (a.z >= 0.0) clipped[n++] = a;
    if ((a.z >= 0.0) != (b.z >= 0.0)) clipped[n++] = mix(a, b, a.z / (a.z - b.z));
  }
  v = clipped;
  return n < 3 ? 0 : n;
}
float listIntegral(mat3 Minv, vec3 q[4], out bool cut) {
  vec3 p[6] = vec3[6](q[0], q[1], q[2], q[3], vec3(0.0), vec3(0.0));
  bool above = true;
  for (int i = 0; i < 4; ++i) above = above && q[i].z > 0.0 && (Minv * q[i]).z > 0.0;
  cut = !above;
  int n = listClip(p, 4);
  for (int i = 0; i < 6; ++i) p[i] = Minv * p[i];
  n = listClip(p, n);
  float sum = 0.0;
  for (int i = 0; i < 6; ++i) {
    if (i >= n) break;
    sum += ltcEdgeVector(p[i], p[i + 1 < n ? i + 1 : 0]).z;
  }
  return abs(sum) / TWO_PI;
}
float unit(inout uint h) { h = pcgHash(h); return uintToUnit(h); }
vec4 evaluate(vec4 a, vec4 b) {
  uint h = uint(a.x) * 747796405u + 1u;
  vec3 c = vec3(4.0 * unit(h) - 2.0, 4.0 * unit(h) - 2.0, 2.0 * unit(h) - 0.6);
  vec3 u = vec3(unit(h) - 0.5, unit(h) - 0.5, unit(h) - 0.5) * 2.0;
  vec3 w = cross(u, vec3(unit(h) - 0.5, unit(h) - 0.5, unit(h) - 0.5));
  vec3 q[4] = vec3[4](c - u - w, c + u - w, c + u + w, c - u + w);
  mat3 Minv = mat3(1.5) + mat3(unit(h) - 0.5, unit(h) - 0.5, unit(h) - 0.5, unit(h) - 0.5, unit(h) - 0.5,
                               unit(h) - 0.5, unit(h) - 0.5, unit(h) - 0.5, unit(h) - 0.5);
  bool cut;
  float list = listIntegral(Minv, q, cut);
  return vec4(ltcPolygonIntegral(Minv, q, 4), list, cut ? 1.0 : 0.0, ltcPolygonFormFactorClipped(q, 4));
})",
                                  a, b);
  int cut = 0, uncut = 0;
  double worst = 0;
  for (int i = 0; i < kCases; ++i) {
    const glm::vec4& r = got[i];
    ASSERT_TRUE(std::isfinite(r.x) && std::isfinite(r.w)) << "case " << i;
    if (r.z > 0.5) {
      ++cut;
      worst = std::max(worst, double(std::abs(r.x - r.y)));
      EXPECT_NEAR(r.x, r.y, 2e-6 + 2e-5 * r.y) << "case " << i;
    } else {
      ++uncut;
      EXPECT_EQ(r.x, r.y) << "case " << i << ": an uncut polygon gives the same bits";
    }
  }
  std::printf("%d cut and %d uncut polygons; largest difference where cut %.3g\n", cut, uncut, worst);
  EXPECT_GT(cut, kCases / 4);
  EXPECT_GT(uncut, 100);
}

TEST(LtcGeometry, DiskVectorFormFactorMatchesQuadrature) {
  const std::vector<Disk> disks = {
      {{0.0, 0.0, 2.0}, {0.0, 0.0, -1.0}, 0.5},                          // overhead, facing the origin
      {{0.6, 0.3, 1.5}, glm::normalize(glm::dvec3(-0.6, -0.3, -1.5)), 0.3},  // facing the origin, off axis
      {{0.5, 0.0, 1.0}, glm::normalize(glm::dvec3(0.3, 0.2, -1.0)), 0.2},    // tilted: elliptic
      {{0.1, 0.1, 3.0}, {0.0, 0.0, -1.0}, 0.02},                         // small and far
      {{0.74, 0.0, 5.0}, {0.0, 0.0, -1.0}, 0.53},                        // off the mirror direction
  };
  std::vector<glm::vec4> a, b;
  std::vector<double> expected;
  std::vector<bool> circular;
  const auto matrices = lobe_matrices();
  for (std::size_t k = 0; k < matrices.size(); ++k)
    for (std::size_t d = 0; d < disks.size(); ++d) {
      glm::dvec3 u, w;
      disk_frame(disks[d].n, u, w);
      a.push_back(glm::vec4(glm::dvec3(disks[d].c), static_cast<double>(k)));
      b.push_back(glm::vec4(glm::dvec3(disks[d].n), disks[d].radius));
      expected.push_back(disk_integral(matrices[k], disks[d].c, u, w, disks[d].radius));
      circular.push_back(k == 0 && d != 2);
    }
  const auto got = evaluate_glsl("#include \"ltc/ltc.glsl\"\n" + matrices_glsl(), R"(
vec4 evaluate(vec4 a, vec4 b) {
  vec3 n = b.xyz;
  vec3 u = normalize(abs(n.x) < 0.9 ? cross(n, vec3(1.0, 0.0, 0.0)) : cross(n, vec3(0.0, 1.0, 0.0)));
  vec3 w = cross(n, u);
  return vec4(ltcDiskVectorFormFactor(kMinv[int(a.w)], a.xyz, u * b.w, w * b.w), 0.0);
})",
                                  a, b);
  double worst = 0;
  const std::size_t mirror = matrices.size() - 1;
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (i / disks.size() == mirror && i % disks.size() == 0) expected[i] = 1.0;  // the whole lobe inside
    const double relative = std::abs(got[i].z - expected[i]) / expected[i];
    if (circular[i]) EXPECT_LT(relative, 1e-3) << "matrix " << i / disks.size() << ", disk " << i % disks.size();
    else worst = std::max(worst, relative);
    EXPECT_TRUE(std::isfinite(got[i].x) && std::isfinite(got[i].y)) << i;
  }
  // The equal-form-factor cap of an elliptic cone.
  EXPECT_LT(worst, 0.01);
  RecordProperty("elliptic_cone_worst_relative_error", std::to_string(worst));
  std::printf("elliptic cones: worst relative error of the cap of equal form factor %.4f\n", worst);
}
