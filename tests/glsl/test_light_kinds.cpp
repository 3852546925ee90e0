// Every registered light kind's GLSL functions (shaders/lights/<kind>.glsl, through the generated
// dispatch of shaders/lights/lights.glsl) agree with each other on the device: samples have the
// pdf lightPdf gives them and reach the light by lightHit; the solid angle is what the samples
// integrate to; the representative direction, the outline and the disk or polygon forms describe
// the light lightHit sees; the declared properties reach the shaders. The kinds come from the
// registry, so a new kind is tested once it has an example below. (Chi-square tests of the
// samplers: tests/glsl/test_sampling.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "gl_fixture.hpp"
#include "render/shader_contract.hpp"
#include "scene/lights/light_kind.hpp"

using namespace glintlab;
using namespace glintlab::test;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// One light of each kind and a point that sees its emitting side, about six sizes away.
struct Example {
  std::string toml;
  glm::vec3 p;
  /// Relative error of lightSolidAngle as the projected solid angle: 0 where it is exact (cones),
  /// the second-order term of A cos / d^2 for planar lights.
  double solid_angle_error = 0;
};
const std::map<std::string, Example>& examples() {
  static const std::map<std::string, Example> e = {
      {"point", {"type = \"point\"\nposition = [1, 2, 3]\nintensity = 2\n", {0.2f, -0.1f, 0.3f}}},
      {"spot",
       {"type = \"spot\"\nposition = [1, 2, 3]\ndirection = [-0.3, -0.7, -1.0]\nintensity = 2\ninner_angle = 5\n"
        "outer_angle = 30\n",
        {0.2f, -0.1f, 0.3f}}},
      {"directional", {"type = \"directional\"\ndirection = [0.3, -1.0, 0.2]\n", {0.2f, -0.1f, 0.3f}}},
      {"sun", {"type = \"sun\"\ndirection = [0.3, -1.0, 0.2]\nangular_radius = 2\n", {0.2f, -0.1f, 0.3f}}},
      {"sphere", {"type = \"sphere\"\nposition = [0.1, 0.2, -0.3]\nradius = 1\n", {0.5f, 0.3f, 2.6f}}},
      {"disk", {"type = \"disk\"\nposition = [0, 0, 0]\ndirection = [0.1, 0.0, 1.0]\nradius = 0.5\n", {0.6f, 0.4f, 5.5f}, 0.02}},
      {"quad",
       {"type = \"quad\"\nposition = [0, 0, 0]\ndirection = [0.0, 0.1, 1.0]\nsize = [1.0, 0.6]\nup = [0.3, 1, 0]\n",
        {-0.5f, 0.4f, 5.5f},
        0.02}},
      {"environment", {"type = \"environment\"\ngenerator = \"studio\"\nrotation = 30\n", {0.2f, -0.1f, 0.3f}}},
  };
  return e;
}

/// A scene holding only `light` (TOML keys of one [[light]]) and a speck of a sphere far away.
TestScene light_scene(const std::string& light) {
  return TestScene().material("m").sphere("m", {{"radius", 0.01}, {"translate", {0, -100, 0}}}).raw("[[light]]\n" + light);
}

const char* kIncludes = "#include \"lights/lights.glsl\"\n";

float unit(std::mt19937& rng) { return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f); }

/// Evaluates `body` on lights[0] of the kind's example scene.
std::vector<glm::vec4> on_example(SceneFixture& f, const std::string& body, const std::vector<glm::vec4>& a,
                                  const std::vector<glm::vec4>& b) {
  f.gpu->bind_buffers();
  return evaluate_glsl(kIncludes, body, a, b);
}

}  // namespace

TEST(LightKinds, EveryRegisteredKindHasAnExampleHere) {
  for (const auto& k : all_light_kinds()) EXPECT_TRUE(examples().contains(k.id)) << "add an example of " << k.id;
}

