#pragma once
// The CPU-side scene: film, camera and camera path, materials, shapes and lights.
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/gpu_contract.hpp"  // kMaxLights, kMaxMaterials: a scene's limits
#include "scene/camera.hpp"
#include "scene/lights/light_kind.hpp"
#include "scene/materials/material.hpp"
#include "scene/mesh.hpp"

namespace glintlab {

/// Limits of a scene that the scene file and the command line's overrides share.
inline constexpr int kMaxFilmSide = 16384;
inline constexpr double kMaxFilmPixels = 64.0 * 1024 * 1024;
inline constexpr int kMaxPathFrames = 100000;

struct Film {
  int width = 640;
  int height = 360;
  float exposure = 0.0f;  ///< stops, applied to displayed images only (never to metrics)
  float bloom = 0.0f;     ///< star bloom strength, displayed images only (0: none)
};

struct Shape {
  std::string type;                  ///< the generator or file kind it came from
  std::shared_ptr<const Mesh> mesh;  ///< object space
  glm::mat4 transform{1.0f};         ///< object to world
  int material = 0;                  ///< index into Scene::materials
};

struct Scene {
  std::string name;    ///< builtin name or file stem
  std::string source;  ///< "builtin:NAME" or the file path given by the user
  std::string description;  ///< the file's one-line `description` (listings only)
  Film film;
  Camera camera;
  CameraPath path;
  std::vector<Material> materials;
  std::vector<Shape> shapes;
  std::vector<Light> lights;
  std::vector<std::string> warnings;  ///< what loading ignored (e.g. a glTF extension), for the user

  /// Hash of everything that affects an image (geometry, maps, lights, camera, film), not of
  /// names: the reference cache's key.
  [[nodiscard]] std::uint64_t content_hash() const;
};

}  // namespace glintlab
