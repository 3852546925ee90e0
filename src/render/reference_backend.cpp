#include "render/reference_backend.hpp"

#include <algorithm>
#include <map>

#include "core/error.hpp"
#include "render/path_reference.hpp"
#include "render/raster_reference.hpp"
#include "shading/method_list.hpp"
#include "shading/registry.hpp"

namespace glintlab {

int ReferenceSettings::subpixels() const {
  for (int k = 32; k > 1; --k)
    if (spp % (k * k) == 0 && 4 * k * k <= spp) return k;
  return 1;
}

int ReferenceSettings::effective_light_samples() const {
  return light_samples > 0 ? light_samples : std::max(1, (256 + spp - 1) / spp);
}

void validate_spp(int spp) {
  if (spp < 1 || spp > kMaxReferenceSpp)
    throw InputError("--spp " + std::to_string(spp) + ": allowed: 1 .. " + std::to_string(kMaxReferenceSpp) +
                     " samples per pixel (best 4 k^2: 64, 256, 1024, 4096)");
}

namespace {

/// A well-mixed 32-bit hash (the finaliser of MurmurHash3) for per-pass seeds and jitter.
std::uint32_t mix32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x85ebca6bu;
  x ^= x >> 13;
  x *= 0xc2b2ae35u;
  x ^= x >> 16;
  return x;
}

float unit_float(std::uint32_t x) { return static_cast<float>(x >> 8) * (1.0f / 16777216.0f); }

}  // namespace

std::uint32_t reference_pass_seed(int frame_seed, int pass) {
  return mix32(static_cast<std::uint32_t>(frame_seed) * 0x9e3779b9u ^ mix32(static_cast<std::uint32_t>(pass) + 1u));
}

glm::vec2 reference_pass_jitter(int frame_seed, int pass) {
  const std::uint32_t h = mix32(reference_pass_seed(frame_seed, pass) ^ 0x6a09e667u);
  return {unit_float(h), unit_float(mix32(h))};
}

ReferencePass ReferencePass::of(const ReferenceSettings& settings, int index) {
  return {settings.subpixels(), settings.effective_light_samples(), reference_pass_seed(settings.seed, index),
          reference_pass_jitter(settings.seed, index), settings.filter, settings.region, settings.max_depth};
}

FilmRegion FilmRegion::within(int film_width, int film_height) const {
  return empty() ? FilmRegion{0, 0, film_width, film_height} : *this;
}

FilmRegion FilmRegion::grid_tile(int film_width, int film_height, int columns, int rows, int index) {
  const int column = index % columns, row = index / columns;
  auto edge = [](int size, int parts, int i) {
    return static_cast<int>(static_cast<long long>(size) * i / parts);
  };
  const int x0 = edge(film_width, columns, column), x1 = edge(film_width, columns, column + 1);
  const int y0 = edge(film_height, rows, row), y1 = edge(film_height, rows, row + 1);
  return {x0, y0, x1 - x0, y1 - y0};
}

ReferenceFrame render_reference(ReferenceBackend& backend, const Camera& camera, int width, int height,
                                const ReferenceSettings& settings, const ProgressFn& progress) {
  validate_spp(settings.spp);
  const int k = settings.subpixels(), passes = settings.passes();
  const FilmRegion region = settings.region.within(width, height);
  ReferenceAccumulator accumulator(region.width, region.height, k * k);
  for (int p = 0; p < passes; ++p)
    accumulator.add_pass(backend.render_pass(camera, width, height, ReferencePass::of(settings, p), [&](int done, int total) {
      if (progress) progress(p * total + done, passes * total);
    }));
  return accumulator.result();
}

