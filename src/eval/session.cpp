#include "eval/session.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>

#include "core/cache_directory.hpp"
#include "core/error.hpp"
#include "core/metrics.hpp"
#include "eval/progress.hpp"
#include "scene/scene_loader.hpp"
#include "shading/registry.hpp"

namespace glintlab {

double reference_noise_target(const Frame& reference, const std::vector<const Frame*>& ranked, double fraction) {
  std::vector<double> errors;
  for (const Frame* f : ranked) errors.push_back(rmse(f->total, reference.total));
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < errors.size(); ++i) {
    smallest = std::min(smallest, errors[i]);
    for (std::size_t j = i + 1; j < errors.size(); ++j)
      if (const double d = std::abs(errors[i] - errors[j]); d > 1e-9) smallest = std::min(smallest, d);
  }
  return std::isfinite(smallest) ? fraction * smallest : 0.0;
}

void parse_spp(const std::string& text, const std::string& flag, CommonOptions& options) {
  if (text == "auto") {
    options.spp_auto = true;
    return;
  }
  try {
    std::size_t used = 0;
    options.spp = std::stoi(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
  } catch (const std::exception&) {
    throw InputError(flag + "=" + text + ": not a number; allowed: 1 .. " + std::to_string(kMaxReferenceSpp) +
                     " samples per pixel, or auto");
  }
  options.spp_auto = false;
  validate_spp(options.spp);
  if (options.max_spp < 4 * kProgressivePassSpp || options.max_spp > kMaxReferenceSpp)
    throw InputError("--max-spp " + std::to_string(options.max_spp) + ": allowed: " +
                     std::to_string(4 * kProgressivePassSpp) + " .. " + std::to_string(kMaxReferenceSpp));
  if (!(options.noise_fraction > 0.0 && options.noise_fraction <= 1.0))
    throw InputError("--noise-fraction " + std::to_string(options.noise_fraction) + ": allowed: (0, 1]");
}

FilmRegion parse_tile(const std::string& text, int width, int height) {
  const std::string allowed = "allowed: INDEX/COLUMNSxROWS with 1 <= COLUMNS <= " + std::to_string(width) +
                              ", 1 <= ROWS <= " + std::to_string(height) + " (the " + std::to_string(width) + "x" +
                              std::to_string(height) + " film) and 0 <= INDEX < COLUMNS x ROWS, e.g. 5/4x4";
  long long index = -1, columns = 0, rows = 0;
  char slash = 0, times = 0, extra = 0;
  const int fields = std::sscanf(text.c_str(), "%lld%c%lld%c%lld%c", &index, &slash, &columns, &times, &rows, &extra);
  if (fields != 5 || slash != '/' || times != 'x' || text.find_first_of(" +-") != std::string::npos)
    throw InputError("--tile " + text + ": not INDEX/COLUMNSxROWS; " + allowed);
  if (columns < 1 || columns > width || rows < 1 || rows > height || index < 0 || index >= columns * rows)
    throw InputError("--tile " + text + ": " + allowed);
  return FilmRegion::grid_tile(width, height, static_cast<int>(columns), static_cast<int>(rows), static_cast<int>(index));
}

void require_finite(const Frame& frame, const std::string& what) {
  const auto bad = std::max(frame.total.count_non_finite(), frame.specular.count_non_finite());
  if (bad > 0)
    throw RuntimeFailure(what + ": " + std::to_string(bad) + " pixels are NaN or Inf; no output was written for it");
}

namespace {

/// load_scene, with a progress bar for procedural maps that take a while to generate.
Scene load_scene_showing_progress(const std::string& spec, bool show_progress) {
  const ScopedGenerationObserver observer(terminal_generation_observer(show_progress));
  return load_scene(spec);
}

/// The estimated bytes of what the scene's kinds and the methods read (src/render/resources/),
/// before anything is made.
std::uint64_t resource_bytes(const Scene& scene, const std::vector<MethodChoice>& methods) {
  const TableCache no_cache{std::filesystem::path()};
  std::vector<std::string> ids = scene_resources(scene);
  std::uint64_t bytes = estimate_resource_bytes(ids, {scene, GpuScene::no_params(), no_cache});
  for (const MethodChoice& m : methods) {
    std::vector<std::string> own;
    for (const std::string& id : method_resources(*m.method, m.params))
      if (std::find(ids.begin(), ids.end(), id) == ids.end()) own.push_back(id);
    bytes += estimate_resource_bytes(own, {scene, m.params, no_cache});
  }
  return bytes;
}

}  // namespace

Session::Session(const CommonOptions& options, std::optional<Workload> workload, const ContextFactory& make_context)
    : options_(options),
      scene_(load_scene_showing_progress(options.scene.empty() ? kDefaultScene : options.scene, !options.quiet)),
      cache_(options.no_cache ? std::filesystem::path() : ReferenceCache::default_directory()) {
  // What loading ignored (a glTF extension, an occlusion texture...) is said, never dropped.
  for (const auto& w : scene_.warnings) std::cerr << "glintlab: warning: " << w << "\n";
  if (!options.spp_text.empty()) parse_spp(options.spp_text, "--spp", options_);
  find_reference_backend(options.reference_backend);  // an unknown id fails before any GL work
  reference_.filter = PixelFilter::parse(options.reference_filter);
  validate_spp(options_.spp);
  if (options.max_spp < 4 * kProgressivePassSpp || options.max_spp > kMaxReferenceSpp)
    throw InputError("--max-spp " + std::to_string(options.max_spp) + ": allowed: " +
                     std::to_string(4 * kProgressivePassSpp) + " .. " + std::to_string(kMaxReferenceSpp));
  if (!(options.noise_fraction > 0.0 && options.noise_fraction <= 1.0))
    throw InputError("--noise-fraction " + std::to_string(options.noise_fraction) + ": allowed: (0, 1]");
  if (options.light_samples < 0 || options.light_samples > 4096)
    throw InputError("--light-samples " + std::to_string(options.light_samples) + ": allowed: 0 (auto) .. 4096");
  width_ = options.width != 0 ? options.width : scene_.film.width;  // 0: the scene's
  height_ = options.height != 0 ? options.height : scene_.film.height;
  if (width_ < 1 || height_ < 1 || width_ > kMaxFilmSide || height_ > kMaxFilmSide ||
      static_cast<double>(width_) * height_ > kMaxFilmPixels)
    throw InputError("--width/--height " + std::to_string(width_) + "x" + std::to_string(height_) + ": allowed: 1 .. " +
                     std::to_string(kMaxFilmSide) + " per side and at most 67108864 pixels");
  if (options.frames < 0 || options.frames > kMaxPathFrames)
    throw InputError("--frames " + std::to_string(options.frames) + ": allowed: 1 .. " + std::to_string(kMaxPathFrames));
  frames_ = options.frames > 0 ? options.frames : scene_.path.frames;
  if (options.frames > 0) scene_.path.frames = options.frames;
  if (!options.tile.empty()) {
    if (options.spp_auto)
      throw InputError("--tile with --spp auto: the tiles of one reference must share their passes; allowed: --spp N");
    reference_.region = parse_tile(options.tile, width_, height_);
  }
  if (options.max_depth < 1 || options.max_depth > kMaxPathDepth)
    throw InputError("--max-depth " + std::to_string(options.max_depth) + ": allowed: 1 .. " + std::to_string(kMaxPathDepth));
  if (options.max_depth != 1 && options.reference_backend != "path" &&
      !options.reference_backend.starts_with(kPathMethodPrefix))
    throw InputError("--max-depth " + std::to_string(options.max_depth) + " with --reference-backend " +
                     options.reference_backend +
                     ": that backend draws direct light only; allowed: --reference-backend path or path:<method>");
  reference_.max_depth = options.max_depth;
  reference_.spp = options_.spp_auto ? kProgressivePassSpp * 4 : options_.spp;
  reference_.light_samples = options_.light_samples;
  if (!workload)
    workload = Workload{.methods = static_cast<int>(parse_method_variants(options_.methods).size()), .reference = true,
                        .outputs = true};
  workload->progressive = workload->reference && options_.spp_auto;
  workload->resources = resource_bytes(scene_, resolve_methods(options_.methods, options_.params));
  if (const auto available = available_memory())
    require_memory(estimate_run_memory(*workload, width_, height_, scene_), *workload, width_, height_, *available);
  context_ = make_context();
  device_ = context_->info().renderer;
  shaders_.set_driver_profile(choose_driver_profile(*context_));
  gpu_scene_ = std::make_unique<GpuScene>(
      scene_, TableCache(default_table_cache_directory(), terminal_table_observer(!options.quiet)));
  // The chosen methods' tables now, rather than inside their first (perhaps timed) frame.
  for (const MethodVariant& m : parse_method_variants(options_.methods)) {
    std::vector<std::string> tables;
    for (const std::string& t : all_tables_of(*m.method)) tables.push_back(table_resource_id(t));
    gpu_scene_->resources().require(tables, gpu_scene_->resource_context());
  }
  renderer_ = std::make_unique<Renderer>(shaders_, *gpu_scene_);
  reference_backend_ = make_reference_backend(options.reference_backend, {shaders_, *gpu_scene_, *renderer_});
}

Frame Session::render(const MethodChoice& choice, int frame) {
  Frame f = renderer_->render(*choice.method, choice.params, camera(frame), width_, height_);
  require_finite(f, "method '" + choice.display_name() + "'");
  return f;
}

Session::Rendered Session::render_with_reference(const std::vector<MethodChoice>& methods, int frame) {
  Rendered r;
  for (const auto& m : methods) r.methods.push_back(render(m, frame));
  std::vector<const Frame*> ranked;
  for (const auto& f : r.methods) ranked.push_back(&f);
  r.reference = reference(frame, ranked);
  return r;
}

ReferenceFrame Session::reference(int frame, const std::vector<const Frame*>& ranked, const std::optional<Camera>& at) {
  ReferenceSettings settings = reference_;
  settings.seed = frame;
  const Camera cam = at.value_or(camera(frame));
  if (!options_.spp_auto) {
    const auto key = ReferenceCache::key(scene_, cam, width_, height_, settings, *reference_backend_, device_);
    const FilmRegion region = settings.region.within(width_, height_);
    if (auto cached = cache_.load(key, region.width, region.height)) return *cached;
    ProgressBar bar("reference " + std::to_string(settings.spp) + " spp, frame " + std::to_string(frame), !options_.quiet);
    ReferenceFrame r =
        render_reference(*reference_backend_, cam, width_, height_, settings, [&](int d, int t) { bar.update(d, t); });
    require_finite(r.mean, "reference");
    cache_.store(key, r);
    return r;
  }

  // Progressive: continue from what the cache holds, one pass of k = 8 at a time.
  settings.spp = kProgressivePassSpp * 4;  // k = 8; light samples as for 256 spp
  const int k = settings.subpixels();
  const auto key = ReferenceCache::key(scene_, cam, width_, height_, settings, *reference_backend_, device_, true);
  const auto cached = cache_.load(key, width_, height_);
  ReferenceAccumulator acc = cached ? ReferenceAccumulator(*cached, k * k) : ReferenceAccumulator(width_, height_, k * k);
  const int max_passes = options_.max_spp / (k * k);
  ProgressBar bar("reference auto (<= " + std::to_string(options_.max_spp) + " spp), frame " + std::to_string(frame),
                  !options_.quiet);
  bool grew = false;
  for (;;) {
    if (acc.passes() >= max_passes) break;
    if (acc.passes() >= 4) {
      const ReferenceFrame now = acc.result();
      if (now.noise_rmse() <= reference_noise_target(now.mean, ranked, options_.noise_fraction)) break;
    }
    const int p = acc.passes();
    acc.add_pass(reference_backend_->render_pass(cam, width_, height_, ReferencePass::of(settings, p)));
    grew = true;
    bar.update(std::min(acc.passes(), max_passes), max_passes);
  }
  ReferenceFrame r = acc.result();
  require_finite(r.mean, "reference");
  if (grew) cache_.store(key, r);
  return r;
}

}  // namespace glintlab
