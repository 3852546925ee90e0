#include "view/viewer.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/colour.hpp"
#include "core/error.hpp"
#include "eval/outputs.hpp"
#include "scene/scene_loader.hpp"
#include "shading/registry.hpp"
#include "view/display_compose.hpp"

namespace glintlab {

namespace {

/// A float exactly as it is (hexadecimal), for the keys that say whether an image is current.
std::string exact(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%a", static_cast<double>(v));
  return text;
}

std::string exact(const glm::vec3& v) { return exact(v.x) + "," + exact(v.y) + "," + exact(v.z); }

/// A parameter's value as `--param` takes it: a choice's name, or the number.
std::string param_text(const ParamDecl& p, float value) {
  if (!p.choices.empty()) {
    const auto i = static_cast<std::size_t>(value);
    if (i < p.choices.size()) return p.choices[i];
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  return text;
}

nlohmann::json camera_json(const Camera& c) {
  return {{"position", {c.position.x, c.position.y, c.position.z}},
          {"target", {c.target.x, c.target.y, c.target.z}},
          {"up", {c.up.x, c.up.y, c.up.z}},
          {"projection", c.projection == Projection::Perspective ? "perspective" : "orthographic"},
          {"fov_y_degrees", c.fov_y_degrees},
          {"view_height", c.view_height}};
}

}  // namespace

Viewer::Viewer(Session& session, const MethodChoice& method, const MethodChoice* second, int frame)
    : session_(session) {
  state_.a = {method.method, method.params};
  state_.b = second ? MethodSlot{second->method, second->params} : state_.a;
  state_.second = second ? SecondImage::Method : SecondImage::Reference;
  state_.exposure = session.scene().film.exposure;
  state_.bloom = session.scene().film.bloom;
  set_frame(frame);
}

void Viewer::select_method(bool second_slot, const std::string& id) {
  const MethodDescriptor& m = find_method(id);  // InputError listing the methods
  slot(second_slot) = {&m, resolve_params(m, {})};
  if (second_slot) state_.second = SecondImage::Method;
  changed();
}

void Viewer::compare_with_reference() {
  state_.second = SecondImage::Reference;
  changed();
}

void Viewer::set_param(bool second_slot, const std::string& name, const std::string& value) {
  MethodSlot& s = slot(second_slot);
  std::map<std::string, std::string> overrides;
  for (const auto& p : s.method->params) overrides[p.name] = param_text(p, s.params.at(p.name));
  if (!s.method->find_param(name)) {
    std::string known;
    for (const auto& p : s.method->params) known += (known.empty() ? "" : ", ") + p.name;
    throw InputError("parameter '" + name + "' of method '" + s.method->id + "' does not exist; allowed: " +
                     (known.empty() ? "none" : known));
  }
  overrides[name] = value;
  s.params = resolve_params(*s.method, overrides);  // InputError for a value out of range
  changed();
}

void Viewer::set_param_value(bool second_slot, const std::string& name, float value) {
  const ParamDecl* p = slot(second_slot).method->find_param(name);
  if (!p) throw InputError("parameter '" + name + "' does not exist");
  set_param(second_slot, name, param_text(*p, value));
}

void Viewer::reset_params(bool second_slot) {
  MethodSlot& s = slot(second_slot);
  s.params = resolve_params(*s.method, {});
  changed();
}

void Viewer::set_mode(CompareMode mode) {
  state_.mode = mode;
  changed();
}

void Viewer::set_split(float split) {
  if (!(split >= 0.0f && split <= 1.0f))
    throw InputError("split " + std::to_string(split) + ": allowed: 0 .. 1 (the fraction of the width on the left)");
  state_.split = split;
  changed();
}

void Viewer::flip() {
  state_.showing_second = !state_.showing_second;
  changed();
}

void Viewer::set_error_overlay(bool on, float opacity) {
  state_.error_overlay = on;
  state_.overlay_opacity = std::clamp(opacity, 0.0f, 1.0f);
  changed();
}

void Viewer::set_frame(int frame) {
  if (frame < 0 || frame >= frames())
    throw InputError("frame " + std::to_string(frame) + ": allowed: 0 .. " + std::to_string(frames() - 1));
  state_.frame = frame;
  changed();
}

void Viewer::step_frame(int delta) { set_frame(((state_.frame + delta) % frames() + frames()) % frames()); }

void Viewer::set_playing(bool playing) { state_.playing = playing; }

void Viewer::move_camera(const Camera& camera) {
  state_.free_camera = camera;
  state_.playing = false;
  changed();
}

void Viewer::return_to_path() {
  state_.free_camera.reset();
  changed();
}

void Viewer::set_exposure(float stops) {
  if (!(stops >= -20.0f && stops <= 20.0f)) throw InputError("exposure " + std::to_string(stops) + ": allowed: -20 .. 20 stops");
  state_.exposure = stops;
  changed();
}

void Viewer::set_bloom(float bloom) {
  if (!(bloom >= 0.0f && bloom <= 1.0f)) throw InputError("bloom " + std::to_string(bloom) + ": allowed: 0 .. 1");
  state_.bloom = bloom;
  changed();
}

void Viewer::set_continuous(bool on) { state_.continuous = on; }

Camera Viewer::camera() const { return state_.free_camera.value_or(session_.camera(state_.frame)); }

bool Viewer::needs_reference() const {
  return state_.error_overlay || (state_.mode != CompareMode::Single && state_.second == SecondImage::Reference);
}

const TimedFrame* Viewer::shown(bool second_slot) const {
  const auto& f = second_slot ? b_ : a_;
  return f ? &*f : nullptr;
}

std::string Viewer::view_key() const {
  const Camera c = camera();
  return std::to_string(state_.frame) + "|" + std::to_string(width()) + "x" + std::to_string(height()) + "|" +
         exact(c.position) + "|" + exact(c.target) + "|" + exact(c.up) + "|" + exact(c.fov_y_degrees) + "|" +
         exact(c.view_height);
}

std::string Viewer::slot_key(const MethodSlot& s) const {
  std::string key = s.method->id;
  for (const auto& [name, value] : s.params) key += "|" + name + "=" + exact(value);
  return key + "|" + view_key();
}

TimedFrame Viewer::render_slot(const MethodSlot& s) {
  // Session::render's path (Renderer::render = draw + read_frame), with the draw timed.
  TimedFrame t;
  const Camera cam = camera();
  t.time = timer_.time([&] { session_.renderer().draw(*s.method, s.params, cam, width(), height()); });
  t.frame = session_.renderer().read_frame();
  require_finite(t.frame, "method '" + s.method->id + "'");
  return t;
}

Image Viewer::display_of(const Frame& frame) const {
  return tonemap_for_display(frame.total, state_.exposure, state_.bloom);
}

void Viewer::update() {
  const bool second_method = state_.mode != CompareMode::Single && state_.second == SecondImage::Method;
  if (const std::string key = slot_key(state_.a); state_.continuous || !a_ || key != a_key_) {
    a_ = render_slot(state_.a);
    a_key_ = key;
    display_dirty_ = true;
  }
  if (const std::string key = slot_key(state_.b); second_method && (state_.continuous || !b_ || key != b_key_)) {
    b_ = render_slot(state_.b);
    b_key_ = key;
    display_dirty_ = true;
  }
  if (needs_reference() && !has_reference()) {
    // A reference not in the cache takes a while: the first call shows the methods and says so
    // (reference_pending), the next one renders it.
    if (!reference_pending_) {
      reference_pending_ = true;
      display_dirty_ = true;
    } else {
      reference_ = session_.reference(state_.frame, {&a_->frame}, state_.free_camera);
      reference_key_ = view_key();
      reference_pending_ = false;
      display_dirty_ = true;
    }
  }
  if (!display_dirty_) return;

  const Frame* truth = has_reference() ? &reference_->mean : nullptr;
  auto shown_image = [&](const Frame& f, bool is_method) {
    Image d = display_of(f);
    if (state_.error_overlay && is_method && truth)
      d = blend_images(d, error_map_display(f.total, truth->total), state_.overlay_opacity);
    return d;
  };
  const bool second_shown = second_method || truth;
  if (state_.mode == CompareMode::Single || !second_shown) {
    display_ = shown_image(a_->frame, true);
  } else {
    const bool show_first = state_.mode == CompareMode::Split || !state_.showing_second;
    const bool show_second = state_.mode == CompareMode::Split || state_.showing_second;
    Image first = show_first ? shown_image(a_->frame, true) : Image();
    Image second;
    if (show_second) second = second_method ? shown_image(b_->frame, true) : shown_image(*truth, false);
    display_ = state_.mode == CompareMode::Split ? split_images(first, second, state_.split)
                                                 : (show_second ? std::move(second) : std::move(first));
  }

  if (!texture_ || texture_width_ != display_.width() || texture_height_ != display_.height()) {
    texture_ = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture_.id(), 1, GL_RGBA8, display_.width(), display_.height());
    // Nearest: a pixel stays a square when enlarged, as sub-pixel detail must be seen.
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    texture_width_ = display_.width();
    texture_height_ = display_.height();
  }
  const auto rgba = to_rgba8(display_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture_.id(), 0, 0, 0, texture_width_, texture_height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  check_gl("uploading the viewer's image");
  display_dirty_ = false;
}

std::string Viewer::screenshot(const std::string& path) {
  const FrameOutput target = frame_output(path, state_.a.method->id);
  update();
  Film film = session_.scene().film;
  film.exposure = state_.exposure;
  film.bloom = state_.bloom;
  write_frame(target.dir, target.stem, a_->frame, film);

  const MethodSlot& a = state_.a;
  nlohmann::json json;
  json["scene"] = session_.options().scene.empty() ? std::string(kDefaultScene) : session_.options().scene;
  json["method"] = a.method->id;
  std::string params;  // the --param flags of what differs from the defaults
  const ParamValues defaults = resolve_params(*a.method, {});
  for (const auto& p : a.method->params) {
    json["params"][p.name] = a.params.at(p.name);
    if (a.params.at(p.name) != defaults.at(p.name)) params += " --param " + p.name + "=" + param_text(p, a.params.at(p.name));
  }
  json["frame"] = state_.frame;
  json["width"] = width();
  json["height"] = height();
  json["camera"] = camera_json(camera());
  json["on_path"] = !state_.free_camera.has_value();
  json["exposure"] = state_.exposure;
  json["bloom"] = state_.bloom;
  const Film& scene_film = session_.scene().film;
  if (!state_.free_camera && film.exposure == scene_film.exposure && film.bloom == scene_film.bloom)
    json["render_command"] = "glintlab render --scene " + json["scene"].get<std::string>() + " --method " + a.method->id +
                             params + " --frame " + std::to_string(state_.frame) + " --width " +
                             std::to_string(width()) + " --height " + std::to_string(height()) + " -o " +
                             (target.dir / (target.stem + ".exr")).string();
  write_text_file(target.dir / (target.stem + ".json"), json.dump(2) + "\n");
  return (target.dir / (target.stem + ".exr")).string();
}

}  // namespace glintlab
