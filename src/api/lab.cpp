// The library interface (include/glintlab/glintlab.hpp) over the CLI's own session: the same
// scene loading, checks, renderer, reference cache and metrics, so that a number from the library
// is the number `glintlab compare` prints.
#include "glintlab/glintlab.hpp"

#include <stdexcept>

#include "core/flip.hpp"
#include "core/metrics.hpp"
#include "eval/commands.hpp"
#include "eval/outputs.hpp"
#include "eval/session.hpp"
#include "scene/scene_loader.hpp"
#include "shading/method_list.hpp"
#include "shading/registry.hpp"

namespace glintlab {

namespace {

RgbImage to_rgb(const Image& image) {
  RgbImage out{image.width(), image.height(), {}};
  out.pixels.reserve(image.pixel_count() * 3);
  for (const glm::vec3& p : image.pixels()) out.pixels.insert(out.pixels.end(), {p.x, p.y, p.z});
  return out;
}

Rendering to_rendering(const Frame& frame) { return {to_rgb(frame.total), to_rgb(frame.specular)}; }

ReferenceRendering to_reference(const ReferenceFrame& r) {
  return {to_rgb(r.mean.total), to_rgb(r.mean.specular), to_rgb(r.standard_error), r.spp, r.passes,
          r.passes >= 2 ? r.noise_rmse() : 0.0};
}

// The names of compare's metrics.json.
Metrics to_metrics(const ImageMetrics& m) {
  return {{"rmse", m.rmse},
          {"rmse_specular", m.rmse_specular},
          {"psnr", m.psnr},
          {"energy_ratio", m.energy_ratio},
          {"energy_ratio_specular", m.energy_ratio_specular},
          {"max_error", m.max_error},
          {"block_rmse", m.block_rmse},
          {"glint_detail", m.glint_detail},
          {"flip_ldr", m.flip_ldr},
          {"flip_hdr", m.flip_hdr},
          {"sparkle_distance", m.sparkle_distance}};
}

CommonOptions common_options(const std::string& scene, const LabOptions& o) {
  CommonOptions c;
  c.scene = scene;
  c.width = o.width;
  c.height = o.height;
  c.frames = o.frames;
  c.spp_text = o.spp;
  if (!o.reference_backend.empty()) c.reference_backend = o.reference_backend;
  c.params = o.params;
  c.pixels_per_degree = o.pixels_per_degree;
  c.no_cache = !o.use_cache;
  c.quiet = o.quiet;
  return c;
}

}  // namespace

std::vector<MethodInfo> list_methods() {
  std::vector<MethodInfo> out;
  for (const MethodDescriptor& m : all_methods()) {
    MethodInfo info{m.id, m.title, m.citation, m.summary, {}};
    for (const ParamDecl& p : m.params)
      info.parameters.push_back({p.name, p.description, p.default_text(), p.allowed(), p.choices});
    out.push_back(std::move(info));
  }
  return out;
}

std::vector<std::string> list_builtin_scenes() {
  std::vector<std::string> names;
  for (const BuiltinScene& s : builtin_scenes()) names.push_back("builtin:" + s.name);
  return names;
}

struct Lab::State {
  explicit State(const CommonOptions& options) : session(options, Workload{.methods = 1, .reference = true}) {}
  // Its GL objects are deleted in its own context, whichever Lab's is current (if EGL cannot make
  // it current again, the context goes with its objects all the same).
  ~State() {
    try {
      current();
    } catch (const RuntimeFailure&) {
    }
  }
  Session session;
  // Every call draws in this Lab's context (a program may hold several Labs).
  Session& current() {
    session.context().make_current();
    return session;
  }
  // The methods of a call, with LabOptions::params applied as --param applies them.
  std::vector<MethodChoice> methods(const std::string& list) const {
    return resolve_methods(list, session.options().params);
  }
  MethodChoice one_method(const std::string& text) const {
    std::vector<MethodChoice> m = methods(text);
    if (m.size() != 1)
      throw InputError("method '" + text + "': one method or variant expected, " + std::to_string(m.size()) + " given");
    return m.front();
  }
  void check_frame(int frame) const {
    if (frame < 0 || frame >= session.frames())
      throw InputError("frame " + std::to_string(frame) + ": allowed: 0 .. " + std::to_string(session.frames() - 1));
  }
};

Lab::Lab(const std::string& scene, const LabOptions& options)
    : state_(std::make_unique<State>(common_options(scene, options))) {}
Lab::~Lab() = default;
Lab::Lab(Lab&&) noexcept = default;
Lab& Lab::operator=(Lab&&) noexcept = default;

int Lab::width() const { return state_->session.width(); }
int Lab::height() const { return state_->session.height(); }
int Lab::frames() const { return state_->session.frames(); }
std::string Lab::scene() const { return state_->session.scene().source; }

Rendering Lab::render(const std::string& method, int frame) {
  state_->check_frame(frame);
  return to_rendering(state_->current().render(state_->one_method(method), frame));
}

ReferenceRendering Lab::reference(int frame) {
  state_->check_frame(frame);
  return to_reference(state_->current().reference(frame));
}

Comparison Lab::compare(const std::string& methods, int frame) {
  state_->check_frame(frame);
  const std::vector<MethodChoice> choices = state_->methods(methods);
  const Session::Rendered all = state_->current().render_with_reference(choices, frame);
  const MetricsViewing viewing = metrics_viewing(state_->session);
  const Frame& reference = all.reference.mean;
  const MetricsReference perceived(reference.total, reference.specular, viewing);
  Comparison out;
  for (std::size_t i = 0; i < choices.size(); ++i)
    out.methods[choices[i].display_name()] = to_metrics(perceived.measure(all.methods[i].total, all.methods[i].specular));
  const ImageMetrics floor = half_reference_floor(all.reference, viewing);
  out.reference = {{"noise_rmse", all.reference.passes >= 2 ? all.reference.noise_rmse() : 0.0},
                   {"spp", all.reference.spp},
                   {"flip_ldr_floor", floor.flip_ldr},
                   {"flip_hdr_floor", floor.flip_hdr},
                   {"sparkle_floor", floor.sparkle_distance}};
  return out;
}

// ---- Animation ----

struct Animation::State {
  Lab::State* lab = nullptr;
  std::vector<MethodChoice> methods;
  std::vector<TemporalAccumulator> accumulators;
  FlickerFloor floor;
  int next = 0;
};

Animation::Animation(std::unique_ptr<State> state) : state_(std::move(state)) {}
Animation::~Animation() = default;
Animation::Animation(Animation&&) noexcept = default;
Animation& Animation::operator=(Animation&&) noexcept = default;

int Animation::frames() const { return state_->lab->session.frames(); }
bool Animation::done() const { return state_->next >= frames(); }

AnimationFrame Animation::next() {
  if (done()) throw std::out_of_range("Animation::next: all " + std::to_string(frames()) + " frames were rendered");
  Session& session = state_->lab->current();
  const int f = state_->next;
  const Session::Rendered all = session.render_with_reference(state_->methods, f);
  const Frame& reference = all.reference.mean;
  state_->floor.add_frame(all.reference);
  const MetricsReference perceived(reference.total, reference.specular, metrics_viewing(session));
  AnimationFrame out{f, {}, {}, to_reference(all.reference)};
  for (std::size_t i = 0; i < state_->methods.size(); ++i) {
    const std::string& name = state_->methods[i].display_name();
    const Frame& frame = all.methods[i];
    state_->accumulators[i].add_frame(frame.total, reference.total, &perceived);
    const ImageMetrics m = perceived.measure(frame.total, frame.specular);
    out.metrics[name] = {{"rmse", m.rmse},
                         {"sparkle_distance", m.sparkle_distance},
                         {"flip_ldr", m.flip_ldr},
                         {"flip_hdr", m.flip_hdr}};
    out.renderings[name] = to_rendering(frame);
  }
  ++state_->next;
  return out;
}

std::map<std::string, Metrics> Animation::summary() const {
  std::map<std::string, Metrics> out;
  for (std::size_t i = 0; i < state_->methods.size(); ++i) {
    const TemporalMetrics t = state_->accumulators[i].result(state_->methods[i].display_name());
    out[t.method] = {{"mean_rmse", t.mean_rmse},
                     {"flicker", t.flicker},
                     {"mean_sparkle_distance", t.mean_sparkle},
                     {"mean_flip_ldr", t.mean_flip_ldr},
                     {"mean_flip_hdr", t.mean_flip_hdr}};
  }
  const ReferenceFloor floor = state_->floor.floor();
  out["reference"] = {{"flicker_floor", floor.flicker},
                      {"noise_rmse", floor.noise_rmse},
                      {"spp_min", floor.spp_min},
                      {"spp_max", floor.spp_max}};
  return out;
}

Animation Lab::animate(const std::string& methods) {
  auto state = std::make_unique<Animation::State>();
  state->lab = state_.get();
  state->methods = state_->methods(methods);
  state->accumulators.resize(state->methods.size());
  return Animation(std::move(state));
}

}  // namespace glintlab
