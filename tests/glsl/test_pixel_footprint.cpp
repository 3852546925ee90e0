// The pixel footprint (shaders/core/footprint.glsl) on the GL device: its derived quantities
// against independent computations in C++, its half-vector derivatives against finite
// differences of the frame model they assume, and against the raster pass's own quad
// differences (dFdx, dFdy) of the half vectors kaplanyan-* and tokuyoshi filter with, on a plane and
// a sphere: what a backend without screen-space derivatives will call instead.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = "#include \"core/footprint.glsl\"\n";

}  // namespace

TEST(PixelFootprint, DerivedQuantitiesAreTheUvJacobiansCovarianceAndSingularValues) {
  // Random Jacobians J = [dx dy] over twelve decades, some degenerate (rank 1, zero, axis-aligned).
  // Expected: C = J J^T, the singular values as the roots of the eigenvalues of J^T J (the other
  // Gram matrix) by the quadratic formula in double, the major axis as C's unit eigenvector of the
  // largest eigenvalue (checked through e^T C e = L^2, sign-free).
  std::mt19937 rng(71);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 2048; ++i) {
    const float scale = static_cast<float>(std::pow(10.0, -8.0 + 6.0 * (0.5 + 0.5 * u(rng))));
    glm::vec4 j(u(rng), u(rng), u(rng), u(rng));
    if (i % 16 == 1) j = glm::vec4(j.x, j.y, 0.3f * j.x, 0.3f * j.y);  // rank 1
    if (i % 16 == 2) j = glm::vec4(j.x, 0.0f, 0.0f, j.w);              // axis-aligned
    if (i % 64 == 3) j = glm::vec4(0.0f);
    a.push_back(j * scale);
    b.emplace_back(0.0f);
  }
  const auto gpu = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 j, vec4 unused) {
  Footprint f = uvFootprint(j.xy, j.zw);
  return vec4(f.majorLength, f.minorLength, dot(f.majorAxis, f.uvCovariance * f.majorAxis), length(f.majorAxis));
})",
                                 a, b);
  const auto covariance = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 j, vec4 unused) {
  mat2 c = uvFootprint(j.xy, j.zw).uvCovariance;
  return vec4(c[0][0], c[1][0], c[0][1], c[1][1]);
})",
                                        a, b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const glm::dvec2 dx(a[i].x, a[i].y), dy(a[i].z, a[i].w);
    const double cxx = dx.x * dx.x + dy.x * dy.x, cxy = dx.x * dx.y + dy.x * dy.y, cyy = dx.y * dx.y + dy.y * dy.y;
    const double gxx = glm::dot(dx, dx), gxy = glm::dot(dx, dy), gyy = glm::dot(dy, dy);  // J^T J
    const double tr = gxx + gyy, det = gxx * gyy - gxy * gxy;
    const double disc = std::sqrt(std::max(0.25 * tr * tr - det, 0.0));
    const double major = std::sqrt(0.5 * tr + disc);
    const double minor = std::abs(dx.x * dy.y - dx.y * dy.x) / std::max(major, 1e-300);
    const double tol = 1e-5 * major;
    EXPECT_NEAR(covariance[i].x, cxx, 1e-5 * tr) << i;
    EXPECT_NEAR(covariance[i].y, cxy, 1e-5 * tr) << i;
    EXPECT_EQ(covariance[i].y, covariance[i].z) << i;
    EXPECT_NEAR(covariance[i].w, cyy, 1e-5 * tr) << i;
    EXPECT_NEAR(gpu[i].x, major, tol) << i;
    EXPECT_NEAR(gpu[i].y, minor, tol) << i;
    EXPECT_NEAR(gpu[i].w, 1.0, 1e-6) << "the major axis is a unit vector, " << i;
    if (major > 0) {
      EXPECT_NEAR(gpu[i].z, major * major, 1e-5 * major * major) << "e^T C e, " << i;
    } else {
      EXPECT_EQ(gpu[i].x, 0.0f) << i;
    }
  }
}

