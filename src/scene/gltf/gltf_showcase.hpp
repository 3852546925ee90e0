#pragma once
// Procedural content for glintlab's own glTF files: images made from functions of uv, glintlab's
// generated meshes in glTF's conventions, and the showcase model that the `gltf-showcase` built-in
// scene loads (no third-party assets: everything here is computed).
#include <functional>

#include "scene/gltf/gltf_writer.hpp"
#include "scene/mesh.hpp"

namespace glintlab::gltf {

/// An image from a function of glTF uv at texel centres ((i + 0.5) / width, (j + 0.5) / height),
/// row j = 0 at the top; each channel in [0, 1] is clamped and rounded to 8 bits.
Image8 make_image(int width, int height, const std::function<glm::vec4(glm::vec2 uv)>& rgba);

/// A tangent-space normal map in glTF's convention from a function of uv giving the normal
/// (x right in the image, y up in the image, z out of the surface); it is normalised and stored as
/// n * 0.5 + 0.5, alpha 1.
Image8 make_normal_image(int width, int height, const std::function<glm::vec3(glm::vec2 uv)>& normal);

/// A glintlab Mesh (uv with v up, mesh.hpp) as a glTF primitive: uv become (u, 1 - v). TANGENT
/// (when asked for) is copied unchanged: both conventions put the bitangent w * cross(n, t) along
/// "up in the image" (glintlab: +v; glTF: -v, towards row 0), so the flip of v and the flip of the
/// rule cancel and w is the same number.
PrimitiveDesc primitive_from_mesh(const Mesh& mesh, bool with_tangents, int material);

/// The built-in scene's model: 5 materials (a checker ground with texture transforms and a
/// roughness/metal stripe texture; a dimple-normal-mapped gold sphere; a streaked anisotropic
/// dielectric torus with ior and specular; an emissive lantern with emissive strength; a ribbed
/// panel), 6 images, 5 meshes (the lantern with two primitives), a nested node hierarchy, three
/// KHR_lights_punctual lights and a perspective camera. TANGENT only on the sphere: the lantern's
/// caps share its normal-mapped material without TANGENT, and the panel and the torus (anisotropy)
/// need a frame built by the importer. Deterministic; 3982 triangles.
Document make_showcase_document();

}  // namespace glintlab::gltf
