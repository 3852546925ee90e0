#include "path/ray_scene.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <type_traits>

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
  r.mask = ray.sees;
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

  for (const Shape& shape : scene.shapes) {
    WorldShape& world = shapes_.emplace_back();
    world.material = shape.material;
    attach(*shape.mesh, shape.transform, static_cast<unsigned>(shapes_.size() - 1), kSeesShapes, world);
  }
  // The visible lights' emitters, as the raster passes draw them (passes/emitter.frag).
  for (const Light& light : scene.lights)
    if (light.kind->emitter)
      if (std::optional<LightEmitter> e = light.kind->emitter(light)) emitters_.push_back(std::move(*e));
  for (const LightEmitter& e : emitters_) {
    WorldShape& world = shapes_.emplace_back();
    attach(e.mesh, e.transform, static_cast<unsigned>(shapes_.size() - 1), kSeesEmitters, world);
  }
  rtcCommitScene(scene_.get());
  check(device_.get(), "building the BVH");
}

void RayScene::attach(const Mesh& mesh, const glm::mat4& model, unsigned id, unsigned mask, WorldShape& world) {
  // The raster passes' vertex transform (passes/forward.vert): positions and tangents by the
  // model matrix, normals by its inverse transpose, the handedness flipped by a mirroring one.
  const glm::mat3 linear(model), normal_matrix = glm::transpose(glm::inverse(linear));
  const float mirrored = glm::determinant(linear) < 0.0f ? -1.0f : 1.0f;
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
  for (std::size_t v = 0; v < world.positions.size(); ++v) std::copy_n(&world.positions[v].x, 3, vertices + 3 * v);
  std::copy(mesh.indices.begin(), mesh.indices.begin() + 3 * mesh.triangle_count(), triangles);
  rtcSetGeometryMask(geometry, mask);
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene_.get(), geometry, id);
  rtcReleaseGeometry(geometry);
  check(device_.get(), "adding a shape");
}

const LightEmitter* RayScene::emitter(const RayHit& hit) const {
  const std::size_t first = shapes_.size() - emitters_.size(), index = static_cast<std::size_t>(hit.shape);
  return hit.hit() && index >= first ? &emitters_[index - first] : nullptr;
}

SurfaceDerivatives RayScene::derivatives(const RayHit& hit, glm::vec3 direction, glm::vec3 dOdx, glm::vec3 dOdy,
                                         glm::vec3 dDdx, glm::vec3 dDdy) const {
  const WorldShape& shape = shapes_.at(static_cast<std::size_t>(hit.shape));
  const std::uint32_t* v = &shape.indices[3 * hit.triangle];
  const glm::vec3 e1 = shape.positions[v[1]] - shape.positions[v[0]], e2 = shape.positions[v[2]] - shape.positions[v[0]];
  const glm::vec3 n = glm::cross(e1, e2);
  // The hit moves with the ray on the triangle's plane (Igehy 1999, eq. 10-12):
  // dP = dO + t dD + dt D with dt = -(dO + t dD).n / (D.n).
  const float t = hit.t, dn = glm::dot(direction, n);
  auto transfer = [&](glm::vec3 dO, glm::vec3 dD) {
    const glm::vec3 moved = dO + t * dD;
    return dn != 0.0f ? moved - direction * (glm::dot(moved, n) / dn) : moved;
  };
  return derivatives_along(hit, transfer(dOdx, dDdx), transfer(dOdy, dDdy));
}

SurfaceDerivatives RayScene::derivatives_along(const RayHit& hit, glm::vec3 dPdx, glm::vec3 dPdy) const {
  const WorldShape& shape = shapes_.at(static_cast<std::size_t>(hit.shape));
  const std::uint32_t* v = &shape.indices[3 * hit.triangle];
  const glm::vec3 e1 = shape.positions[v[1]] - shape.positions[v[0]], e2 = shape.positions[v[2]] - shape.positions[v[0]];
  SurfaceDerivatives d;
  d.dPdx = dPdx;
  d.dPdy = dPdy;
  // The barycentric steps that move the point by dP: dP = db1 e1 + db2 e2 (least squares on the plane).
  const float a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2), det = a * c - b * b;
  auto barycentric = [&](glm::vec3 dP) {
    if (det <= 0.0f) return glm::vec2(0.0f);
    const float p = glm::dot(e1, dP), q = glm::dot(e2, dP);
    return glm::vec2(c * p - b * q, a * q - b * p) / det;
  };
  const glm::vec2 bx = barycentric(d.dPdx), by = barycentric(d.dPdy);
  auto step = [&](const auto& values, glm::vec2 db) {
    using Value = std::decay_t<decltype(values[0])>;
    if (values.empty()) return Value(0.0f);
    return db.x * (values[v[1]] - values[v[0]]) + db.y * (values[v[2]] - values[v[0]]);
  };
  d.dNdx = step(shape.normals, bx);
  d.dNdy = step(shape.normals, by);
  d.dTdx = step(shape.tangents, bx);
  d.dTdy = step(shape.tangents, by);
  d.dUVdx = step(shape.uvs, bx);
  d.dUVdy = step(shape.uvs, by);
  return d;
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