// Both as a test harness compiles the dispatch (every kind) and as a scene of only this kind does
// (the forward variant's LIGHT_<ID>_COUNT: the other kinds removed, properties that are literals).
TEST(LightKinds, DeclaredPropertiesReachTheShaders) {
  for (const auto& kind : all_light_kinds()) {
    SceneFixture f(light_scene(examples().at(kind.id).toml));
    ASSERT_EQ(f.scene.lights[0].kind, &kind);
    std::string only_this_kind;
    for (const auto& k : all_light_kinds())
      only_this_kind += "#define " + light_count_define(k) + (&k == &kind ? " 1\n" : " 0\n");
    for (const std::string& specialisation : {std::string(), only_this_kind}) {
      f.gpu->bind_buffers();
      const auto r = evaluate_glsl(specialisation + kIncludes, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  return vec4(lightHasExtent(L) ? 1.0 : 0.0, lightIsDistant(L) ? 1.0 : 0.0,
              float(lightForm(L)) + (lightHasDiskForm(L) ? 10.0 : 0.0) + (lightHasPolygonForm(L) ? 20.0 : 0.0),
              float(lightType(L)) + (lightIsCompact(L) ? 0.5 : 0.0));
})",
                                   {glm::vec4(0)}, {glm::vec4(0)});
      const std::string what = kind.id + (specialisation.empty() ? " (every kind compiled)" : " (only its kind compiled)");
      EXPECT_EQ(r[0].x, kind.has_extent ? 1.0f : 0.0f) << what;
      EXPECT_EQ(r[0].y, kind.distant ? 1.0f : 0.0f) << what;
      EXPECT_EQ(r[0].z, static_cast<float>(static_cast<int>(kind.form)) + (kind.form == LightForm::Disk ? 10.0f : 0.0f) +
                            (kind.form == LightForm::Polygon ? 20.0f : 0.0f))
          << what;
      EXPECT_EQ(r[0].w, static_cast<float>(kind.code()) + (kind.compact ? 0.5f : 0.0f)) << what;
    }
  }
}

TEST(LightKinds, DeltaLightsShineFromTheirCentreDirectionAndCannotBeHit) {
  for (const auto& kind : all_light_kinds()) {
    if (kind.has_extent) continue;
    SCOPED_TRACE(kind.id);
    const Example& e = examples().at(kind.id);
    SceneFixture f(light_scene(e.toml));
    const auto r = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  vec3 l, irradiance;
  deltaLightIncidence(L, a.xyz, l, irradiance);
  float dist;
  return vec4(dot(l, lightCentreDirection(L, a.xyz)), lightHit(L, a.xyz, l, dist) ? 1.0 : 0.0, irradiance.g, 0.0);
})",
                              {glm::vec4(e.p, 0)}, {glm::vec4(0)});
    EXPECT_NEAR(r[0].x, 1.0f, 1e-6f) << "incidence along the centre direction";
    EXPECT_EQ(r[0].y, 0.0f) << "a ray cannot hit a delta light";
    EXPECT_GT(r[0].z, 0.0f);
  }
}

