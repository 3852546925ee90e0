// The plane geometry and the shading of `podee` (shaders/podee/reflection_space.glsl,
// reflection_space_shading.glsl) on the GL device, against independent computations in C++:
// polygon clipping against a 16384-gon, convex hulls by monotone chain, brute-force distances.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "gl_fixture.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

const char* kIncludes = R"(#include "podee/reflection_space_shading.glsl")";

using Poly = std::vector<glm::dvec2>;

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

double area(const Poly& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

/// Convex hull, counter-clockwise (Andrew's monotone chain).
Poly hull(Poly p) {
  std::sort(p.begin(), p.end(), [](auto a, auto b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  Poly h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k > 1 ? k - 1 : k);
  return h;
}

/// Sutherland-Hodgman: the convex polygon p clipped to the half-plane left of a->b.
Poly clip(const Poly& p, glm::dvec2 a, glm::dvec2 b) {
  Poly out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 c = p[i], n = p[(i + 1) % p.size()];
    const double sc = cross(b - a, c - a), sn = cross(b - a, n - a);
    if (sc >= 0) out.push_back(c);
    if ((sc >= 0) != (sn >= 0)) out.push_back(c + (n - c) * (sc / (sc - sn)));
  }
  return out;
}

/// Area of the convex polygon p inside the unit disk, the disk as a 4096-gon of equal area.
double disk_intersection(Poly p, glm::dvec2 centre = {0, 0}, double r = 1) {
  constexpr int n = 4096;
  const double equal_area = r * std::sqrt(2 * M_PI / (n * std::sin(2 * M_PI / n)));
  for (int i = 0; i < n && !p.empty(); ++i) {
    const double a0 = 2 * M_PI * i / n, a1 = 2 * M_PI * (i + 1) / n;
    p = clip(p, centre + equal_area * glm::dvec2(std::cos(a0), std::sin(a0)),
             centre + equal_area * glm::dvec2(std::cos(a1), std::sin(a1)));
  }
  return p.empty() ? 0 : area(p);
}

double distance_to(const Poly& convex, glm::dvec2 t) {
  bool inside = true;
  double best = 1e300;
  for (std::size_t i = 0; i < convex.size(); ++i) {
    const glm::dvec2 a = convex[i], e = convex[(i + 1) % convex.size()] - a;
    inside = inside && cross(e, t - a) >= 0;
    const double ee = glm::dot(e, e);
    const double s = ee > 0 ? std::clamp(glm::dot(t - a, e) / ee, 0.0, 1.0) : 0.0;
    best = std::min(best, glm::length(t - (a + s * e)));
  }
  return inside ? 0 : best;
}

/// Four points of a random quad: a random convex quad, bow tie or dart, at a random scale and
/// distance from the unit disk, so that it lies inside, outside, across the rim or around it.
struct QuadCase {
  glm::vec4 a, b;  // corners (a.xy, a.zw, b.xy, b.zw)
  Poly points() const { return {{a.x, a.y}, {a.z, a.w}, {b.x, b.y}, {b.z, b.w}}; }
};

std::vector<QuadCase> random_quads(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<QuadCase> cases;
  for (int i = 0; i < count; ++i) {
    const double scale = std::exp(std::log(0.02) + u(rng) * std::log(200.0));  // 0.02 .. 4 disk radii
    const double dist = u(rng) * (1.5 + scale);
    const double phi = 2 * M_PI * u(rng);
    const glm::dvec2 centre = dist * glm::dvec2(std::cos(phi), std::sin(phi));
    Poly q;
    for (int k = 0; k < 4; ++k) {
      // Jittered angles keep most quads convex; every third case scrambles the order (bow ties,
      // darts, triangles with a point inside).
      const double a = 2 * M_PI * (k + 0.8 * (u(rng) - 0.5)) / 4;
      const double r = scale * (0.3 + u(rng));
      q.push_back(centre + r * glm::dvec2(std::cos(a), std::sin(a) * (0.2 + u(rng))));
    }
    if (i % 3 == 0) std::swap(q[1], q[2]);
    cases.push_back({glm::vec4(q[0].x, q[0].y, q[1].x, q[1].y), glm::vec4(q[2].x, q[2].y, q[3].x, q[3].y)});
  }
  return cases;
}

std::vector<glm::vec4> run(const std::vector<QuadCase>& cases, const std::string& body) {
  std::vector<glm::vec4> a, b;
  for (const auto& c : cases) {
    a.push_back(c.a);
    b.push_back(c.b);
  }
  return evaluate_glsl(kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  vec2 q[4] = vec2[](a.xy, a.zw, b.xy, b.zw);
  convexHullQuad(q);
)" + body + "}",
                       a, b);
}

}  // namespace

