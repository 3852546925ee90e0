#include "scene/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

namespace glintlab {

void Mesh::append(const Mesh& other) {
  const auto base = static_cast<std::uint32_t>(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  tangents.insert(tangents.end(), other.tangents.begin(), other.tangents.end());
  uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  for (auto i : other.indices) indices.push_back(base + i);
}

std::string Mesh::validate() const {
  const auto n = positions.size();
  if (n == 0 || indices.empty()) return "mesh has no triangles";
  if (indices.size() % 3 != 0) return "index count " + std::to_string(indices.size()) + " is not a multiple of 3";
  if (normals.size() != n || uvs.size() != n || (!tangents.empty() && tangents.size() != n))
    return "vertex attribute counts differ";
  for (auto i : indices)
    if (i >= n) return "index " + std::to_string(i) + " out of range (" + std::to_string(n) + " vertices)";
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(positions[i][c]) || !std::isfinite(normals[i][c]))
        return "vertex " + std::to_string(i) + " has a non-finite position or normal";
  return {};
}

void compute_normals(Mesh& m) {
  m.normals.assign(m.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const auto a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    const glm::vec3 n = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
    m.normals[a] += n;
    m.normals[b] += n;
    m.normals[c] += n;
  }
  for (auto& n : m.normals) n = glm::dot(n, n) > 0 ? glm::normalize(n) : glm::vec3(0, 1, 0);
}

void compute_tangents(Mesh& mesh) {
  const auto n = mesh.positions.size();
  std::vector<glm::vec3> tan(n, glm::vec3(0.0f)), bitan(n, glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const auto i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    const glm::vec3 e1 = mesh.positions[i1] - mesh.positions[i0];
    const glm::vec3 e2 = mesh.positions[i2] - mesh.positions[i0];
    const glm::vec2 d1 = mesh.uvs[i1] - mesh.uvs[i0];
    const glm::vec2 d2 = mesh.uvs[i2] - mesh.uvs[i0];
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-20f) continue;
    const float r = 1.0f / det;
    const glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) * r;
    const glm::vec3 tdir = (e2 * d1.x - e1 * d2.x) * r;
    for (auto i : {i0, i1, i2}) {
      tan[i] += sdir;
      bitan[i] += tdir;
    }
  }
  mesh.tangents.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 nrm = mesh.normals[i];
    glm::vec3 t = tan[i] - nrm * glm::dot(nrm, tan[i]);
    if (glm::dot(t, t) < 1e-20f) {  // no uv gradient: any vector orthogonal to the normal
      t = std::abs(nrm.x) < 0.9f ? glm::cross(nrm, glm::vec3(1, 0, 0)) : glm::cross(nrm, glm::vec3(0, 1, 0));
    }
    t = glm::normalize(t);
    const float w = glm::dot(glm::cross(nrm, t), bitan[i]) < 0.0f ? -1.0f : 1.0f;
    mesh.tangents[i] = glm::vec4(t, w);
  }
}

Mesh make_sphere(float radius, int segments, int rings) {
  Mesh m;
  for (int r = 0; r <= rings; ++r) {
    const float v = static_cast<float>(r) / static_cast<float>(rings);
    const float theta = v * glm::pi<float>();
    for (int s = 0; s <= segments; ++s) {
      const float u = static_cast<float>(s) / static_cast<float>(segments);
      const float phi = u * glm::two_pi<float>();
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      m.positions.push_back(radius * n);
      m.normals.push_back(n);
      m.uvs.emplace_back(u, 1.0f - v);
      // d/dphi of the position, well defined at the poles too.
      m.tangents.emplace_back(glm::normalize(glm::vec3(-std::sin(phi), 0.0f, -std::cos(phi))), 1.0f);
    }
  }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const auto a = static_cast<std::uint32_t>(r * (segments + 1) + s);
      const auto b = a + static_cast<std::uint32_t>(segments + 1);
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  // The analytic tangent is d/du; fix handedness against the uv layout.
  compute_tangents(m);
  return m;
}

Mesh make_plane(glm::vec2 size, float uv_scale, int subdivisions) {
  Mesh m;
  const int n = std::max(1, subdivisions);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(n);
      const float v = static_cast<float>(j) / static_cast<float>(n);
      m.positions.emplace_back((u - 0.5f) * size.x, 0.0f, (0.5f - v) * size.y);
      m.normals.emplace_back(0, 1, 0);
      m.uvs.emplace_back(u * uv_scale, v * uv_scale);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto a = static_cast<std::uint32_t>(j * (n + 1) + i);
      const auto b = a + static_cast<std::uint32_t>(n + 1);
      m.indices.insert(m.indices.end(), {a, a + 1, b, b, a + 1, b + 1});
    }
  compute_tangents(m);
  return m;
}

Mesh make_disk(float radius, int segments) {
  Mesh m;
  m.positions.emplace_back(0.0f);
  m.normals.emplace_back(0, 1, 0);
  m.uvs.emplace_back(0.5f, 0.5f);
  for (int s = 0; s <= segments; ++s) {
    const float phi = glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
    const float c = std::cos(phi), sn = std::sin(phi);
    m.positions.emplace_back(radius * c, 0.0f, -radius * sn);
    m.normals.emplace_back(0, 1, 0);
    m.uvs.emplace_back(0.5f + 0.5f * c, 0.5f + 0.5f * sn);
  }
  for (int s = 0; s < segments; ++s)
    m.indices.insert(m.indices.end(), {0u, static_cast<std::uint32_t>(s + 1), static_cast<std::uint32_t>(s + 2)});
  compute_tangents(m);
  return m;
}