TEST(LightKinds, SamplesHaveLightPdfsDensityAndHitTheLight) {
  // sampleLightDirection's pdf is lightPdf's at the sample, and the sample reaches the light at
  // the distance it reports; E[(dir . centre) / pdf] over the samples is the projected solid
  // angle lightSolidAngle gives (exactly for cones; A cos / d^2 to second order in size over
  // distance for planar lights: 1% at these distances).
  const int n = 1 << 16;
  for (const auto& kind : all_light_kinds()) {
    if (!kind.has_extent || !kind.compact) continue;  // an environment: its own test below
    SCOPED_TRACE(kind.id);
    const Example& e = examples().at(kind.id);
    SceneFixture f(light_scene(e.toml));
    std::mt19937 rng(11);
    std::vector<glm::vec4> a(n), b(n, glm::vec4(e.p, 0.0f));
    for (auto& v : a) v = glm::vec4(unit(rng), unit(rng), 0, 0);
    const auto r = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  vec3 p = b.xyz, dir;
  float dist, pdf;
  if (!sampleLightDirection(L, p, a.xy, dir, dist, pdf)) return vec4(0.0, 1.0, -1.0, 1.0);
  float hitDist;
  bool hit = lightHit(L, p, dir, hitDist);
  return vec4(dot(dir, lightCentreDirection(L, p)) / pdf, lightPdf(L, p, dir, dist) / pdf, hit ? 1.0 : 0.0,
              hit && dist < FAR_AWAY ? hitDist / dist : 1.0);
})",
                              a, b);
    const auto omega = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) { return vec4(lightSolidAngle(lights[0], a.xyz, lightCentreDirection(lights[0], a.xyz))); })",
                                  {glm::vec4(e.p, 0)}, {glm::vec4(0)});
    double sum = 0, sum2 = 0, worst_pdf = 0, worst_dist = 0;
    int rejected = 0, missed = 0;
    for (const auto& v : r) {
      sum += v.x;
      sum2 += double(v.x) * v.x;
      if (v.z < 0) {
        ++rejected;
        continue;
      }
      missed += v.z == 0.0f;
      worst_pdf = std::max(worst_pdf, std::abs(double(v.y) - 1));
      worst_dist = std::max(worst_dist, std::abs(double(v.w) - 1));
    }
    EXPECT_EQ(rejected, 0) << "the point sees the light: every sample is usable";
    EXPECT_LT(missed, n / 10000) << "samples that lightHit says miss the light (edges in float allowed)";
    EXPECT_LT(worst_pdf, 1e-5) << "lightPdf against the sample's pdf";
    EXPECT_LT(worst_dist, 1e-3) << "lightHit's distance against the sample's";
    const double mean = sum / n, sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    const double tolerance = 4 * sigma + (e.solid_angle_error + 1e-5) * mean;
    EXPECT_NEAR(omega[0].x, mean, tolerance) << "lightSolidAngle against the samples' estimate";
    std::printf("%s: solid angle %.6g, samples %.6g +- %.2g; pdf error %.2g, distance error %.2g, missed %d\n",
                kind.id.c_str(), omega[0].x, mean, sigma, worst_pdf, worst_dist, missed);
  }
}