TEST(ReflectionSpace, HullOfFoldedAndDartQuadsMatchesMonotoneChain) {
  const auto cases = random_quads(400, 3);
  const auto gpu = run(cases, "return vec4(quadArea(q), 0.0, 0.0, 0.0);");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const double expected = area(hull(cases[i].points()));
    EXPECT_NEAR(gpu[i].x, expected, 1e-5 * expected + 1e-9) << "case " << i;
  }
}

TEST(ReflectionSpace, ExactCoverageMatchesPolygonClipping) {
  // Quads from 1/50 to 4 disk radii, inside, outside, across the rim and around the whole disk.
  const auto cases = random_quads(300, 5);
  const auto gpu = run(cases, "return vec4(unitDiskIntersectionArea(q, AREA_EXACT) / quadArea(q), 0.0, 0.0, 0.0);");
  int partial = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Poly h = hull(cases[i].points());
    const double expected = disk_intersection(h) / area(h);
    partial += expected > 0.01 && expected < 0.99;
    EXPECT_NEAR(gpu[i].x, expected, 5e-5) << "case " << i;
  }
  EXPECT_GT(partial, 60);  // the cases exercise the rim, not only all-or-nothing
}

TEST(ReflectionSpace, IntersectionAreaKeepsItsPrecisionWithACornerFarAway) {
  // A corner ray that nearly misses the light plane lands 1e3 .. 1e5 light radii away; the area
  // on the disk must not suffer (the rim crossings are measured from the nearer endpoint).
  auto cases = random_quads(200, 17);
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (auto& c : cases) {
    const double far = std::pow(10.0, 3 + 2 * u(rng)), phi = 2 * M_PI * u(rng);
    c.b.z = static_cast<float>(far * std::cos(phi));
    c.b.w = static_cast<float>(far * std::sin(phi));
  }
  const auto gpu = run(cases, "return vec4(unitDiskIntersectionArea(q, AREA_EXACT), 0.0, 0.0, 0.0);");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const double expected = disk_intersection(hull(cases[i].points()));
    EXPECT_NEAR(gpu[i].x, expected, 1e-4 * M_PI) << "case " << i << ": " << cases[i].a.x << "," << cases[i].a.y << " " << cases[i].a.z << "," << cases[i].a.w << " " << cases[i].b.x << "," << cases[i].b.y << " " << cases[i].b.z << "," << cases[i].b.w;
  }
}

TEST(ReflectionSpace, LensAreaMatchesIntegratedChords) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::vec4> a, b;
  for (int i = 0; i < 100; ++i) {
    const double r = std::exp(std::log(0.002) + u(rng) * std::log(2000.0));  // both sides of the small-disk form
    a.emplace_back(r, u(rng) * (1.2 + r), 0, 0);
    b.emplace_back(0);
  }
  const auto gpu = evaluate_glsl(kIncludes, "vec4 evaluate(vec4 a, vec4 b) { return vec4(unitDiskLensArea(a.x, a.y)); }", a, b);
  for (std::size_t i = 0; i < a.size(); ++i) {
    // Midpoint rule over x of the overlap of the two disks' vertical chords.
    const double r = a[i].x, d = a[i].y;
    const double lo = std::max(-1.0, d - r), hi = std::min(1.0, d + r);
    const int steps = 200000;
    double expected = 0;
    for (int k = 0; k < steps && hi > lo; ++k) {
      const double x = lo + (k + 0.5) * (hi - lo) / steps;
      const double h1 = std::sqrt(std::max(0.0, 1 - x * x)), h2 = std::sqrt(std::max(0.0, r * r - (x - d) * (x - d)));
      expected += 2 * std::min(h1, h2) * (hi - lo) / steps;
    }
    EXPECT_NEAR(gpu[i].x, expected, 1e-3 * M_PI * std::min(r * r, 1.0)) << "r " << r << " d " << d;
  }
}

