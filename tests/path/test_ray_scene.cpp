// Embree's hits against shapes whose surface is known in closed form, and its two queries
// (closest hit, occlusion) against each other.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>
#include <vector>

#include "path/ray_scene.hpp"
#include "scene/scene_loader.hpp"

using namespace glintlab;

namespace {

Scene one_shape(Mesh mesh, glm::mat4 transform, int material = 0) {
  Scene scene;
  scene.materials.resize(static_cast<std::size_t>(material) + 1);
  scene.shapes.push_back(Shape{.type = "test", .mesh = std::make_shared<const Mesh>(std::move(mesh)),
                               .transform = transform, .material = material});
  return scene;
}

glm::vec3 unit_vector(std::mt19937& random) {
  std::normal_distribution<float> gauss;
  return glm::normalize(glm::vec3(gauss(random), gauss(random), gauss(random)));
}

}  // namespace

TEST(RayScene, HitsATessellatedSphereWhereTheSphereIs) {
  const glm::vec3 centre(1.0f, 2.0f, 3.0f);
  const float radius = 0.5f;
  const RayScene scene(one_shape(make_sphere(1.0f, 256, 128),
                                 glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(radius)), 2));
  // The tessellation's facets lie inside the sphere by at most its sagitta, r (1 - cos(pi / 128)).
  const float sagitta = radius * (1.0f - std::cos(3.14159265f / 128.0f));
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<Ray> rays;
  std::vector<float> miss_distance;  // > 0: how far outside the sphere the ray passes
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 origin = centre + 3.0f * unit_vector(random);
    // Aimed within 0.9 r of the centre (hits) or from 1.1 r to 2 r (misses).
    const float offset = i % 2 == 0 ? 0.9f * radius * uniform(random) : radius * (1.1f + 0.9f * uniform(random));
    glm::vec3 d = glm::normalize(centre - origin), side = glm::normalize(glm::cross(d, unit_vector(random)));
    const glm::vec3 aim = centre + offset * side;
    rays.push_back(Ray{.origin = origin, .direction = glm::normalize(aim - origin)});
    miss_distance.push_back(offset - radius);
  }
  std::vector<RayHit> hits(rays.size());
  scene.intersect(rays, hits, RayCoherence::Incoherent);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Ray& ray = rays[i];
    // The analytic sphere's first intersection.
    const glm::vec3 oc = ray.origin - centre;
    const float b = glm::dot(oc, ray.direction), c = glm::dot(oc, oc) - radius * radius;
    const float discriminant = b * b - c;
    if (miss_distance[i] > 0.0f) {
      EXPECT_FALSE(hits[i].hit()) << "ray " << i << " passes " << miss_distance[i] << " outside the sphere";
      continue;
    }
    ASSERT_TRUE(hits[i].hit()) << "ray " << i;
    const float t = -b - std::sqrt(discriminant);
    // Along the ray a facet sagitta deep lies further by at most sagitta / cos(incidence).
    const float cos_incidence = std::sqrt(discriminant) / radius;
    EXPECT_GE(hits[i].t, t - 1e-5f) << "ray " << i;
    EXPECT_LE(hits[i].t, t + 1.01f * sagitta / cos_incidence + 1e-5f) << "ray " << i;
    const SurfacePoint point = scene.surface(hits[i]);
    EXPECT_EQ(point.material, 2);
    EXPECT_LT(glm::length(point.position - (ray.origin + hits[i].t * ray.direction)), 1e-5f);
    const glm::vec3 truth = glm::normalize(point.position - centre);
    EXPECT_GT(glm::dot(glm::normalize(point.normal), truth), 0.9999f) << "the interpolated normal, ray " << i;
    EXPECT_GT(glm::dot(point.geometric_normal, truth), 0.999f) << "the facet's normal, ray " << i;
  }
}

TEST(RayScene, InterpolatesAttributesAsTheRasteriserUnderAMirroringTransform) {
  // A 2 x 4 plane (uv over [0, 3]^2) tilted, scaled unevenly and mirrored in x, stood up and moved: uv, normal and tangent at
  // a hit are the plane's closed form carried through the same transform as passes/forward.vert's.
  const glm::mat4 model = glm::rotate(glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), {0.5f, 1.0f, -2.0f}), 0.7f,
                                                             {1, 0, 0}),
                                                 {-1.5f, 1.0f, 0.7f}),
                                      0.5f, {0, 0, 1});
  const RayScene scene(one_shape(make_plane({2.0f, 4.0f}, 3.0f), model));
  const glm::mat4 to_object = glm::inverse(model);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> uniform(-0.45f, 0.45f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec3 object(2.0f * uniform(random), 0.0f, 4.0f * uniform(random));
    const glm::vec3 world = glm::vec3(model * glm::vec4(object, 1.0f));
    const glm::vec3 origin = world + 2.0f * unit_vector(random);
    const Ray ray{.origin = origin, .direction = glm::normalize(world - origin)};
    std::vector<RayHit> hit(1);
    scene.intersect({&ray, 1}, hit, RayCoherence::Coherent);
    ASSERT_TRUE(hit[0].hit());
    const SurfacePoint point = scene.surface(hit[0]);
    const glm::vec3 at = glm::vec3(to_object * glm::vec4(point.position, 1.0f));
    EXPECT_LT(glm::length(point.position - world), 1e-4f);
    EXPECT_NEAR(point.uv.x, (at.x / 2.0f + 0.5f) * 3.0f, 1e-4f);
    EXPECT_NEAR(point.uv.y, (0.5f - at.z / 4.0f) * 3.0f, 1e-4f);
    const glm::vec3 normal = glm::normalize(glm::transpose(glm::inverse(glm::mat3(model))) * glm::vec3(0, 1, 0));
    EXPECT_GT(glm::dot(glm::normalize(point.normal), normal), 0.99999f);
    // +u runs along object +x, which the mirror turns to world -x; the handedness flips with it.
    EXPECT_GT(glm::dot(glm::normalize(glm::vec3(point.tangent)), glm::normalize(glm::mat3(model) * glm::vec3(1, 0, 0))),
              0.99999f);
    const glm::vec4 unmirrored = make_plane({2.0f, 4.0f}, 3.0f).tangents[0];
    EXPECT_NEAR(point.tangent.w, -unmirrored.w, 1e-5f);
  }
}