TEST(PixelFootprint, TexelCovarianceAndUnitsAreTheUvJacobianScaled) {
  // footprintTexelCovariance: sigma^2 S J J^T S with S = diag(W, H); a non-finite J gives 0.
  // footprintInUnits(f, t): the footprint of J / t (lengths / t, the same axis).
  std::mt19937 rng(72);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 256; ++i) {
    a.emplace_back(glm::vec4(u(rng), u(rng), u(rng), u(rng)) * 1e-3f);
    b.emplace_back(64 << (i % 4), 32 << (i % 3), 0.1 + 2.0 * (0.5 + 0.5 * u(rng)), 1.0 + 15.0 * (0.5 + 0.5 * u(rng)));
  }
  a.emplace_back(INFINITY, 0.0f, 0.0f, 1e-3f);
  b.emplace_back(64.0f, 64.0f, 0.5f, 2.0f);
  const auto texel = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 j, vec4 p) {
  mat2 c = footprintTexelCovariance(uvFootprint(j.xy, j.zw), ivec2(p.xy), p.z);
  return vec4(c[0][0], c[1][0], c[1][1], 0.0);
})",
                                   a, b);
  const auto units = evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 j, vec4 p) {
  Footprint f = uvFootprint(j.xy, j.zw), g = footprintInUnits(f, p.w);
  return vec4(g.majorLength * p.w / f.majorLength, g.minorLength * p.w / f.minorLength,
              abs(dot(g.majorAxis, f.majorAxis)), length(g.dUVdx * p.w - f.dUVdx));
})",
                                   a, b);
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const double w = b[i].x, h = b[i].y, s2 = double(b[i].z) * b[i].z;
    const glm::dvec2 jx(a[i].x * w, a[i].y * h), jy(a[i].z * w, a[i].w * h);
    const double cxx = s2 * (jx.x * jx.x + jy.x * jy.x), cxy = s2 * (jx.x * jx.y + jy.x * jy.y),
                 cyy = s2 * (jx.y * jx.y + jy.y * jy.y);
    EXPECT_NEAR(texel[i].x, cxx, 1e-5 * (cxx + cyy)) << i;
    EXPECT_NEAR(texel[i].y, cxy, 1e-5 * (cxx + cyy)) << i;
    EXPECT_NEAR(texel[i].z, cyy, 1e-5 * (cxx + cyy)) << i;
    EXPECT_NEAR(units[i].x, 1.0, 1e-5) << i;
    EXPECT_NEAR(units[i].y, 1.0, 1e-4) << i;
    EXPECT_NEAR(units[i].z, 1.0, 1e-5) << i;
    EXPECT_LT(units[i].w, 1e-6 * glm::length(glm::vec2(a[i].x, a[i].y))) << i;
  }
  EXPECT_EQ(texel.back(), glm::vec4(0.0f)) << "a non-finite Jacobian is a point";
}

namespace {

using glm::dvec3;

dvec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(dvec3(g(rng), g(rng), g(rng)));
}

/// One configuration of halfVectorDifferential's inputs: the vertex frame (n, t, handedness), the
/// shading frame turned from it by `angle` about n, v, l and the differentials along x and y.
struct HalfVectorCase {
  dvec3 n, t;
  double handedness, angle;
  dvec3 v, l;
  dvec3 dN[2], dT[2], dV[2], dl[2];
};

std::string glsl_vec3(const dvec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "vec3(%.9g, %.9g, %.9g)", v.x, v.y, v.z);
  return text;
}

dvec3 as_float(const dvec3& v) { return dvec3(glm::vec3(v)); }

/// The frame model halfVectorDifferential assumes, moved by eps along axis `a`: n = normalize(n +
/// eps dN), the tangent orthogonalised against it, the bitangent of the same handedness, the
/// shading frame turned by the fixed angle, v and l renormalised. Returns (slope.xy, projected.xy).
glm::dvec4 half_vector_forms(const HalfVectorCase& c, int a, double eps) {
  const dvec3 n = glm::normalize(c.n + eps * c.dN[a]);
  const dvec3 tangent = c.t + eps * c.dT[a];
  const dvec3 t = glm::normalize(tangent - n * glm::dot(n, tangent));
  const dvec3 b = c.handedness * glm::cross(n, t);
  const dvec3 ts = std::cos(c.angle) * t + std::sin(c.angle) * b, bs = std::cos(c.angle) * b - std::sin(c.angle) * t;
  const dvec3 h = glm::normalize(c.v + eps * c.dV[a]) + glm::normalize(c.l + eps * c.dl[a]);
  const dvec3 u = glm::normalize(h);
  return {glm::dot(h, ts) / glm::dot(h, n), glm::dot(h, bs) / glm::dot(h, n), glm::dot(u, ts), glm::dot(u, bs)};
}

}  // namespace