TEST(LightKinds, PdfAndSolidAngleIntegrateOverTheDirectionsThatHit) {
  // Directions drawn here uniformly in a cone about the centre that holds the whole light: over
  // those lightHit accepts, lightPdf integrates to 1 and (dir . centre) to lightSolidAngle, the
  // projected solid angle (to second order for planar lights).
  const int n = 1 << 20;
  for (const auto& kind : all_light_kinds()) {
    if (!kind.has_extent || !kind.compact) continue;  // an environment: its own test below
    SCOPED_TRACE(kind.id);
    const Example& e = examples().at(kind.id);
    SceneFixture f(light_scene(e.toml));
    const auto centre = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) {
  vec3 lc = lightCentreDirection(lights[0], a.xyz);
  return vec4(lc, lightSolidAngle(lights[0], a.xyz, lc));
})",
                                   {glm::vec4(e.p, 0)}, {glm::vec4(0)});
    const glm::dvec3 axis = glm::normalize(glm::dvec3(centre[0]));
    const double omega = centre[0].w;
    // Three times the half-angle of the cone of equal solid angle holds these examples' lights.
    const double half = std::min(3 * std::asin(std::sqrt(std::min(omega / kPi, 1.0))), 0.5 * kPi);
    const double one_minus_cos = 2 * std::sin(0.5 * half) * std::sin(0.5 * half), cone = 2 * kPi * one_minus_cos;
    const glm::dvec3 t = glm::normalize(glm::cross(std::abs(axis.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), axis));
    const glm::dvec3 b = glm::cross(axis, t);
    std::mt19937 rng(13);
    std::vector<glm::vec4> dirs(n), points(n, glm::vec4(e.p, 0));
    for (auto& d : dirs) {
      const double v = one_minus_cos * unit(rng), phi = 2 * kPi * unit(rng), s = std::sqrt(v * (2 - v));
      d = glm::vec4(glm::vec3((1 - v) * axis + s * (std::cos(phi) * t + std::sin(phi) * b)), 0);
    }
    const auto r = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  vec3 dir = normalize(a.xyz);
  float dist;
  if (!lightHit(L, b.xyz, dir, dist)) return vec4(0.0);
  return vec4(lightPdf(L, b.xyz, dir, dist), dot(dir, lightCentreDirection(L, b.xyz)), 0.0, 0.0);
})",
                              dirs, points);
    double pdf_sum = 0, pdf_sum2 = 0, projected = 0, projected2 = 0;
    for (const auto& v : r) {
      pdf_sum += v.x * cone;
      pdf_sum2 += double(v.x * cone) * (v.x * cone);
      projected += v.y * cone;
      projected2 += double(v.y * cone) * (v.y * cone);
    }
    const double pdf_mean = pdf_sum / n, pdf_sigma = std::sqrt((pdf_sum2 / n - pdf_mean * pdf_mean) / n);
    const double proj_mean = projected / n, proj_sigma = std::sqrt((projected2 / n - proj_mean * proj_mean) / n);
    EXPECT_NEAR(pdf_mean, 1.0, 4 * pdf_sigma) << "lightPdf over the directions that hit";
    EXPECT_NEAR(omega, proj_mean, 4 * proj_sigma + e.solid_angle_error * proj_mean) << "lightSolidAngle";
    std::printf("%s: pdf integral %.4f +- %.4f; projected solid angle %.6g +- %.2g, lightSolidAngle %.6g\n",
                kind.id.c_str(), pdf_mean, pdf_sigma, proj_mean, proj_sigma, omega);
  }
}

TEST(LightKinds, RepresentativeDirectionLiesOnTheLight) {
  // A reflected ray that hits the light is its own representative direction; any other finds a
  // direction on the light's edge (nudged towards the centre, it hits).
  const int n = 4096;
  for (const auto& kind : all_light_kinds()) {
    if (!kind.has_extent || !kind.compact) continue;  // an environment: its own test below
    SCOPED_TRACE(kind.id);
    const Example& e = examples().at(kind.id);
    SceneFixture f(light_scene(e.toml));
    std::mt19937 rng(12);
    std::vector<glm::vec4> a(n), b(n);
    for (int i = 0; i < n; ++i) {
      const float z = 2 * unit(rng) - 1, phi = 2 * float(kPi) * unit(rng), s = std::sqrt(1 - z * z);
      a[i] = glm::vec4(unit(rng), unit(rng), 0, 0);
      b[i] = glm::vec4(s * std::cos(phi), s * std::sin(phi), z, 0);
    }
    const std::string p = "vec3(" + std::to_string(e.p.x) + ", " + std::to_string(e.p.y) + ", " + std::to_string(e.p.z) + ")";
    const auto r = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  vec3 p = )" + p + R"(, lc = lightCentreDirection(L, p);
  float sinHalf = sqrt(min(lightSolidAngle(L, p, lc) / PI, 1.0));
  vec3 dir;
  float dist, pdf, hitDist;
  sampleLightDirection(L, p, a.xy, dir, dist, pdf);
  float itself = dot(lightRepresentativeDirection(L, p, dir, lc, sinHalf), dir);
  vec3 edge = lightRepresentativeDirection(L, p, b.xyz, lc, sinHalf);
  bool onLight = lightHit(L, p, normalize(mix(edge, lc, 1e-3)), hitDist);
  return vec4(itself, onLight ? 1.0 : 0.0, dot(edge, edge), 0.0);
})",
                              a, b);
    double worst = 0;
    int off = 0;
    for (const auto& v : r) {
      worst = std::max(worst, 1.0 - v.x);
      off += v.y == 0.0f;
      ASSERT_NEAR(v.z, 1.0f, 1e-5f) << "a unit direction";
    }
    EXPECT_LT(worst, 1e-6) << "a direction on the light is its own representative";
    EXPECT_EQ(off, 0) << "representative directions off the light";
  }
}