const std::vector<ReferenceBackendEntry>& reference_backends() {
  static const std::vector<ReferenceBackendEntry> entries = {
      {"raster",
       "the forward renderer at k x k jittered sub-pixels per pixel, unfiltered textures, lights with extent by MIS",
       [](const ReferenceBackendContext& c) { return std::make_unique<RasterReference>(c); }},
      {"raster-realisation",
       "raster, with binomial-glints materials as one fixed realisation of their microfacets (slope cells with "
       "binomial counts) integrated over each light: the physical question, not the counting model",
       [](const ReferenceBackendContext& c) {
         return std::make_unique<RasterReference>(c, "raster-realisation", kRealisationReferenceModule);
       }},
      {"path",
       "a path tracer: Embree's rays on the CPU, the hits shaded by the raster reference's GLSL on the GL device, "
       "direct light with shadows (every light sample's shadow ray traced)",
       [](const ReferenceBackendContext& c) { return std::make_unique<PathReference>(c); }},
      {"path-unshadowed",
       "path with every shadow ray unblocked, direct light only: the raster reference's light transport traced, "
       "to hold the two backends to each other on any scene",
       [](const ReferenceBackendContext& c) { return std::make_unique<PathReference>(c, false); }},
      {"raster-facets",
       "raster, with binomial-glints materials as one fixed field of mirror facets, one per uv cell of "
       "e^log_density per unit area with a GGX normal of its own random stream: the binomial methods' "
       "ground truth independent of their counting model and of every footprint",
       [](const ReferenceBackendContext& c) {
         return std::make_unique<RasterReference>(c, "raster-facets", kFacetsReferenceModule);
       }},
  };
  return entries;
}

namespace {

/// The methods whose footprint NDF the path tracer can render (MethodDescriptor::path_footprint_ndf),
/// as backend ids: "path:yan2016, path:deng2022".
std::string path_method_backends() {
  std::string ids;
  for (const MethodDescriptor& m : all_methods())
    if (m.path_footprint_ndf) ids += (ids.empty() ? "" : ", ") + std::string(kPathMethodPrefix) + m.id;
  return ids;
}

/// "path:<method variant>": the path tracer with normal-map-glints materials as the variant's
/// footprint NDF; the variant's settings are the method's parameters (its defaults elsewhere).
ReferenceBackendEntry path_method_backend(const std::string& id) {
  const std::string spec = id.substr(std::string(kPathMethodPrefix).size());
  const std::string origin = "--reference-backend " + id;
  const std::vector<MethodVariant> variants = parse_method_variants(spec, origin);
  if (variants.size() != 1 || !variants.front().method->path_footprint_ndf)
    throw InputError(origin + ": the path tracer renders the footprint NDF of one method; allowed: " +
                     path_method_backends() + " (each with settings id{name=value,...})");
  const MethodVariant& v = variants.front();
  std::map<std::string, std::string> settings(v.settings.begin(), v.settings.end());
  MethodChoice choice{v.method, resolve_params(*v.method, settings, origin + ":"), v.name, v.file_name};
  return {kPathMethodPrefix + v.name,
          "path, with normal-map-glints materials as " + v.method->id + "'s footprint NDF",
          [choice](const ReferenceBackendContext& c) { return std::make_unique<PathReference>(c, choice); },
          /*ground_truth=*/false};
}

}  // namespace

ReferenceBackendEntry find_reference_backend(const std::string& id) {
  if (id.starts_with(kPathMethodPrefix)) return path_method_backend(id);
  std::string known;
  for (const auto& e : reference_backends()) {
    if (e.id == id) return e;
    known += (known.empty() ? "" : ", ") + e.id;
  }
  throw InputError("--reference-backend " + id + ": unknown backend; allowed: " + known + ", " + path_method_backends());
}

void require_ground_truth_backend(const std::string& id, const std::string& command) {
  if (find_reference_backend(id).ground_truth) return;
  std::string truths;
  for (const auto& e : reference_backends()) truths += (truths.empty() ? "" : ", ") + e.id;
  throw InputError("--reference-backend " + id + ": renders a method's approximation, which cannot be the ground truth " +
                   command + " judges methods by; allowed: " + truths +
                   " (render --reference and converge take " + id + ")");
}

std::unique_ptr<ReferenceBackend> make_reference_backend(const std::string& id, const ReferenceBackendContext& context) {
  return find_reference_backend(id).create(context);
}

}  // namespace glintlab