TEST(ReflectionSpace, SelectedPointIsTheClosestPointToTheLightsCentre) {
  const auto cases = random_quads(300, 7);
  const auto gpu = run(cases, "vec2 c = closestPointInConvexQuad(q, vec2(0.0)); return vec4(c, length(c), 0.0);");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Poly h = hull(cases[i].points());
    const double expected = distance_to(h, {0, 0});
    EXPECT_NEAR(gpu[i].z, expected, 1e-5 * (1 + expected)) << "case " << i;
    // The point lies in the hull (distance 0 from it).
    EXPECT_LT(distance_to(h, {gpu[i].x, gpu[i].y}), 1e-4 * (1 + expected)) << "case " << i;
  }
}

TEST(ReflectionSpace, DegenerateQuadsGiveFiniteFractions) {
  // Coincident corners, collinear corners, zero quads, points at 1e8 and mixtures: the covered
  // area of every mode stays finite, within [0, pi] and within the quad's own area.
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<QuadCase> cases;
  for (int i = 0; i < 4096; ++i) {
    glm::dvec2 p[4];
    const double scale = std::pow(10.0, 8 * std::abs(u(rng)) - 4);
    const glm::dvec2 base(u(rng) * 2, u(rng) * 2), dir(u(rng), u(rng));
    for (int k = 0; k < 4; ++k) {
      switch (i % 4) {
        case 0: p[k] = base; break;                                                      // a point
        case 1: p[k] = base + scale * u(rng) * dir; break;                               // collinear
        case 2: p[k] = k < 2 ? base : base + scale * glm::dvec2(u(rng), u(rng)); break;  // repeated corners
        default: p[k] = base + scale * glm::dvec2(u(rng), u(rng)); break;                 // any
      }
    }
    cases.push_back({glm::vec4(p[0].x, p[0].y, p[1].x, p[1].y), glm::vec4(p[2].x, p[2].y, p[3].x, p[3].y)});
  }
  const auto gpu = run(cases, R"(
  vec2 c = closestPointInConvexQuad(q, vec2(0.0));
  return vec4(unitDiskIntersectionArea(q, AREA_EXACT), unitDiskIntersectionArea(q, AREA_LENS), c);)");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(std::isfinite(gpu[i][k])) << "case " << i << " component " << k;
    // No larger than the disk or the quad (up to the float rounding of the quad's area).
    double extent = 0;
    for (const auto& p : cases[i].points()) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    const double bound = std::min(M_PI, area(hull(cases[i].points())) + 1e-6 * extent * extent) * (1 + 1e-4) + 1e-6;
    for (int k = 0; k < 2; ++k) {
      EXPECT_GE(gpu[i][k], 0.0f) << "case " << i;
      EXPECT_LE(gpu[i][k], bound) << "case " << i << " mode " << k << ": " << cases[i].a.x << "," << cases[i].a.y << " " << cases[i].a.z << "," << cases[i].a.w << " " << cases[i].b.x << "," << cases[i].b.y << " " << cases[i].b.z << "," << cases[i].b.w;
    }
  }
}