Mesh make_torus(float major_radius, float minor_radius, int segments, int sides) {
  Mesh m;
  for (int i = 0; i <= segments; ++i) {
    const float u = static_cast<float>(i) / static_cast<float>(segments);
    const float phi = u * glm::two_pi<float>();
    const glm::vec3 centre(major_radius * std::cos(phi), 0.0f, -major_radius * std::sin(phi));
    const glm::vec3 outward(std::cos(phi), 0.0f, -std::sin(phi));
    for (int j = 0; j <= sides; ++j) {
      const float v = static_cast<float>(j) / static_cast<float>(sides);
      const float theta = v * glm::two_pi<float>();
      const glm::vec3 n = std::cos(theta) * outward + std::sin(theta) * glm::vec3(0, 1, 0);
      m.positions.push_back(centre + minor_radius * n);
      m.normals.push_back(n);
      m.uvs.emplace_back(u, v);
    }
  }
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < sides; ++j) {
      const auto a = static_cast<std::uint32_t>(i * (sides + 1) + j);
      const auto b = a + static_cast<std::uint32_t>(sides + 1);
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  compute_tangents(m);
  return m;
}

std::uint64_t tube_vertex_count(std::size_t points, int segments_per_span, int sides) {
  const std::uint64_t curve = points == 2 ? 2 : (points - 1) * static_cast<std::uint64_t>(segments_per_span) + 1;
  return curve * static_cast<std::uint64_t>(sides + 1);
}

Mesh make_tube(const std::vector<glm::vec3>& points, float radius, int segments_per_span, int sides) {
  // Centripetal-free uniform Catmull-Rom through the points, with the end points duplicated.
  std::vector<glm::vec3> curve;
  const auto n = points.size();
  auto p = [&](std::ptrdiff_t i) { return points[static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, static_cast<std::ptrdiff_t>(n) - 1))]; };
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const auto k = static_cast<std::ptrdiff_t>(i);
    const glm::vec3 p0 = p(k - 1), p1 = p(k), p2 = p(k + 1), p3 = p(k + 2);
    const int steps = n == 2 ? 1 : segments_per_span;
    for (int s = 0; s < steps; ++s) {
      const float t = static_cast<float>(s) / static_cast<float>(steps);
      const float t2 = t * t, t3 = t2 * t;
      curve.push_back(0.5f * ((2.0f * p1) + (-p0 + p2) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                              (-p0 + 3.0f * p1 - 3.0f * p2 + p3) * t3));
    }
  }
  curve.push_back(points.back());
  // Parallel-transport frames along the curve (no twisting).
  Mesh m;
  glm::vec3 prev_t = glm::normalize(curve[1] - curve[0]);
  glm::vec3 normal = std::abs(prev_t.y) < 0.9f ? glm::normalize(glm::cross(prev_t, glm::vec3(0, 1, 0)))
                                               : glm::normalize(glm::cross(prev_t, glm::vec3(1, 0, 0)));
  float length = 0.0f;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const glm::vec3 t = glm::normalize(i + 1 < curve.size() ? curve[i + 1] - curve[i] : curve[i] - curve[i - 1]);
    const glm::vec3 axis = glm::cross(prev_t, t);
    if (glm::length(axis) > 1e-6f) {
      const float angle = std::acos(std::clamp(glm::dot(prev_t, t), -1.0f, 1.0f));
      const glm::vec3 a = glm::normalize(axis);
      normal = normal * std::cos(angle) + glm::cross(a, normal) * std::sin(angle) +
               a * glm::dot(a, normal) * (1.0f - std::cos(angle));
    }
    normal = glm::normalize(normal - t * glm::dot(normal, t));
    const glm::vec3 binormal = glm::cross(t, normal);
    if (i > 0) length += glm::length(curve[i] - curve[i - 1]);
    for (int j = 0; j <= sides; ++j) {
      const float v = static_cast<float>(j) / static_cast<float>(sides);
      const float theta = v * glm::two_pi<float>();
      const glm::vec3 nrm = std::cos(theta) * normal + std::sin(theta) * binormal;
      m.positions.push_back(curve[i] + radius * nrm);
      m.normals.push_back(nrm);
      m.uvs.emplace_back(length / (glm::two_pi<float>() * radius), v);
    }
    prev_t = t;
  }
  for (std::size_t i = 0; i + 1 < curve.size(); ++i)
    for (int j = 0; j < sides; ++j) {
      const auto a = static_cast<std::uint32_t>(i * static_cast<std::size_t>(sides + 1) + static_cast<std::size_t>(j));
      const auto b = a + static_cast<std::uint32_t>(sides + 1);
      m.indices.insert(m.indices.end(), {a, a + 1, b, b, a + 1, b + 1});
    }
  compute_tangents(m);
  return m;
}

}  // namespace glintlab