TEST(PixelFootprint, HalfVectorDerivativesAreTheChainRuleOfTheFrameModel) {
  // Random frames (both handednesses, turned about n), view and light directions, and
  // differentials; expected: central differences (eps = 1e-6, in double) of the model's slope and
  // projected half vector. Tolerance 1e-6 (1 + |d|): float32 evaluation of O(1) quantities (the
  // worst case measures 0.05 x that).
  std::mt19937 rng(73);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<HalfVectorCase> cases;
  while (cases.size() < 64) {
    HalfVectorCase c;
    c.n = as_float(random_unit(rng));
    c.t = as_float(glm::normalize(glm::cross(c.n, random_unit(rng))));
    c.handedness = cases.size() % 2 ? -1.0 : 1.0;
    c.angle = static_cast<float>(cases.size() % 3 == 0 ? 0.0 : 3.0 * u(rng));
    c.v = as_float(random_unit(rng));
    c.l = as_float(random_unit(rng));
    const dvec3 h = c.v + c.l;
    if (glm::dot(c.v, c.n) < 0.1 || glm::dot(c.l, c.n) < 0.1 || glm::dot(h, c.n) < 0.3 * glm::length(h)) continue;
    for (int a = 0; a < 2; ++a) {
      c.dN[a] = as_float(0.1 * random_unit(rng));
      c.dT[a] = as_float(0.1 * random_unit(rng));
      const dvec3 dv = 0.05 * random_unit(rng), dl = 0.05 * random_unit(rng);
      c.dV[a] = as_float(dv - c.v * glm::dot(c.v, dv));  // derivatives of unit vectors
      c.dl[a] = as_float(dl - c.l * glm::dot(c.l, dl));
    }
    cases.push_back(c);
  }
  // 13 vec3 per case, as the GLSL below reads them: n, t, (handedness, angle, 0), v, l, then dN, dT,
  // dV, dl along x and along y.
  std::string data;
  for (const HalfVectorCase& c : cases) {
    std::vector<dvec3> fields = {c.n, c.t, dvec3(c.handedness, c.angle, 0), c.v, c.l};
    for (int axis = 0; axis < 2; ++axis) fields.insert(fields.end(), {c.dN[axis], c.dT[axis], c.dV[axis], c.dl[axis]});
    for (const dvec3& f : fields) data += (data.empty() ? "" : ",\n") + glsl_vec3(f);
  }
  data = "const vec3 CASES[" + std::to_string(cases.size() * 13) + "] = vec3[](\n" + data + ");\n";
  std::vector<glm::vec4> a, b(2 * cases.size(), glm::vec4(0.0f));
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (int form = 0; form < 2; ++form) a.emplace_back(float(i), float(form), 0, 0);
  const auto gpu = evaluate_glsl(std::string(kIncludes) + data, R"(
vec4 evaluate(vec4 a, vec4 unused) {
  int i = 13 * int(a.x);
  vec3 n = CASES[i], t = CASES[i + 1];
  vec3 b = CASES[i + 2].x * cross(n, t);
  float c = cos(CASES[i + 2].y), s = sin(CASES[i + 2].y);
  mat3 frame = mat3(c * t + s * b, c * b - s * t, n);
  Footprint f = makeFootprint(vec3(0.0), vec3(0.0), CASES[i + 5], CASES[i + 9], CASES[i + 6], CASES[i + 10],
                              CASES[i + 7], CASES[i + 11], vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
  HalfVectorDifferential d = halfVectorDifferential(f, CASES[i + 3], CASES[i + 4], CASES[i + 8], CASES[i + 12], frame, n, t);
  vec2 dx, dy;
  if (a.y < 0.5) halfVectorSlopeDerivatives(d, dx, dy);
  else halfVectorProjectedDerivatives(d, dx, dy);
  return vec4(dx, dy);
})",
                                 a, b);
  const double eps = 1e-6;
  for (std::size_t i = 0; i < cases.size(); ++i)
    for (int form = 0; form < 2; ++form) {
      const glm::vec4 got = gpu[2 * i + form];
      for (int axis = 0; axis < 2; ++axis) {
        const glm::dvec4 d =
            (half_vector_forms(cases[i], axis, eps) - half_vector_forms(cases[i], axis, -eps)) / (2 * eps);
        const glm::dvec2 expected = form == 0 ? glm::dvec2(d.x, d.y) : glm::dvec2(d.z, d.w);
        const glm::dvec2 value = axis == 0 ? glm::dvec2(got.x, got.y) : glm::dvec2(got.z, got.w);
        const double tol = 1e-6 * (1 + glm::length(expected));
        EXPECT_NEAR(value.x, expected.x, tol) << "case " << i << " form " << form << " axis " << axis;
        EXPECT_NEAR(value.y, expected.y, tol) << "case " << i << " form " << form << " axis " << axis;
      }
    }
}