TEST(ReflectionSpace, ShadingIsFiniteForAnyCornersAndZeroForLightsBehind) {
  // 2^16 random pixels: surface frame, view, material (mirror to alpha 0.5, GGX and Beckmann),
  // a disk, sphere or sun, and corner rays from coincident to wildly spread, some pointing away
  // from the light or into the surface; every area mode and the lobe extension on and off.
  // Every case whose light lies wholly below the surface's tangent plane (or whose disk faces
  // away) must give exactly zero.
  const int count = 1 << 16;
  std::vector<glm::vec4> a(count), b(count, glm::vec4(0));
  for (int i = 0; i < count; ++i) a[i] = glm::vec4(static_cast<float>(i), 0, 0, 0);
  const auto gpu = evaluate_glsl(std::string(kIncludes) + "\n#include \"core/sampling.glsl\"", R"(
vec3 randomUnit(inout uint h) {
  h = pcgHash(h);
  vec2 u = hashToUnit2(h);
  float z = 2.0 * u.x - 1.0, r = sqrt(max(1.0 - z * z, 0.0));
  return vec3(r * cos(TWO_PI * u.y), r * sin(TWO_PI * u.y), z);
}
float random01(inout uint h) { h = pcgHash(h); return uintToUnit(h); }

vec4 evaluate(vec4 a, vec4 b) {
  uint i = uint(a.x), h = pcgHash(i * 7919u + 17u);
  Surface s;
  s.position = 3.0 * randomUnit(h);
  s.vertexNormal = randomUnit(h);
  basisAround(s.vertexNormal, s.vertexTangent, s.vertexBitangent);
  vec3 v = randomUnit(h);
  s.view = dot(v, s.vertexNormal) < 0.0 ? -v : v;
  s.anisotropyRotation = 0.0;
  setShadingNormal(s, normalize(s.vertexNormal + 0.3 * randomUnit(h)));
  s.ndf = int(i % 2u);
  s.alpha = vec2(i % 5u == 0u ? 0.0 : 0.5 * pow(random01(h), 3.0), 0.5 * pow(random01(h), 3.0));
  s.rho = 0.0;  // every field the lobe reads is set: an unset one is undefined in GLSL
  s.f0 = vec3(0.9);
  s.diffuse = vec3(0.2);

  int kind = int(i % 3u);
  LightData L;
  L.colour_type = vec4(1.0, 1.0, 1.0, float(kind == 0 ? LIGHT_DISK : kind == 1 ? LIGHT_SPHERE : LIGHT_SUN));
  vec3 toLight = randomUnit(h);
  float dist = 0.5 + 10.0 * random01(h);
  L.position_radius = vec4(s.position + dist * toLight, 0.01 + 0.5 * random01(h));
  vec3 facing = randomUnit(h);
  L.direction_cos = vec4(kind == 0 ? facing : -toLight, kind == 2 ? 0.9 + 0.0999 * random01(h) : 0.0);
  L.axis_u = vec4(0.0, 0.0, 0.0, kind == 2 ? 1.0 - L.direction_cos.w : 0.0);  // a sun's 1 - cos (lights.glsl)
  L.axis_v = vec4(0.0);

  CornerRays corners;
  vec3 r = reflect(-s.view, s.normal);
  float spread = pow(10.0, -6.0 + 7.0 * random01(h));
  for (int k = 0; k < 4; ++k) {
    corners.origin[k] = s.position + spread * 0.01 * randomUnit(h);
    vec3 d = r + spread * randomUnit(h);
    corners.direction[k] = (i % 7u == 0u) ? -toLight : normalize(dot(d, d) > 0.0 ? d : r);
  }
  // Wholly behind: below the tangent plane by more than the light's radius (angular radius for
  // a sun), or a disk whose emitting side faces away.
  float below = -dot(toLight, s.vertexNormal);
  bool behind = kind == 2 ? below > sqrt(1.0 - L.direction_cos.w * L.direction_cos.w)
                          : dist * below > L.position_radius.w || (kind == 0 && dot(facing, toLight) >= 0.0);
  const int areas[3] = int[](AREA_EXACT, AREA_CIRCLE, AREA_LENS);
  ReflectionSpaceOptions options = ReflectionSpaceOptions(areas[i % 3u], i % 4u != 0u);
  Radiance result = shadeReflectionSpace(s, L, corners, materialLobe(s), options);
  float sum = result.specular.r + result.specular.g + result.specular.b + result.diffuse.r;
  return vec4(sum, behind ? 1.0 : 0.0, min(min(result.specular.r, result.diffuse.r), 0.0), 0.0);
}
)",
                                 a, b);
  int behind = 0;
  for (int i = 0; i < count; ++i) {
    ASSERT_TRUE(std::isfinite(gpu[i].x)) << "case " << i;
    ASSERT_EQ(gpu[i].z, 0.0f) << "negative radiance, case " << i;
    if (gpu[i].y > 0.5f) {
      ++behind;
      ASSERT_EQ(gpu[i].x, 0.0f) << "light behind the surface, case " << i;
    }
  }
  EXPECT_GT(behind, count / 4);
}
