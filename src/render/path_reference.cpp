#include "render/path_reference.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <set>
#include <span>
#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "core/hash.hpp"
#include "gl/context.hpp"
#include "gl/shader_library.hpp"
#include "path/camera_rays.hpp"
#include "path/ray_cone.hpp"
#include "render/gpu_scene.hpp"
#include "render/pass_tiles.hpp"
#include "render/render_target.hpp"
#include "render/resources/resource.hpp"
#include "render/shader_contract.hpp"
#include "render/subpixel_filter.hpp"
#include "tables/registry.hpp"

namespace glintlab {
namespace {

// The std430 records of passes/path_direct.comp (PathHit, PathShadowRay): vec4s only.
struct PathHit {
  glm::vec4 position, normal, tangent, face_normal;
  glm::vec4 dPdx, dPdy, dNdx, dNdy, dTangentdx, dTangentdy;
  glm::vec4 uv;             // xy: uv; zw: d/dx
  glm::vec4 dUVdy_global;   // xy: d/dy; zw: the sub-pixel's coordinates, as int bits
  glm::vec4 incoming;       // after a bounce: xyz back along the ray, w = 1
  glm::vec4 dViewdx, dViewdy;
};
static_assert(sizeof(PathHit) == 15 * sizeof(glm::vec4));
struct PathShadowRay {
  glm::vec4 dir_dist, diffuse, specular;
};
static_assert(sizeof(PathShadowRay) == 3 * sizeof(glm::vec4));  // read back into vec4s (shadow_host_)
struct PathBounce {
  glm::vec4 dir_lobe, diffuse, specular, dDdx, dDdy;
};

// A path in flight: its sample, the ray it follows and what the light it gathers from here on is
// worth to the sample's total and specular images (after its first bounce, the specular image
// keeps what came by the first vertex's specular lobe).
struct PathState {
  std::size_t sample;
  Ray ray;
  glm::vec3 total_weight{1.0f};
  glm::vec3 specular_weight{1.0f};
  bool mirrored = false;        ///< every bounce so far off a mirror: `differential` is the ray's own
  RayDifferential differential;  ///< per sub-pixel, GL's screen axes
  RayCone cone;                  ///< the widening of rough bounces so far, at the ray's origin (path:<method>)
};

// A float in [0, 1) from a sample's sub-pixel, the path vertex and the pass's seed (Russian roulette).
float path_random(glm::ivec2 global, int depth, std::uint32_t seed) {
  Hasher h;
  h.value(global.x);
  h.value(global.y);
  h.value(depth);
  h.value(seed);
  return static_cast<float>(h.digest() >> 40) * (1.0f / 16777216.0f);
}

// Russian roulette from this vertex on: paths whose weight is below 1 survive with that probability.
constexpr int kRouletteDepth = 3;

// A tile's shadow rays at most (their records: 96 MiB), so a tile holds fewer samples when the
// scene has many lights or many samples per light.
constexpr std::size_t kMaxShadowRaysPerTile = std::size_t{1} << 21;
constexpr unsigned kGroupSize = 64;

// Shadow rays start this far off the surface, along its face normal on the ray's side (relative to
// the point's distance from the origin: float positions are that precise).
constexpr float kRayOffset = 1e-4f;

// A ray's origin just off a surface point, along its face normal on the side the ray leaves to.
glm::vec3 offset_origin(glm::vec3 p, glm::vec3 face_normal, glm::vec3 direction) {
  const float offset = kRayOffset * (1.0f + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
  return p + (glm::dot(direction, face_normal) >= 0.0f ? offset : -offset) * face_normal;
}

void set_uint(GLuint program, const char* name, unsigned v) {
  glProgramUniform1ui(program, glGetUniformLocation(program, name), v);
}

}  // namespace

PathReference::PathReference(const ReferenceBackendContext& context, bool shadows)
    : shaders_(context.shaders), scene_(context.scene), rays_(context.scene.resource_context().scene), shadows_(shadows) {}

PathReference::PathReference(const ReferenceBackendContext& context, MethodChoice method)
    : PathReference(context, true) {
  method_module_ = method_program_module(shaders_, *method.method, method.params);
  method_resources_ = method_resources(*method.method, method.params);
  scene_.resources().require(method_resources_, scene_.resource_context(method.params));
  if (const auto sigma = method.params.find("footprint_sigma"); sigma != method.params.end()) footprint_sigma_ = sigma->second;
  method_ = std::move(method);
}

std::string PathReference::id() const {
  if (method_) return kPathMethodPrefix + method_->display_name();
  return shadows_ ? "path" : "path-unshadowed";
}

bool PathReference::by_method(int material) const {
  return method_ && scene_.kind(material).id == "normal-map-glints";
}

ShaderDefines PathReference::program_defines(int material) const {
  ShaderDefines defines = forward_variant(kReferenceModule, scene_.light_ranges(), material_variant(scene_, material));
  if (by_method(material))
    for (auto& [name, value] : defines) {
      if (name == "$METHOD") value = method_module_;
      if (name == "$MATERIAL") value = kFootprintNdfMaterialModule;
    }
  return defines;
}

std::uint64_t PathReference::estimator_hash() const {
  if (estimator_hash_ != 0) return estimator_hash_;
  Hasher h;
  h.text(shadows_ ? "glintlab-path-v1 shadow rays of the scene's shapes" : "glintlab-path-v1 no shadows");
  std::set<std::string> programs;
  for (const auto& mesh : scene_.meshes())
    programs.insert(shaders_.expand("passes/path_direct.comp", program_defines(mesh.material)));
  for (const std::string& text : programs) h.text(text);
  if (method_) {
    // Its run-time parameters are uniforms, not text; its resources follow its parameters.
    h.text("ray cones widened by each rough lobe's sqrt(2) alpha (path/ray_cone.hpp) v1");
    h.text(id());
    for (const auto& [name, value] : method_->params) {
      h.text(name);
      h.value(value);
    }
  }
  h.text(shaders_.expand("passes/path_background.comp", {}));
  hash_pass_inputs(h, shaders_, scene_);
  estimator_hash_ = h.digest();
  return estimator_hash_;
}

std::size_t PathReference::shadow_rays_per_hit(const ReferencePass& pass) const {
  // Each light may write 2 n + 1 shadow rays per hit (n light samples; passes/path_direct.comp);
  // an environment on a method's footprint NDF n + its lobes (at most environment_lobes).
  const std::size_t n = static_cast<std::size_t>(pass.light_samples);
  const std::size_t lobes = method_ && method_->params.contains("environment_lobes")
                                ? static_cast<std::size_t>(method_->params.at("environment_lobes"))
                                : 0;
  std::size_t rays = 0;
  for (const Light& light : scene_.resource_context().scene.lights)
    rays += std::max(2 * n + 1, light.environment ? n + lobes : 0);
  return std::max<std::size_t>(1, rays);
}

GLuint PathReference::DeviceBuffer::hold(std::size_t bytes) {
  if (bytes > capacity || !buffer) {
    capacity = std::max<std::size_t>(bytes, 256);
    buffer = gl::make_buffer(static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  return buffer.id();
}

GLuint PathReference::shading_program(int material) {
  GLuint& program = programs_[material];
  if (!program) {
    program = shaders_.compute("passes/path_direct.comp", program_defines(material));
    // The method's parameters are the program's own uniforms: set once, kept with it.
    if (by_method(material)) set_param_uniforms(program, method_->params);
  }
  return program;
}

Frame PathReference::render_pass(const Camera& camera, int width, int height, const ReferencePass& pass,
                                 const ProgressFn& progress) {
  const int k = pass.subpixels;
  if (k < 1 || k > 32) throw InputError("reference sub-pixels per axis " + std::to_string(k) + ": allowed: 1 .. 32");
  const FilmRegion wanted = pass.region.within(width, height);
  const int margin = pass.filter.support_pixels();
  const std::size_t rays_per_hit = shadow_rays_per_hit(pass);
  const int side = static_cast<int>(std::sqrt(static_cast<double>(std::max<std::size_t>(1024, kMaxShadowRaysPerTile / rays_per_hit))));
  const int tile = std::max(1, side / k - 2 * margin);
  const std::vector<PassTile> tiles = pass_tiles({width, height}, wanted, tile, margin);

  RenderTarget high(std::min(width, tile + 2 * margin) * k, std::min(height, tile + 2 * margin) * k);
  PassFilm out(width, height);
  SubpixelFilter filter(shaders_, pass.filter);
  std::vector<glm::vec4> total, specular;
  int done = 0;
  for (const PassTile& t : tiles) {
    shade_tile(camera, width, height, pass, t, total, specular);
    const glm::ivec2 samples = t.region_size * k;
    glTextureSubImage2D(high.total(), 0, 0, 0, samples.x, samples.y, GL_RGBA, GL_FLOAT, total.data());
    glTextureSubImage2D(high.specular(), 0, 0, 0, samples.x, samples.y, GL_RGBA, GL_FLOAT, specular.data());
    filter.reduce(high, t.samples(k, pass.jitter, height), out.total(), out.specular());
    glFinish();
    check_gl("path-tracing a reference tile");
    if (progress) progress(++done, static_cast<int>(tiles.size()));
  }
  return out.read(wanted);
}

void PathReference::shade_tile(const Camera& camera, int width, int height, const ReferencePass& pass, const PassTile& tile,
                               std::vector<glm::vec4>& total, std::vector<glm::vec4>& specular) {
  const int k = pass.subpixels;
  const glm::ivec2 samples = tile.region_size * k;
  const std::size_t count = static_cast<std::size_t>(samples.x) * static_cast<std::size_t>(samples.y);
  total.assign(count, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  specular.assign(count, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));

  // Each sample's camera ray, where the raster reference's sample of the same sub-pixel looks: the
  // sub-pixel's corner plus the pass's jitter, in GL's y-up rows; differentials per sub-pixel.
  const CameraRays camera_rays(camera, {width, height});
  const float per_subpixel = 1.0f / static_cast<float>(k);
  std::vector<PathState> paths(count);
  std::vector<RayDifferential> differentials(count);
  std::vector<glm::ivec2> global(count);
  for (int y = 0; y < samples.y; ++y)
    for (int x = 0; x < samples.x; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * samples.x + x;
      global[i] = {tile.region_origin.x * k + x, tile.region_gl_y * k + y};
      const glm::vec2 film_point((static_cast<float>(global[i].x) + pass.jitter.x) * per_subpixel,
                                 static_cast<float>(height) - (static_cast<float>(global[i].y) + pass.jitter.y) * per_subpixel);
      RayDifferential r = camera_rays.at(film_point);
      // Per sub-pixel, along GL's screen axes (y up) as the raster pass's derivatives are.
      r.dOdx *= per_subpixel;
      r.dDdx *= per_subpixel;
      r.dOdy *= -per_subpixel;
      r.dDdy *= -per_subpixel;
      differentials[i] = r;
      paths[i] = PathState{.sample = i, .ray = Ray{.origin = r.origin, .direction = r.direction}};
    }

  // The frame as the raster reference's pass sees it (passes/reference_estimator.glsl reads
  // target.z = k, tile.z = light samples, tile.w = the pass's seed; frame.glsl the camera).
  const FrameUniforms frame =
      frame_uniforms(camera, camera.projection_matrix(static_cast<float>(width) / static_cast<float>(height)),
                     {samples.x, samples.y, k, 0},
                     {tile.region_origin.x * k, tile.region_gl_y * k, pass.light_samples, static_cast<int>(pass.seed & 0x7fffffffu)});
  const gl::Buffer frame_ubo = gl::make_buffer(sizeof(FrameUniforms), &frame);
  const std::size_t rays_per_hit = shadow_rays_per_hit(pass);

  for (int depth = 0; depth < pass.max_depth && !paths.empty(); ++depth) {
    std::vector<Ray> rays(paths.size());
    for (std::size_t p = 0; p < paths.size(); ++p) rays[p] = paths[p].ray;
    std::vector<RayHit> hits(paths.size());
    rays_.intersect(rays, hits, depth == 0 ? RayCoherence::Coherent : RayCoherence::Incoherent);

    // Camera rays: emitters as the raster's emitter pass draws them, misses the background. After
    // a bounce both are light the previous vertex's light samples have counted (their MIS
    // includes the material's own directions), so the path ends there.
    std::map<int, std::vector<std::size_t>> by_material;  // path indices
    std::vector<std::size_t> missed;                     // sample indices
    std::vector<glm::vec4> missed_directions;
    for (std::size_t p = 0; p < paths.size(); ++p) {
      const std::size_t i = paths[p].sample;
      if (!hits[p].hit()) {
        if (depth == 0) {
          missed.push_back(i);
          missed_directions.emplace_back(rays[p].direction, 0.0f);
        }
      } else if (const LightEmitter* e = rays_.emitter(hits[p])) {
        const bool lit = e->two_sided || glm::dot(rays_.surface(hits[p]).normal, rays[p].direction) < 0.0f;
        if (depth == 0) total[i] = glm::vec4(lit ? e->radiance : glm::vec3(0.0f), 1.0f);
      } else {
        by_material[rays_.surface(hits[p]).material].push_back(p);
      }
    }
    if (!missed.empty()) shade_background(missed, std::move(missed_directions), total);

    std::vector<std::size_t> path_of;  // record -> path
    std::vector<std::pair<int, std::pair<unsigned, unsigned>>> draws;  // material, (first, count)
    for (const auto& [material, indices] : by_material) {
      draws.push_back({material, {static_cast<unsigned>(path_of.size()), static_cast<unsigned>(indices.size())}});
      path_of.insert(path_of.end(), indices.begin(), indices.end());
    }
    std::vector<PathHit> records(path_of.size());
    tbb::parallel_for(std::size_t{0}, records.size(), [&](std::size_t h) {
      const std::size_t p = path_of[h], i = paths[p].sample;
      const SurfacePoint point = rays_.surface(hits[p]);
      // The camera ray's own differentials at the first vertex and after mirrors (Igehy 1999);
      // after any other bounce, those a camera ray through the point would have (pbrt-v4's rule:
      // docs/methods.md, "The path tracer").
      RayDifferential r = depth == 0 ? differentials[i] : paths[p].differential;
      RayHit at = hits[p];
      if (depth > 0 && !paths[p].mirrored) {
        r = camera_rays.towards(point.position);
        r.dOdx *= per_subpixel;
        r.dDdx *= per_subpixel;
        r.dOdy *= -per_subpixel;
        r.dDdy *= -per_subpixel;
        at.t = glm::dot(point.position - r.origin, r.direction);
      }
      SurfaceDerivatives d = rays_.derivatives(at, r.direction, r.dOdx, r.dOdy, r.dDdx, r.dDdy);
      if (depth > 0 && !paths[p].mirrored && method_) {
        // path:<method>: the camera's footprint at the point widened by the rough lobes bounced off
        // on the way (Deng et al. 2022 sec. 5.3; path/ray_cone.hpp).
        const RayCone cone = paths[p].cone.travelled(hits[p].t);
        const auto [x, y] = widen_footprint(d.dPdx, d.dPdy, rays[p].direction, glm::normalize(point.geometric_normal),
                                            cone.width, footprint_sigma_);
        d = rays_.derivatives_along(hits[p], x, y);
      }
      records[h] = PathHit{
          .position = glm::vec4(point.position, 0.0f),
          .normal = glm::vec4(point.normal, 0.0f),
          .tangent = point.tangent,
          .face_normal = glm::vec4(point.geometric_normal, 0.0f),
          .dPdx = glm::vec4(d.dPdx, 0.0f),
          .dPdy = glm::vec4(d.dPdy, 0.0f),
          .dNdx = glm::vec4(d.dNdx, 0.0f),
          .dNdy = glm::vec4(d.dNdy, 0.0f),
          .dTangentdx = d.dTdx,
          .dTangentdy = d.dTdy,
          .uv = glm::vec4(point.uv, d.dUVdx),
          .dUVdy_global = glm::vec4(d.dUVdy, std::bit_cast<float>(global[i].x), std::bit_cast<float>(global[i].y)),
          .incoming = glm::vec4(-rays[p].direction, depth > 0 ? 1.0f : 0.0f),
          .dViewdx = glm::vec4(-r.dDdx, 0.0f),
          .dViewdy = glm::vec4(-r.dDdy, 0.0f)};
    });
    if (records.empty()) break;

    // Shade every hit on the device.
    const bool bounce = depth + 1 < pass.max_depth;
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frame_ubo.id());
    scene_.bind_buffers();
    scene_.resources().bind(scene_.scene_resource_ids(), scene_.resource_context());
    if (method_) scene_.resources().bind(method_resources_, scene_.resource_context(method_->params));
    const std::size_t shadow_count = records.size() * rays_per_hit;
    const GLuint hit_buffer = hits_.hold(records.size() * sizeof(PathHit));
    glNamedBufferSubData(hit_buffer, 0, static_cast<GLsizeiptr>(records.size() * sizeof(PathHit)), records.data());
    const GLuint ray_buffer = shadow_rays_.hold(shadow_count * sizeof(PathShadowRay));
    const GLuint emission_buffer = emission_.hold(records.size() * sizeof(glm::vec4));
    const GLuint bounce_buffer = bounces_.hold(records.size() * sizeof(PathBounce));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPathHitsBinding, hit_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPathShadowRaysBinding, ray_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPathEmissionBinding, emission_buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPathContinuationBinding, bounce_buffer);
    for (const auto& [material, range] : draws) {
      const GLuint program = shading_program(material);
      glUseProgram(program);
      scene_.bind_material(program, material);
      set_uint(program, "uFirst", range.first);
      set_uint(program, "uCount", range.second);
      set_uint(program, "uRaysPerHit", static_cast<unsigned>(rays_per_hit));
      set_uint(program, "uDepth", static_cast<unsigned>(depth));
      glProgramUniform1i(program, glGetUniformLocation(program, "uBounce"), bounce ? 1 : 0);
      glDispatchCompute((range.second + kGroupSize - 1) / kGroupSize, 1, 1);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (shadow_host_.size() < 3 * shadow_count) shadow_host_.resize(3 * shadow_count);
    const std::span<const PathShadowRay> shadow(reinterpret_cast<const PathShadowRay*>(shadow_host_.data()), shadow_count);
    std::vector<glm::vec4> emission(records.size());
    std::vector<PathBounce> bounces(records.size());
    glGetNamedBufferSubData(ray_buffer, 0, static_cast<GLsizeiptr>(shadow_count * sizeof(PathShadowRay)), shadow_host_.data());
    glGetNamedBufferSubData(emission_buffer, 0, static_cast<GLsizeiptr>(emission.size() * sizeof(glm::vec4)), emission.data());
    glGetNamedBufferSubData(bounce_buffer, 0, static_cast<GLsizeiptr>(bounces.size() * sizeof(PathBounce)), bounces.data());
    check_gl("shading the path tracer's hits");

    // What this vertex adds to its sample: emission, and each light sample whose light is visible.
    auto add = [&](std::size_t record, glm::vec3 diffuse, glm::vec3 specular_part) {
      const PathState& path = paths[path_of[record]];
      const glm::vec3 sum = diffuse + specular_part;
      total[path.sample] += glm::vec4(path.total_weight * sum, 0.0f);
      specular[path.sample] += glm::vec4(depth == 0 ? specular_part : path.specular_weight * sum, 0.0f);
    };
    for (std::size_t h = 0; h < records.size(); ++h) {
      const PathState& path = paths[path_of[h]];
      total[path.sample] += glm::vec4(path.total_weight * glm::vec3(emission[h]), 0.0f);
      if (depth > 0) specular[path.sample] += glm::vec4(path.specular_weight * glm::vec3(emission[h]), 0.0f);
    }
    // The shadow rays: from just off the surface on the ray's side, to just short of the light
    // (lights are exact shapes of their own, not in the BVH's shapes: kSeesShapes).
    std::vector<Ray> shadow_rays;
    std::vector<std::size_t> shadow_of;
    shadow_rays.reserve(shadow_count);
    shadow_of.reserve(shadow_count);
    for (std::size_t r = 0; r < shadow.size(); ++r) {
      const float dist = shadow[r].dir_dist.w;
      if (!(dist > 0.0f)) continue;
      const PathHit& h = records[r / rays_per_hit];
      shadow_rays.push_back(Ray{.origin = offset_origin(glm::vec3(h.position), glm::vec3(h.face_normal), glm::vec3(shadow[r].dir_dist)),
                                .direction = glm::vec3(shadow[r].dir_dist),
                                .t_far = dist * (1.0f - 1e-4f),
                                .sees = kSeesShapes});
      shadow_of.push_back(r);
    }
    std::vector<std::uint8_t> blocked(shadow_rays.size(), 0);
    if (shadows_) rays_.occluded(shadow_rays, blocked, RayCoherence::Incoherent);
    for (std::size_t j = 0; j < shadow_rays.size(); ++j)
      if (!blocked[j]) {
        const PathShadowRay& ray = shadow[shadow_of[j]];
        add(shadow_of[j] / rays_per_hit, glm::vec3(ray.diffuse), glm::vec3(ray.specular));
      }

    // The bounces: the paths that go on, with Russian roulette from kRouletteDepth on.
    if (!bounce) break;
    std::vector<PathState> next;
    for (std::size_t h = 0; h < records.size(); ++h) {
      const PathBounce& b = bounces[h];
      if (b.dir_lobe.w < 0.5f) continue;
      PathState path = paths[path_of[h]];
      const glm::vec3 weight = glm::vec3(b.diffuse) + glm::vec3(b.specular);
      if (depth == 0) {
        path.total_weight = weight;
        path.specular_weight = glm::vec3(b.specular);
      } else {
        path.total_weight *= weight;
        path.specular_weight *= weight;
      }
      if (depth + 1 >= kRouletteDepth) {
        const float survive = std::min(1.0f, std::max({path.total_weight.x, path.total_weight.y, path.total_weight.z}));
        if (!(survive > 0.0f) || path_random(global[path.sample], depth, pass.seed) >= survive) continue;
        path.total_weight /= survive;
        path.specular_weight /= survive;
      }
      const glm::vec3 dir(b.dir_lobe);
      path.ray = Ray{.origin = offset_origin(glm::vec3(records[h].position), glm::vec3(records[h].face_normal), dir),
                     .direction = dir};
      path.mirrored = b.dDdx.w > 0.5f && (depth == 0 || path.mirrored);
      if (!path.mirrored)
        path.cone = path.cone.travelled(hits[path_of[h]].t).bounced(b.dDdx.w > 0.5f ? 0.0f : lobe_spread(b.dDdy.w, b.dir_lobe.w < 1.5f));
      if (path.mirrored)
        path.differential = RayDifferential{.origin = glm::vec3(records[h].position),
                                            .direction = dir,
                                            .dOdx = glm::vec3(records[h].dPdx),
                                            .dOdy = glm::vec3(records[h].dPdy),
                                            .dDdx = glm::vec3(b.dDdx),
                                            .dDdy = glm::vec3(b.dDdy)};
      next.push_back(path);
    }
    paths = std::move(next);
  }
}

void PathReference::shade_background(const std::vector<std::size_t>& missed, std::vector<glm::vec4> directions,
                                     std::vector<glm::vec4>& total) {
  if (scene_.background_light() < 0) return;
  const gl::Buffer buffer = gl::make_buffer(static_cast<GLsizeiptr>(directions.size() * sizeof(glm::vec4)),
                                            directions.data());
  const GLuint program = shaders_.compute("passes/path_background.comp");
  glUseProgram(program);
  glProgramUniform1i(program, glGetUniformLocation(program, "uLight"), scene_.background_light());
  set_uint(program, "uCount", static_cast<unsigned>(directions.size()));
  scene_.bind_buffers();
  scene_.resources().bind(scene_.scene_resource_ids(), scene_.resource_context());  // the environment's maps
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPathHitsBinding, buffer.id());
  glDispatchCompute((static_cast<unsigned>(directions.size()) + kGroupSize - 1) / kGroupSize, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer.id(), 0, static_cast<GLsizeiptr>(directions.size() * sizeof(glm::vec4)), directions.data());
  check_gl("the path tracer's background");
  for (std::size_t j = 0; j < missed.size(); ++j) total[missed[j]] = glm::vec4(glm::vec3(directions[j]), 1.0f);
}

}  // namespace glintlab
