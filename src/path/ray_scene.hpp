#pragma once
// The scene's shapes in world space under Embree's BVH: closest hits and occlusion for batches of
// rays (Embree's stream queries, spread over TBB's threads), and the surface at a hit with its
// vertex attributes interpolated as the rasteriser interpolates them. The path tracer's host side
// (docs/methods.md, "Ray queries").
#include <cstdint>
#include <embree3/rtcore.h>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <span>
#include <vector>

#include "scene/lights/light_kind.hpp"
#include "scene/scene.hpp"

namespace glintlab {

/// What a ray sees (Embree's geometry masks): the scene's shapes, the visible lights' emitters.
inline constexpr unsigned kSeesShapes = 1u, kSeesEmitters = 2u, kSeesEverything = kSeesShapes | kSeesEmitters;

/// A ray segment: the points origin + t direction with t in [t_near, t_far].
struct Ray {
  glm::vec3 origin;
  float t_near = 0.0f;
  glm::vec3 direction;
  float t_far = 1e30f;
  unsigned sees = kSeesEverything;  ///< shadow rays see only shapes: the lights are exact shapes of their own
};

/// The closest hit along a ray, or none (shape < 0).
struct RayHit {
  float t = 0.0f;
  int shape = -1;               ///< index into Scene::shapes, or past them an emitter (RayScene::emitter)
  std::uint32_t triangle = 0;   ///< triangle of that shape's mesh
  glm::vec2 barycentric{0.0f};  ///< weights of the triangle's second and third vertices
  [[nodiscard]] bool hit() const { return shape >= 0; }
};

/// The surface at a hit, in world space: the vertex attributes interpolated at the hit's
/// barycentric coordinates (not normalised, as a rasteriser's varyings arrive), and the
/// triangle's own normal.
struct SurfacePoint {
  glm::vec3 position;
  glm::vec3 normal;            ///< interpolated vertex normal
  glm::vec4 tangent;           ///< interpolated tangent, w the handedness
  glm::vec2 uv;
  glm::vec3 geometric_normal;  ///< unit, the triangle's winding (p1 - p0) x (p2 - p0)
  int material = 0;
};

/// How the surface at a hit changes per step of the ray's film point (Igehy 1999): the hit point
/// moved on the triangle's plane, the attributes by the barycentric coordinates that move implies.
struct SurfaceDerivatives {
  glm::vec3 dPdx, dPdy;
  glm::vec3 dNdx, dNdy;  ///< of the interpolated (unnormalised) normal
  glm::vec4 dTdx, dTdy;  ///< of the interpolated tangent
  glm::vec2 dUVdx, dUVdy;
};

/// Camera rays and rays from a light or a point towards a light sample share directions and
/// origins (Embree's coherent traversal); bounces off rough surfaces do not.
enum class RayCoherence { Coherent, Incoherent };

class RayScene {
 public:
  /// Builds the BVH over every shape of `scene` (moved to world space). Throws std::runtime_error
  /// with Embree's message if the device or the build fails.
  explicit RayScene(const Scene& scene);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  /// The closest hit of each ray (hits.size() == rays.size()).
  void intersect(std::span<const Ray> rays, std::span<RayHit> hits, RayCoherence coherence) const;
  /// Whether anything lies on each ray's segment (blocked.size() == rays.size()).
  void occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked, RayCoherence coherence) const;
  /// The surface where `hit` (a hit) lies.
  [[nodiscard]] SurfacePoint surface(const RayHit& hit) const;
  /// Its derivatives along a ray of unit `direction` whose origin and direction move by its
  /// differentials dOdx .. dDdy per step x and y.
  [[nodiscard]] SurfaceDerivatives derivatives(const RayHit& hit, glm::vec3 direction, glm::vec3 dOdx, glm::vec3 dOdy,
                                               glm::vec3 dDdx, glm::vec3 dDdy) const;
  /// Its derivatives along two steps dPdx, dPdy of the point on the hit triangle's plane (the
  /// attributes' changes the barycentric steps that move the point by them imply).
  [[nodiscard]] SurfaceDerivatives derivatives_along(const RayHit& hit, glm::vec3 dPdx, glm::vec3 dPdy) const;
  /// The emitter a hit is on (a visible light with extent: LightKind::emitter), or null for a shape.
  [[nodiscard]] const LightEmitter* emitter(const RayHit& hit) const;

  [[nodiscard]] std::size_t triangle_count() const;

 private:
  /// Rays per stream query: enough for Embree to sort a coherent stream into packets, few enough
  /// for TBB to balance the streams over the threads.
  static constexpr std::size_t kStreamSize = 256;
  /// Calls batch(begin, count) on TBB's threads for streams of at most kStreamSize covering [0, count).
  template <typename Batch>
  static void for_each_stream(std::size_t count, const Batch& batch);

  /// A shape's mesh in world space (positions in Embree's buffer, the rest here).
  struct WorldShape {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
    int material = 0;
  };
  struct DeviceDeleter {
    void operator()(RTCDeviceTy* device) const;
  };
  struct SceneDeleter {
    void operator()(RTCSceneTy* scene) const;
  };

  std::unique_ptr<RTCDeviceTy, DeviceDeleter> device_;
  std::unique_ptr<RTCSceneTy, SceneDeleter> scene_;
  /// Adds a mesh in world space as geometry `id`, seen by rays whose mask meets `mask`.
  void attach(const Mesh& mesh, const glm::mat4& model, unsigned id, unsigned mask, WorldShape& world);

  std::vector<WorldShape> shapes_;     // the scene's shapes, then the emitters' meshes
  std::vector<LightEmitter> emitters_;  // geometry shapes_.size() - emitters_.size() + i
};

}  // namespace glintlab
