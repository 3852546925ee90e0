#include "path/ray_scene.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glintlab {
namespace {


std::string device_error_text(RTCDevice device) {
  switch (rtcGetDeviceError(device)) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

void check(RTCDevice device, const char* what) {
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed: " + device_error_text(device));
}

RTCIntersectContext context_for(RayCoherence coherence) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = coherence == RayCoherence::Coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                      : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  return context;
}

RTCRay to_embree(const Ray& ray) {
  RTCRay r{};
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.tnear = ray.t_near;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.tfar = ray.t_far;
  r.mask = std::numeric_limits<unsigned>::max();
  return r;
}

}  // namespace

void RayScene::DeviceDeleter::operator()(RTCDeviceTy* device) const { rtcReleaseDevice(device); }
void RayScene::SceneDeleter::operator()(RTCSceneTy* scene) const { rtcReleaseScene(scene); }

RayScene::RayScene(const Scene& scene) : device_(rtcNewDevice(nullptr)) {
  if (!device_) throw std::runtime_error("Embree: creating a device failed: " + device_error_text(nullptr));
  scene_.reset(rtcNewScene(device_.get()));
  check(device_.get(), "creating a scene");
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_HIGH);

  shapes_.reserve(scene.shapes.size());
  for (std::size_t index = 0; index < scene.shapes.size(); ++index) {
    const Shape& shape = scene.shapes[index];
    const Mesh& mesh = *shape.mesh;
    // The raster passes' vertex transform (passes/forward.vert): positions and tangents by the
    // model matrix, normals by its inverse transpose, the handedness flipped by a mirroring one.
    const glm::mat4& model = shape.transform;
    const glm::mat3 linear(model), normal_matrix = glm::transpose(glm::inverse(linear));
    const float mirrored = glm::determinant(linear) < 0.0f ? -1.0f : 1.0f;
    WorldShape& world = shapes_.emplace_back();
    world.material = shape.material;
    world.indices = mesh.indices;
    world.uvs = mesh.uvs;
    world.positions.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) world.positions.push_back(glm::vec3(model * glm::vec4(p, 1.0f)));
    for (const glm::vec3& n : mesh.normals) world.normals.push_back(normal_matrix * n);
    for (const glm::vec4& t : mesh.tangents) world.tangents.emplace_back(linear * glm::vec3(t), t.w * mirrored);

    RTCGeometry geometry = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), world.positions.size()));
    auto* triangles = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), mesh.triangle_count()));
    check(device_.get(), "allocating a shape's buffers");
    for (std::size_t v = 0; v < world.positions.size(); ++v)
      std::copy_n(&world.positions[v].x, 3, vertices + 3 * v);
    std::copy(mesh.indices.begin(), mesh.indices.begin() + 3 * mesh.triangle_count(), triangles);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene_.get(), geometry, static_cast<unsigned>(index));
    rtcReleaseGeometry(geometry);
    check(device_.get(), "adding a shape");
  }
  rtcCommitScene(scene_.get());
  check(device_.get(), "building the BVH");
}

RayScene::~RayScene() = default;

std::size_t RayScene::triangle_count() const {
  std::size_t count = 0;
  for (const WorldShape& shape : shapes_) count += shape.indices.size() / 3;
  return count;
}

template <typename Batch>
void RayScene::for_each_stream(std::size_t count, const Batch& batch) {
  // A range TBB hands out may hold more than its grain: it is cut into streams here.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, kStreamSize), [&](const auto& range) {
    for (std::size_t begin = range.begin(); begin < range.end(); begin += kStreamSize)
      batch(begin, std::min(kStreamSize, range.end() - begin));
  });
}

void RayScene::intersect(std::span<const Ray> rays, std::span<RayHit> hits, RayCoherence coherence) const {
  if (hits.size() != rays.size()) throw std::invalid_argument("RayScene::intersect: as many hits as rays needed");
  for_each_stream(rays.size(), [&](std::size_t begin, std::size_t count) {
    RTCRayHit stream[kStreamSize];
    for (std::size_t i = 0; i < count; ++i) {
      stream[i].ray = to_embree(rays[begin + i]);
      stream[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
      stream[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
    RTCIntersectContext context = context_for(coherence);
    rtcIntersect1M(scene_.get(), &context, stream, static_cast<unsigned>(count), sizeof(RTCRayHit));
    for (std::size_t i = 0; i < count; ++i) {
      const RTCRayHit& h = stream[i];
      hits[begin + i] = h.hit.geomID == RTC_INVALID_GEOMETRY_ID
                            ? RayHit{}
                            : RayHit{.t = h.ray.tfar,
                                     .shape = static_cast<int>(h.hit.geomID),
                                     .triangle = h.hit.primID,
                                     .barycentric = {h.hit.u, h.hit.v}};
    }
  });
}

void RayScene::occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked, RayCoherence coherence) const {
  if (blocked.size() != rays.size()) throw std::invalid_argument("RayScene::occluded: as many answers as rays needed");
  for_each_stream(rays.size(), [&](std::size_t begin, std::size_t count) {
    RTCRay stream[kStreamSize];
    for (std::size_t i = 0; i < count; ++i) stream[i] = to_embree(rays[begin + i]);
    RTCIntersectContext context = context_for(coherence);
    rtcOccluded1M(scene_.get(), &context, stream, static_cast<unsigned>(count), sizeof(RTCRay));
    // Embree marks an occluded ray by setting its tfar to -inf.
    for (std::size_t i = 0; i < count; ++i) blocked[begin + i] = stream[i].tfar < 0.0f ? 1 : 0;
  });
}

SurfacePoint RayScene::surface(const RayHit& hit) const {
  const WorldShape& shape = shapes_.at(static_cast<std::size_t>(hit.shape));
  const std::uint32_t i0 = shape.indices[3 * hit.triangle], i1 = shape.indices[3 * hit.triangle + 1],
                      i2 = shape.indices[3 * hit.triangle + 2];
  const float b1 = hit.barycentric.x, b2 = hit.barycentric.y, b0 = 1.0f - b1 - b2;
  auto blend = [&](const auto& values) { return b0 * values[i0] + b1 * values[i1] + b2 * values[i2]; };
  SurfacePoint point;
  point.position = blend(shape.positions);
  point.normal = shape.normals.empty() ? glm::vec3(0.0f) : blend(shape.normals);
  point.tangent = shape.tangents.empty() ? glm::vec4(0.0f) : blend(shape.tangents);
  point.uv = shape.uvs.empty() ? glm::vec2(0.0f) : blend(shape.uvs);
  point.geometric_normal = glm::normalize(
      glm::cross(shape.positions[i1] - shape.positions[i0], shape.positions[i2] - shape.positions[i0]));
  point.material = shape.material;
  if (shape.normals.empty()) point.normal = point.geometric_normal;
  return point;
}

}  // namespace glintlab
