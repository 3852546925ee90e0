// Camera rays against the raster passes' own camera: every point of a ray projects back to the
// film point it was made for, and its differentials are its derivatives.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "path/camera_rays.hpp"

using namespace glintlab;

namespace {

Camera tilted_camera(Projection projection) {
  Camera camera;
  camera.projection = projection;
  camera.position = {1.5f, 2.0f, 4.0f};
  camera.target = {-0.3f, 0.2f, 0.1f};
  camera.fov_y_degrees = 35.0f;
  camera.view_height = 3.0f;
  return camera;
}

// The film point (pixels, y down) where the raster passes draw world point x.
glm::vec3 film_point(const Camera& camera, glm::ivec2 film, glm::vec3 x) {
  const glm::vec4 clip = camera.projection_matrix(static_cast<float>(film.x) / static_cast<float>(film.y)) *
                         camera.view_matrix() * glm::vec4(x, 1.0f);
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x + 1.0f) * 0.5f * static_cast<float>(film.x), (1.0f - ndc.y) * 0.5f * static_cast<float>(film.y), ndc.z};
}

class CameraRaysIn : public testing::TestWithParam<Projection> {};

}  // namespace

TEST_P(CameraRaysIn, EveryPointOfARayProjectsToItsFilmPoint) {
  const Camera camera = tilted_camera(GetParam());
  const glm::ivec2 film(64, 36);
  const CameraRays rays(camera, film);
  for (glm::vec2 p : {glm::vec2(0.5f, 0.5f), glm::vec2(31.25f, 17.75f), glm::vec2(63.9f, 0.1f), glm::vec2(5.0f, 35.5f)}) {
    const RayDifferential ray = rays.at(p);
    EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-6f);
    EXPECT_NEAR(film_point(camera, film, ray.origin).z, -1.0f, 1e-4f) << "the ray starts on the near plane";
    for (float t : {0.5f, 3.0f, 20.0f}) {
      const glm::vec3 q = film_point(camera, film, ray.origin + t * ray.direction);
      EXPECT_NEAR(q.x, p.x, 2e-3f) << "t " << t;
      EXPECT_NEAR(q.y, p.y, 2e-3f) << "t " << t;
    }
  }
}

TEST_P(CameraRaysIn, DifferentialsAreTheRaysDerivativesPerPixel) {
  const CameraRays rays(tilted_camera(GetParam()), {64, 36});
  const float h = 0.25f;  // the origins are affine in the film point; the directions nearly so
  for (glm::vec2 p : {glm::vec2(0.5f, 0.5f), glm::vec2(40.0f, 20.0f), glm::vec2(63.5f, 35.5f)}) {
    const RayDifferential ray = rays.at(p);
    const RayDifferential right = rays.at(p + glm::vec2(h, 0.0f)), left = rays.at(p - glm::vec2(h, 0.0f));
    const RayDifferential down = rays.at(p + glm::vec2(0.0f, h)), up = rays.at(p - glm::vec2(0.0f, h));
    auto expect_near = [](glm::vec3 a, glm::vec3 b, float scale, const char* what) {
      EXPECT_LT(glm::length(a - b), 2e-3f * scale + 1e-6f) << what;
    };
    expect_near((right.origin - left.origin) / (2.0f * h), ray.dOdx, glm::length(ray.dOdx), "dO/dx");
    expect_near((down.origin - up.origin) / (2.0f * h), ray.dOdy, glm::length(ray.dOdy), "dO/dy");
    expect_near((right.direction - left.direction) / (2.0f * h), ray.dDdx, glm::length(ray.dDdx), "dD/dx");
    expect_near((down.direction - up.direction) / (2.0f * h), ray.dDdy, glm::length(ray.dDdy), "dD/dy");
    EXPECT_NEAR(glm::dot(ray.dDdx, ray.direction), 0.0f, 1e-7f) << "a unit direction turns, it does not stretch";
  }
}

INSTANTIATE_TEST_SUITE_P(Projections, CameraRaysIn, testing::Values(Projection::Perspective, Projection::Orthographic),
                         [](const auto& info) {
                           return info.param == Projection::Perspective ? "Perspective" : "Orthographic";
                         });

TEST(CameraRays, OrthographicRaysAreParallelAndPerspectiveRaysShareTheEye) {
  Camera camera = tilted_camera(Projection::Orthographic);
  const CameraRays parallel(camera, {64, 36});
  const glm::vec3 forward = glm::normalize(camera.target - camera.position);
  for (glm::vec2 p : {glm::vec2(0.5f, 0.5f), glm::vec2(63.5f, 35.5f)}) {
    const RayDifferential ray = parallel.at(p);
    EXPECT_LT(glm::length(ray.direction - forward), 1e-5f);
    EXPECT_LT(glm::length(ray.dDdx) + glm::length(ray.dDdy), 1e-6f);
    EXPECT_NEAR(glm::length(ray.dOdx), camera.view_height / 36.0f, 1e-5f) << "one pixel of the view's height";
  }
  camera.projection = Projection::Perspective;
  const CameraRays pinhole(camera, {64, 36});
  for (glm::vec2 p : {glm::vec2(0.5f, 0.5f), glm::vec2(63.5f, 35.5f)}) {
    const RayDifferential ray = pinhole.at(p);
    // Back from the near plane to the eye along the ray.
    const float back = glm::dot(ray.origin - camera.position, ray.direction);
    EXPECT_LT(glm::length(ray.origin - back * ray.direction - camera.position), 1e-5f);
  }
}