TEST(LightKinds, OutlineHasTheLightsSolidAngle) {
  // lightOutline's ellipse (conjugate semi-axes dl1, dl2 in directions) covers pi |dl1 x dl2|:
  // the cone of equal solid angle for spheres and suns, the light projected along the centre
  // direction for planar lights (a quad as its ellipse of equal area) - lightSolidAngle each time.
  for (const auto& kind : all_light_kinds()) {
    if (!kind.has_extent || !kind.compact) continue;  // an environment: its own test below
    SCOPED_TRACE(kind.id);
    const Example& e = examples().at(kind.id);
    SceneFixture f(light_scene(e.toml));
    const auto r = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  vec3 p = a.xyz, lc = lightCentreDirection(L, p), dl1, dl2;
  float omega = lightSolidAngle(L, p, lc);
  lightOutline(L, p, lc, sqrt(min(omega / PI, 1.0)), dl1, dl2);
  return vec4(omega, PI * length(cross(dl1, dl2)), abs(dot(dl1, lc)) + abs(dot(dl2, lc)), 0.0);
})",
                              {glm::vec4(e.p, 0)}, {glm::vec4(0)});
    EXPECT_NEAR(r[0].y / r[0].x, 1.0, 1e-4) << "outline area against the solid angle";
    EXPECT_LT(r[0].z, 1e-6) << "the semi-axes are perpendicular to the centre direction";
  }
}

TEST(LightKinds, DiskAndPolygonFormsOutlineWhatLightHitSees) {
  // Rays from p through the form's outline scaled by 0.99 hit the light, by 1.01 miss it: the disk
  // form (the disk itself, or the disk facing p that subtends a sphere's or a sun's cone) and the
  // polygon form trace the light's silhouette. The disk form's angular radius is the cone of the
  // light's solid angle (exactly for cones, to first order for a disk).
  const int n = 64;
  for (const auto& kind : all_light_kinds()) {
    if (kind.form == LightForm::None) continue;
    SCOPED_TRACE(kind.id);
    const Example& e = examples().at(kind.id);
    SceneFixture f(light_scene(e.toml));
    std::vector<glm::vec4> a;
    for (float scale : {0.99f, 1.01f})
      for (int i = 0; i < n; ++i) a.emplace_back(scale, (i + 0.5f) / n, 0, 0);
    const std::vector<glm::vec4> b(a.size(), glm::vec4(e.p, 0));
    const auto r = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  vec3 p = b.xyz, q;
  float angularRadius = 0.0;
  if (lightForm(L) == LIGHT_FORM_DISK) {
    LightDisk disk = lightDiskForm(L, p);
    vec3 t, s;
    basisAround(disk.normal, t, s);
    float phi = TWO_PI * a.y;
    q = disk.centre + a.x * disk.radius * (cos(phi) * t + sin(phi) * s);
    angularRadius = disk.angularRadius;
  } else {
    vec3 v[LIGHT_POLYGON_MAX_VERTICES];
    int count = lightPolygonForm(L, v);
    vec3 middle = vec3(0.0);
    for (int i = 0; i < count; ++i) middle += v[i] / float(count);
    float x = a.y * float(count);
    int i = min(int(x), count - 1);
    vec3 edge = mix(v[i], v[(i + 1) % count], x - float(i));
    q = middle + a.x * (edge - middle);
  }
  float dist;
  bool hit = lightHit(L, p, normalize(q - p), dist);
  float omega = lightSolidAngle(L, p, lightCentreDirection(L, p));
  return vec4(hit ? 1.0 : 0.0, PI * sin(angularRadius) * sin(angularRadius) / omega, 0.0, 0.0);
})",
                              a, b);
    int inside_missed = 0, outside_hit = 0;
    for (std::size_t i = 0; i < r.size(); ++i) (i < std::size_t(n) ? inside_missed : outside_hit) += (r[i].x > 0.5f) != (i < std::size_t(n));
    EXPECT_EQ(inside_missed, 0) << "rays inside the form that miss the light";
    EXPECT_EQ(outside_hit, 0) << "rays outside the form that hit the light";
    if (kind.form == LightForm::Disk) {
      EXPECT_NEAR(r[0].y, 1.0, std::max(e.solid_angle_error, 2e-3)) << "the disk form's cone against the solid angle";
    }
  }
}

