// Resource `environment-map` (the environment light kind's; src/scene/lights/environment.cpp): the
// scene's environment as four textures. The light itself, read by the reference: its radiance map
// (texel for texel, nearest) and the CDFs that sample it by luminance x sin(theta)
// (shaders/lights/environment.glsl). The split sum's, read by the methods: the GGX-prefiltered mip
// chain and the irradiance map (shaders/lobe/environment_shading.glsl).
#include <algorithm>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>

#include "core/gpu_contract.hpp"
#include "core/hash.hpp"
#include "gl/context.hpp"
#include "gl/objects.hpp"
#include "render/resources/resource.hpp"
#include "render/resources/scene_environment.hpp"
#include "scene/lights/environment_map.hpp"
#include "scene/lights/environment_prefilter.hpp"
#include "scene/lights/environment_sampling.hpp"

namespace glintlab {

namespace {

gl::Texture make_texture(GLenum format, int levels, int width, int height, GLenum min_filter, GLenum wrap_s) {
  gl::Texture t = gl::make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.id(), levels, format, width, height);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(min_filter));
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, min_filter == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap_s));  // around in azimuth
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);             // not over the poles
  return t;
}

void upload_rgb(const gl::Texture& t, int level, const Image& image) {
  glTextureSubImage2D(t.id(), level, 0, 0, image.width(), image.height(), GL_RGB, GL_FLOAT, image.pixels().data());
}

std::uint64_t rgb_bytes(const Image& image) { return 12ull * image.pixel_count(); }

class EnvironmentMapResource : public GpuResource {
 public:
  explicit EnvironmentMapResource(const EnvironmentMap& map) {
    const Image& radiance = map.radiance;
    radiance_ = make_texture(GL_RGB32F, 1, radiance.width(), radiance.height(), GL_NEAREST, GL_REPEAT);
    upload_rgb(radiance_, 0, radiance);

    const EnvironmentSampling sampling = build_environment_sampling(radiance);
    cdf_ = make_texture(GL_R32F, 1, sampling.width + 1, sampling.height + 1, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glTextureSubImage2D(cdf_.id(), 0, 0, 0, sampling.width + 1, sampling.height + 1, GL_RED, GL_FLOAT,
                        sampling.cdf.data());

    const PrefilteredEnvironment prefiltered = prefilter_environment(widened_for_specular_chain(radiance));
    const auto& levels = prefiltered.specular_levels;
    specular_ = make_texture(GL_RGB32F, static_cast<int>(levels.size()), levels[0].width(), levels[0].height(),
                             GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT);
    for (std::size_t m = 0; m < levels.size(); ++m) {
      // The chain must be a mip chain: each level half the one above (GL's sizes).
      const int w = std::max(1, levels[0].width() >> m), h = std::max(1, levels[0].height() >> m);
      if (levels[m].width() != w || levels[m].height() != h)
        throw std::logic_error("environment prefilter: level " + std::to_string(m) + " is not " + std::to_string(w) +
                               "x" + std::to_string(h));
      upload_rgb(specular_, static_cast<int>(m), levels[m]);
    }
    const Image& irradiance = prefiltered.irradiance;
    irradiance_ = make_texture(GL_RGB32F, 1, irradiance.width(), irradiance.height(), GL_LINEAR, GL_REPEAT);
    upload_rgb(irradiance_, 0, irradiance);

    bytes_ = rgb_bytes(radiance) + 4ull * sampling.cdf.size() + rgb_bytes(irradiance);
    for (const Image& level : levels) bytes_ += rgb_bytes(level);
    check_gl("uploading the environment map");
  }
  void bind() const override {
    glBindTextureUnit(kEnvironmentRadianceUnit, radiance_.id());
    glBindTextureUnit(kEnvironmentCdfUnit, cdf_.id());
    glBindTextureUnit(kEnvironmentSpecularUnit, specular_.id());
    glBindTextureUnit(kEnvironmentIrradianceUnit, irradiance_.id());
  }
  [[nodiscard]] std::uint64_t gpu_bytes() const override { return bytes_; }

 private:
  gl::Texture radiance_, cdf_, specular_, irradiance_;
  std::uint64_t bytes_ = 0;
};

}  // namespace

ResourceType environment_map_resource() {
  return {
      .id = "environment-map",
      .title = "the environment light's radiance map, its luminance CDFs, GGX-prefiltered mip chain and irradiance",
      .binding = "samplers at ENVIRONMENT_RADIANCE_UNIT, ENVIRONMENT_CDF_UNIT, ENVIRONMENT_SPECULAR_UNIT, "
                 "ENVIRONMENT_IRRADIANCE_UNIT",
      .key =
          [](const ResourceContext& c) {
            Hasher h;
            hash_environment(h, scene_environment(c.scene));
            return h.hex();
          },
      .estimate_bytes =
          [](const ResourceContext& c) -> std::uint64_t {
            const EnvironmentMap* map = scene_environment(c.scene);
            if (!map) return 0;
            const auto w = static_cast<std::uint64_t>(map->radiance.width());
            const auto h = static_cast<std::uint64_t>(map->radiance.height());
            // Radiance, CDFs, a chain of at most 256 x 128 (4/3 of its base level), 32 x 16 irradiance.
            const std::uint64_t base = std::min<std::uint64_t>(w, kEnvironmentSpecularBaseWidth);
            return 12 * w * h + 4 * (w + 1) * (h + 1) + 12 * base * (base / 2) * 4 / 3 + 12 * 32 * 16;
          },
      .make =
          [](const ResourceContext& c) -> std::unique_ptr<GpuResource> {
            const EnvironmentMap* map = scene_environment(c.scene);
            if (!map) throw std::logic_error("environment-map: the scene has no environment light");
            return std::make_unique<EnvironmentMapResource>(*map);
          },
  };
}

}  // namespace glintlab