namespace {

/// A module in the method slot that writes, per pixel, one axis's derivative of the half vector
/// towards the (point) light in one form, into the specular image (x, y, and whether the pixel
/// and its neighbour across the quad are inside the test's domain):
///   form   0: slope h.xy / h.z (slopeHalfVector, kaplanyan-*), 1: projected (projectedHalfVector, tokuyoshi)
///   source 0: the quad's difference, as the methods take it (dFdxFine / dFdyFine)
///          1: from the footprint (surfaceHalfVectorDifferential), the mean over the pixel and its
///             neighbour across the quad: the difference's own point (a central difference)
///          2: from the footprint at this pixel (one-sided against the difference)
///          3: as 1 with the frame held still (dN = dT = 0): what the test must reject on a sphere
constexpr const char* kModule = R"(
#include "lobe/footprint_filtering.glsl"
#include "lights/lights.glsl"
uniform float param_form, param_source, param_axis;

void prepareSurface(inout Surface s) {}

vec2 footprintDerivative(Surface s, vec3 l, vec3 dldx, vec3 dldy, bool slope, bool x) {
  HalfVectorDifferential d = surfaceHalfVectorDifferential(s, l, dldx, dldy);
  vec2 dx, dy;
  if (slope) halfVectorSlopeDerivatives(d, dx, dy);
  else halfVectorProjectedDerivatives(d, dx, dy);
  return x ? dx : dy;
}

Radiance shadeLight(Surface s, LightData L) {
  bool slope = param_form < 0.5, x = param_axis < 0.5;
  vec3 l = lightCentreDirection(L, s.position);
  vec2 h = slope ? slopeHalfVector(s, l) : projectedHalfVector(s, l);
  vec2 quad = x ? dFdxFine(h) : dFdyFine(h);
  float distance = length(L.position_radius.xyz - s.position);
  vec3 dldx = pointDirectionDerivative(l, distance, s.footprint.dPdx);
  vec3 dldy = pointDirectionDerivative(l, distance, s.footprint.dPdy);
  vec2 here = footprintDerivative(s, l, dldx, dldy, slope, x);
  Surface still = s;
  still.footprint.dNdx = still.footprint.dNdy = still.footprint.dTdx = still.footprint.dTdy = vec3(0.0);
  vec2 stillHere = footprintDerivative(still, l, dldx, dldy, slope, x);
  // The pair's mean c + (+-1/2) dFdx(c): + on the quad's first column (row), - on its second.
  float toMean = (int(x ? gl_FragCoord.x : gl_FragCoord.y) & 1) == 0 ? 0.5 : -0.5;
  vec2 mean = here + toMean * (x ? dFdxFine(here) : dFdyFine(here));
  vec2 stillMean = stillHere + toMean * (x ? dFdxFine(stillHere) : dFdyFine(stillHere));
  // The domain: half vectors within 45 degrees of the normal (where highlights are, slopes at most
  // 1), the vertex normal facing the viewer (no frame flips within the quad), a frame turning by
  // less than 0.05 radians per pixel (not a sphere's poles, where the tangent spins), in both pixels.
  vec3 hl = toLocal(s, s.view + l);
  float turn = max(length(vertexFrameRotation(s.vertexNormal, s.vertexTangent, s.footprint.dNdx, s.footprint.dTdx)),
                   length(vertexFrameRotation(s.vertexNormal, s.vertexTangent, s.footprint.dNdy, s.footprint.dTdy)));
  float inside = hl.z > 0.7 * length(hl) && dot(s.vertexNormal, s.view) > 0.5 && turn < 0.05 ? 1.0 : 0.0;
  inside *= 1.0 - abs(x ? dFdxFine(inside) : dFdyFine(inside));
  int source = int(param_source + 0.5);
  vec2 value = source == 0 ? quad : source == 1 ? mean : source == 2 ? here : stillMean;
  return Radiance(vec3(0.0), vec3(value, inside));
}
)";