TEST(RayScene, OcclusionAgreesWithTheClosestHitAndBatchesAnswerAsSingleRays) {
  const Scene loaded = load_scene("builtin:every-family");
  const RayScene scene(loaded);
  ASSERT_GT(scene.triangle_count(), 1000u);
  std::mt19937 random(3);
  std::uniform_real_distribution<float> uniform(-3.0f, 3.0f), length(0.05f, 6.0f);
  std::vector<Ray> rays;
  for (int i = 0; i < 4000; ++i)
    rays.push_back(Ray{.origin = {uniform(random), 0.5f * uniform(random) + 1.5f, uniform(random)},
                       .direction = unit_vector(random),
                       .t_far = length(random)});
  std::vector<RayHit> hits(rays.size()), coherent(rays.size());
  std::vector<std::uint8_t> blocked(rays.size());
  scene.intersect(rays, hits, RayCoherence::Incoherent);
  scene.intersect(rays, coherent, RayCoherence::Coherent);
  scene.occluded(rays, blocked, RayCoherence::Incoherent);
  int hit_count = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    std::vector<RayHit> single(1);
    scene.intersect({&rays[i], 1}, single, RayCoherence::Incoherent);
    EXPECT_EQ(single[0].shape, hits[i].shape) << "ray " << i;
    EXPECT_EQ(single[0].t, hits[i].t) << "ray " << i;
    EXPECT_EQ(coherent[i].shape, hits[i].shape) << "ray " << i;
    EXPECT_EQ(coherent[i].triangle, hits[i].triangle) << "ray " << i;
    EXPECT_EQ(static_cast<bool>(blocked[i]), hits[i].hit()) << "ray " << i << ", t " << hits[i].t;
    hit_count += hits[i].hit();
  }
  // Both answers occur, so the agreement is not vacuous.
  EXPECT_GT(hit_count, 400);
  EXPECT_LT(hit_count, 3600);
}

TEST(RayScene, EmittersAreSeenByCameraRaysAsTheirOwnLightAndNeverByShadowRays) {
  // Two quads and a sphere light of different radiances, each on its own ray from the origin.
  const Scene scene = parse_scene(R"(
[film]
width = 16
height = 16
[camera]
position = [0, 0, 5]
target = [0, 0, 0]
[[material]]
name = "m"
[[shape]]
type = "sphere"
material = "m"
radius = 0.2
translate = [0, 0, -3]
[[light]]
type = "quad"
position = [2, 0, 0]
direction = [-1, 0, 0]
radiance = 2
[[light]]
type = "quad"
position = [0, 2, 0]
direction = [0, -1, 0]
radiance = 3
[[light]]
type = "sphere"
position = [0, 0, 2]
radius = 0.5
radiance = 5
)",
                                  "emitters.toml", ".");
  const RayScene rays(scene);
  const std::vector<Ray> camera = {
      {.origin = {0, 0, 0}, .direction = {1, 0, 0}},  {.origin = {0, 0, 0}, .direction = {0, 1, 0}},
      {.origin = {0, 0, 0}, .direction = {0, 0, 1}},  {.origin = {0, 0, 0}, .direction = {0, 0, -1}},
      {.origin = {0, 0, 0}, .direction = {-1, 0, 0}}};
  std::vector<RayHit> hits(camera.size());
  rays.intersect(camera, hits, RayCoherence::Incoherent);
  const float expected[] = {2.0f, 3.0f, 5.0f};
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(hits[i].hit()) << "ray " << i;
    const LightEmitter* e = rays.emitter(hits[i]);
    ASSERT_NE(e, nullptr) << "ray " << i;
    EXPECT_EQ(e->radiance, glm::vec3(expected[i])) << "ray " << i;
  }
  ASSERT_TRUE(hits[3].hit());
  EXPECT_EQ(rays.emitter(hits[3]), nullptr) << "the sphere shape is no emitter";
  EXPECT_EQ(rays.surface(hits[3]).material, 0);
  EXPECT_FALSE(hits[4].hit());
  // Shadow rays see the shapes only.
  std::vector<Ray> shadow = camera;
  for (Ray& r : shadow) r.sees = kSeesShapes;
  std::vector<std::uint8_t> blocked(shadow.size());
  rays.occluded(shadow, blocked, RayCoherence::Incoherent);
  EXPECT_EQ(blocked, (std::vector<std::uint8_t>{0, 0, 0, 1, 0}));
}
