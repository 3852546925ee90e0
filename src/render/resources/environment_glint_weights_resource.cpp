// Resource `environment-glint-weights` (kneiphof2025's): the scene environment's luminance-level
// weights (src/scene/lights/environment_glint_levels.hpp) prefiltered by the radiance's own GGX
// chain, so that at any direction and roughness the weights are the shares of the lobe's reflected
// directions in each region; the levels themselves travel in the light's record (axis_u). A scene
// without an environment gets a 1 x 1 chain of zeros (nothing reads it there).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/gpu_contract.hpp"
#include "gl/context.hpp"
#include "gl/objects.hpp"
#include "render/resources/resource.hpp"
#include "render/resources/scene_environment.hpp"
#include "scene/lights/environment_glint_levels.hpp"
#include "scene/lights/environment_prefilter.hpp"

namespace glintlab {

namespace {

class EnvironmentGlintWeightsResource : public GpuResource {
 public:
  explicit EnvironmentGlintWeightsResource(const EnvironmentMap* map) {
    std::vector<Image> levels = {Image(1, 1)};
    if (map) levels = prefilter_environment_specular(environment_glint_levels(widened_for_specular_chain(map->radiance)).weights);
    texture_ = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.id(), static_cast<GLsizei>(levels.size()), GL_RGB32F, levels[0].width(),
                       levels[0].height());
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);         // around in azimuth
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);  // not over the poles
    for (std::size_t m = 0; m < levels.size(); ++m) {
      const int w = std::max(1, levels[0].width() >> m), h = std::max(1, levels[0].height() >> m);
      if (levels[m].width() != w || levels[m].height() != h)
        throw std::logic_error("environment glint weights: level " + std::to_string(m) + " is not a mip level");
      glTextureSubImage2D(texture_.id(), static_cast<GLint>(m), 0, 0, w, h, GL_RGB, GL_FLOAT, levels[m].pixels().data());
      bytes_ += 12ull * levels[m].pixel_count();
    }
    check_gl("uploading the environment's glint weights");
  }
  void bind() const override { glBindTextureUnit(kEnvironmentGlintWeightsUnit, texture_.id()); }
  [[nodiscard]] std::uint64_t gpu_bytes() const override { return bytes_; }

 private:
  gl::Texture texture_;
  std::uint64_t bytes_ = 0;
};

}  // namespace

ResourceType environment_glint_weights_resource() {
  return {
      .id = "environment-glint-weights",
      .title = "the environment's luminance-level weights, GGX-prefiltered as its radiance (Kneiphof & Klein 2025)",
      .binding = "sampler at ENVIRONMENT_GLINT_WEIGHTS_UNIT",
      .key =
          [](const ResourceContext& c) {
            Hasher h;
            hash_environment(h, scene_environment(c.scene));
            return h.hex();
          },
      .estimate_bytes =
          [](const ResourceContext& c) -> std::uint64_t {
            const EnvironmentMap* map = scene_environment(c.scene);
            if (!map) return 12;
            // A chain of at most 256 x 128 (4/3 of its base level), as the radiance's; the weights
            // of the widened map while it is made.
            const auto w = static_cast<std::uint64_t>(std::max(map->radiance.width(), kEnvironmentSpecularBaseWidth));
            const auto h = static_cast<std::uint64_t>(std::max(map->radiance.height(), kEnvironmentSpecularBaseWidth / 2));
            const std::uint64_t base = kEnvironmentSpecularBaseWidth;
            return 12 * base * (base / 2) * 4 / 3 + 12 * w * h;
          },
      .make = [](const ResourceContext& c) -> std::unique_ptr<GpuResource> {
        return std::make_unique<EnvironmentGlintWeightsResource>(scene_environment(c.scene));
      },
  };
}

}  // namespace glintlab
