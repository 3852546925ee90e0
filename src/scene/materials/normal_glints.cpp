#include "scene/materials/normal_glints.hpp"

#include <algorithm>
#include <cmath>

namespace glintlab {

float normal_glint_masking_alpha(const NormalMap& map, float intrinsic_roughness) {
  double sum = 0.0;
  for (const glm::vec3& n : map.normals) {
    const double z = std::max(static_cast<double>(n.z), 1e-3);  // as the GPU's slope moments: maps keep n.z > 0
    sum += (static_cast<double>(n.x) * n.x + static_cast<double>(n.y) * n.y) / (z * z);
  }
  const double mean = map.normals.empty() ? 0.0 : sum / static_cast<double>(map.normals.size());
  const double sigma = intrinsic_roughness;
  return static_cast<float>(std::sqrt(mean + 2.0 * sigma * sigma));
}

}  // namespace glintlab
