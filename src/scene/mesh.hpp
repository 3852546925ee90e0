#pragma once
// Triangle meshes in object space and the procedural shape generators of the scene format.
// Tangents are vec4: xyz along +u, w = handedness so that bitangent = w * cross(normal, tangent).
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

namespace glintlab {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec4> tangents;
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices;

  [[nodiscard]] std::size_t triangle_count() const { return indices.size() / 3; }
  /// Appends another mesh (used to merge generated pieces).
  void append(const Mesh& other);
  /// Checks sizes, index ranges and finiteness; returns an empty string or what is wrong.
  [[nodiscard]] std::string validate() const;
};

/// Fills `normals` with smooth, area-weighted vertex normals (for meshes that come without them).
void compute_normals(Mesh& mesh);
/// Fills `tangents` from uv gradients (per-vertex accumulation, Gram-Schmidt against the normal).
void compute_tangents(Mesh& mesh);

Mesh make_sphere(float radius, int segments, int rings);
/// Square in the xz plane, normal +y, uv in [0, uv_scale]^2.
Mesh make_plane(glm::vec2 size, float uv_scale, int subdivisions = 1);
/// Disk in the xz plane, normal +y.
Mesh make_disk(float radius, int segments);
/// Torus around the y axis.
Mesh make_torus(float major_radius, float minor_radius, int segments, int sides);
/// Tube of constant radius around a Catmull-Rom curve through `points` (uv: u along, v around).
Mesh make_tube(const std::vector<glm::vec3>& points, float radius, int segments_per_span, int sides);
/// The vertices make_tube makes: known before generating, since many points with many segments
/// and sides reach billions (beyond memory and 32-bit indices).
std::uint64_t tube_vertex_count(std::size_t points, int segments_per_span, int sides);
/// The most vertices one generated shape may have: above the largest sphere, torus and plane
/// (4097^2); ~1.5 GiB of vertex data on the host, as much again on the GPU.
inline constexpr std::uint64_t kMaxShapeVertices = std::uint64_t{1} << 25;

}  // namespace glintlab