/// The module's image of (form, source, axis): per pixel (derivative, inside).
std::vector<glm::vec3> half_vector_image(SceneFixture& f, int form, int source, int axis) {
  const Frame frame = f.renderer->render_module(
      "test/footprint_half_vector.glsl", {{"form", float(form)}, {"source", float(source)}, {"axis", float(axis)}},
      f.scene.camera, f.scene.film.width, f.scene.film.height);
  return frame.specular.pixels();
}

struct Agreement {
  int inside = 0, outside_tolerance = 0;
  double worst = 0;  // of |error| / tolerance
};

/// The footprint's derivatives of `source` against the quad's, over the pixels inside the domain:
/// tolerance relative 2e-3 |quad| plus 2e-6 absolute.
Agreement agreement(SceneFixture& f, int source) {
  Agreement a;
  for (int form = 0; form < 2; ++form)
    for (int axis = 0; axis < 2; ++axis) {
      const auto quad = half_vector_image(f, form, 0, axis), footprint = half_vector_image(f, form, source, axis);
      for (std::size_t i = 0; i < quad.size(); ++i) {
        if (quad[i].z != 1.0f) continue;
        ++a.inside;
        const glm::dvec2 q(quad[i].x, quad[i].y), p(footprint[i].x, footprint[i].y);
        const double error = glm::length(p - q), tol = 2e-3 * glm::length(q) + 2e-6;
        a.worst = std::max(a.worst, error / tol);
        if (error > tol) ++a.outside_tolerance;
      }
    }
  return a;
}

TestScene half_vector_scene() {
  return TestScene()
      .film(128, 96)
      .camera({0.3, 1.2, 2.2}, {0, 0.2, 0}, 40)
      .material("m", {{"f0", 0.5}, {"alpha", 0.2}})
      .point_light({1.5, 2.5, 1.0}, 4);
}

}  // namespace

TEST(PixelFootprint, HalfVectorDerivativesFromTheFootprintAreTheQuadDifferencesOnAPlaneAndASphere) {
  // The raster pass differences the half vector across the 2x2 quad; the footprint's chain rule is
  // the derivative at each pixel, so the two agree to first order at the pixel and to second order
  // at the pair's mean (the trapezoid rule), which the test compares. Tolerance 2e-3 relative (the
  // interpolated normal's departure from unit length, under 4e-4 on the default sphere of 128
  // segments, and the third-order terms: the frame turns by under 0.05 rad per pixel in the
  // domain, 0.05^2 / 12 = 2e-4) plus 2e-6 (float32 rounding of differences of O(1) values). The
  // worst pixel measures 0.5 x the tolerance on the sphere, 0.02 x on the plane.
  if (!shaders().exists("test/footprint_half_vector.glsl"))
    shaders().add_source("test/footprint_half_vector.glsl", kModule);
  for (const bool sphere : {false, true}) {
    SceneFixture f(sphere ? half_vector_scene().sphere("m", {{"radius", 0.8}, {"translate", {0, 0.2, 0}}})
                          : half_vector_scene().plane("m", {{"size", 8}}));
    const char* shape = sphere ? "sphere" : "plane";
    const Agreement mean = agreement(f, 1), here = agreement(f, 2), still = agreement(f, 3);
    EXPECT_GT(mean.inside, 4 * 1500) << shape;  // 4 images: form x axis
    EXPECT_EQ(mean.outside_tolerance, 0) << shape << ": worst error " << mean.worst << " x the tolerance";
    // At the pixel itself the chain rule is half a pixel from where the difference is taken: the
    // tolerance sees that offset (the comparison is sharp enough to place the derivative).
    EXPECT_GT(here.worst, 1.0) << shape;
    if (sphere) {
      // The sphere's frame turns: holding it still must fail (the test sees the rotation).
      EXPECT_GT(still.outside_tolerance, still.inside / 2) << shape;
    } else {
      EXPECT_EQ(still.outside_tolerance, 0) << "a plane's frame does not turn";
    }
    std::printf(
        "%s: %d pixels x forms x axes, worst error / tolerance %.3g at the pair's mean, %.3g at the pixel, "
        "%.3g with the frame held still\n",
        shape, mean.inside, mean.worst, here.worst, still.worst);
  }
}