TEST(LightKinds, EnvironmentSamplesAndPdfCoverTheSphere) {
  // A light around the whole sphere (not compact): every sample hits it at infinity with
  // lightPdf's density, E[1 / pdf] over its samples is the sphere's 4 pi, and lightPdf over
  // uniformly drawn directions integrates to 1 (the studio map has no black texel).
  const int n = 1 << 18;
  const Example& e = examples().at("environment");
  SceneFixture f(light_scene(e.toml));
  f.gpu->resources().bind(f.gpu->scene_resource_ids(), f.gpu->resource_context());
  std::mt19937 rng(17);
  std::vector<glm::vec4> a(n), b(n, glm::vec4(e.p, 0.0f));
  for (auto& v : a) v = glm::vec4(unit(rng), unit(rng), unit(rng), unit(rng));
  const auto r = on_example(f, R"(
vec4 evaluate(vec4 a, vec4 b) {
  LightData L = lights[0];
  vec3 dir;
  float dist, pdf;
  if (!sampleLightDirection(L, b.xyz, a.xy, dir, dist, pdf)) return vec4(-1.0);
  float hitDist;
  bool hit = lightHit(L, b.xyz, dir, hitDist) && hitDist >= FAR_AWAY;
  // A uniform direction on the sphere from a.zw, and the density there.
  float z = 1.0 - 2.0 * a.z, s = sqrt(max(0.0, 1.0 - z * z));
  vec3 u = vec3(s * cos(TWO_PI * a.w), z, s * sin(TWO_PI * a.w));
  return vec4(1.0 / pdf, lightPdf(L, b.xyz, dir, dist) / pdf, hit ? 1.0 : 0.0, lightPdf(L, b.xyz, u, FAR_AWAY));
})",
                            a, b);
  double inverse = 0, inverse2 = 0, uniform = 0, uniform2 = 0, worst_pdf = 0;
  int rejected = 0, missed = 0;
  for (const auto& v : r) {
    if (v.x < 0) {
      ++rejected;
      continue;
    }
    inverse += v.x;
    inverse2 += double(v.x) * v.x;
    const double w = 4 * kPi * v.w;
    uniform += w;
    uniform2 += w * w;
    missed += v.z == 0.0f;
    worst_pdf = std::max(worst_pdf, std::abs(double(v.y) - 1));
  }
  EXPECT_EQ(rejected, 0);
  EXPECT_EQ(missed, 0) << "every direction reaches an environment";
  EXPECT_LT(worst_pdf, 1e-3) << "lightPdf against the sample's pdf";
  const double mi = inverse / n, si = std::sqrt((inverse2 / n - mi * mi) / n);
  const double mu = uniform / n, su = std::sqrt((uniform2 / n - mu * mu) / n);
  EXPECT_NEAR(mi, 4 * kPi, 4 * si) << "E[1 / pdf]: the sphere's solid angle";
  EXPECT_NEAR(mu, 1.0, 4 * su) << "lightPdf integrates to 1";
  std::printf("environment: E[1/pdf] %.5f +- %.2g (4 pi = %.5f); pdf integral %.4f +- %.4f\n", mi, si, 4 * kPi, mu, su);
}
