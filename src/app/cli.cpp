#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "core/cache_directory.hpp"
#include "core/error.hpp"
#include "core/file_access.hpp"
#include "core/pixel_filter_width.hpp"
#include "eval/commands.hpp"
#include "eval/convergence.hpp"
#include "eval/outputs.hpp"
#include "eval/environment_fit_report.hpp"
#include "eval/prefilter_report.hpp"
#include "prefilter/prefilter_params.hpp"
#include "eval/program_command.hpp"
#include "export/export_command.hpp"
#include "eval/progress.hpp"
#include "eval/reference_tiles.hpp"
#include "eval/report.hpp"
#include "eval/session.hpp"
#include "gl/driver_profile.hpp"
#include "render/reference_cache.hpp"
#include "tables/gpu_tables.hpp"
#include "scene/materials/material_kind.hpp"
#include "scene/materials/material_reference.hpp"
#include "scene/scene_loader.hpp"
#include "shading/method_reference.hpp"
#include "shading/registry.hpp"
#include "eval/metrics_command.hpp"
#include "view/view_command.hpp"
#include "view/view_script.hpp"

namespace glintlab {

namespace {

/// The flags shared by the commands that render; the same names everywhere.
void add_common(CLI::App* cmd, CommonOptions& o, bool many_methods) {
  cmd->add_option("--scene", o.scene, "scene file (.toml) or builtin:NAME (see 'glintlab scenes')")
      ->default_str(kDefaultScene);
  if (many_methods) {
    cmd->add_option("--methods,--method", o.methods,
                    "comma-separated method ids, variants id{name=value,...} (a name of its own in every output), "
                    "or 'all' (see 'glintlab methods')")
        ->default_str("all");
    o.methods = "all";
  } else {
    cmd->add_option("--method,--methods", o.methods,
                    "method id, or a variant id{name=value,...} (see 'glintlab methods')")
        ->default_str("conventional");
  }
  cmd->add_option("--param", o.params,
                  "set a method parameter: name=value or method.name=value (repeatable; the last one wins, and a "
                  "variant's own settings win over it)");
  cmd->add_option("--spp", o.spp_text,
                  "reference samples per pixel (1 .. 65536; 4 k^2 gives four passes of k x k), or auto: "
                  "add passes until the reference's noise is below --noise-fraction of the differences ranked")
      ->default_str("64");
  cmd->add_option("--max-spp", o.max_spp, "the cap of --spp auto")->default_str("4096");
  cmd->add_option("--noise-fraction", o.noise_fraction,
                  "--spp auto's target: reference noise RMSE over the smallest RMSE or RMSE difference ranked")
      ->default_str("0.1");
  cmd->add_option("--light-samples", o.light_samples,
                  "reference light samples per sub-pixel and area light (0: max(1, 256/spp))")->default_str("0");
  std::string backends;
  for (const auto& b : reference_backends()) backends += (backends.empty() ? "" : "|") + b.id;
  backends += "|path:<method>";
  cmd->add_option("--reference-backend", o.reference_backend,
                  "how the ground truth is computed (" + backends + "; see 'glintlab info')")
      ->default_str(o.reference_backend);
  cmd->add_option("--max-depth", o.max_depth,
                  "path vertices lit by the path backends (--reference-backend path or path:<method>): 1 direct light, more bounces")
      ->default_str("1");
  cmd->add_option("--reference-filter", o.reference_filter,
                  "the reference's pixel filter: box (each pixel's own samples), or gaussian[:S] (every sample "
                  "within 3 S pixels, Gaussian of S = 0.1 .. 4 pixels, default " +
                      pixel_filter_sigma_text() + ": the methods' Gaussian footprint)")
      ->default_str(o.reference_filter);
  cmd->add_option("--width", o.width, "film width in pixels (overrides the scene)")
      ->check(CLI::Range(1, kMaxFilmSide));
  cmd->add_option("--height", o.height, "film height in pixels (overrides the scene)")
      ->check(CLI::Range(1, kMaxFilmSide));
  cmd->add_option("--frames", o.frames, "frames of the camera path (overrides the scene)")
      ->check(CLI::Range(1, kMaxPathFrames));
  cmd->add_flag("--no-cache", o.no_cache, "do not read or write the reference cache");
  cmd->add_flag("-q,--quiet", o.quiet, "no progress bar");
}

/// The viewing FLIP assumes, for the commands that measure (compare, animate).
void add_metric_options(CLI::App* cmd, CommonOptions& o) {
  cmd->add_option("--ppd", o.pixels_per_degree,
                  "FLIP's pixels per degree of visual angle (default 67.02: 0.7 m from a 0.7 m wide 3840-pixel display)")
      ->check(CLI::Range(1.0, 1000.0));
}

std::string default_out(const std::string& command, const CommonOptions& o) {
  std::string scene = o.scene.empty() ? kDefaultScene : o.scene;
  if (scene.rfind("builtin:", 0) == 0) scene = scene.substr(8);
  else scene = std::filesystem::path(scene).stem().string();
  return "out/" + command + "/" + scene;
}

/// "393216 bytes (384 KiB), 780288 bytes (762 KiB) with mips"; one size when there is no mip chain.
std::string table_size_text(const TableBytes& bytes) {
  const auto one = [](std::size_t b) { return std::to_string(b) + " bytes (" + std::to_string(b / 1024) + " KiB)"; };
  return bytes.with_mips == bytes.base ? one(bytes.base) : one(bytes.base) + ", " + one(bytes.with_mips) + " with mips";
}

std::string ms_text(double ms) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f ms", ms);
  return text;
}

void print_methods() {
  const TableCache tables(default_table_cache_directory());
  for (const auto& m : all_methods()) {
    std::cout << m.id << " — " << m.title << "\n  " << m.summary << "\n  source: " << m.citation << "\n";
    for (const auto& p : m.params)
      std::cout << "  --param " << p.name << "=" << p.default_text() << "  (" << p.allowed() << ") "
                << p.description << "\n";
    for (const auto& id : all_tables_of(m)) {
      const TableSummary t = summarise_table(id, tables);
      std::cout << "  table " << id << ": " << table_size_text(t.table->gpu_bytes) << " on the GPU; "
                << (t.cached_generation_ms ? "cached (generating took " + ms_text(*t.cached_generation_ms) + ")"
                                           : std::string("not cached yet (generated on first use)"))
                << "\n";
    }
    std::cout << "\n";
  }
}

void print_info() {
  auto ctx = GlContext::create_headless();
  const auto i = ctx->info();
  std::cout << "platform:        " << i.egl_platform << "\n"
            << "vendor:          " << i.vendor << "\n"
            << "renderer:        " << i.renderer << (ctx->is_software() ? " (software)" : "") << "\n"
            << "version:         " << i.version << "\n"
            << "GLSL:            " << i.glsl_version << "\n"
            << "driver profile:  " << driver_profile_id(choose_driver_profile(*ctx))
            << " (GLINTLAB_DRIVER_PROFILE=auto|software|hardware; docs/methods.md, \"Driver profiles\")\n"
            << "limits used:\n"
            << "  max texture size          " << i.max_texture_size << "\n"
            << "  max array texture layers  " << i.max_array_layers << "\n"
            << "  max SSBO bindings         " << i.max_ssbo_bindings << "\n"
            << "  max compute invocations   " << i.max_compute_invocations << "\n"
            << "  max draw buffers          " << i.max_draw_buffers << "\n"
            << "  timer queries             " << (i.timer_query ? "yes" : "no") << "\n"
            << "reference cache: " << ReferenceCache::default_directory().string() << "\n"
            << "reference backends (--reference-backend; the first is the default):\n";
  for (const auto& b : reference_backends()) std::cout << "  " << b.id << ": " << b.description << "\n";
  std::string made_from_methods;
  for (const auto& m : all_methods())
    if (m.path_footprint_ndf) made_from_methods += (made_from_methods.empty() ? "" : ", ") + std::string(kPathMethodPrefix) + m.id;
  std::cout << "  " << made_from_methods
            << " (with settings, path:deng2022{environment_lobes=0}): path with normal-map-glints materials as the "
               "method's footprint NDF; a renderer, not a ground truth (render --reference and converge take it)\n";
  // Every precomputed table, loaded from the cache or generated (and cached) now.
  std::cout << "precomputed tables (cache: " << default_table_cache_directory().string() << "):\n";
  for (const TableReport& r : build_every_table(TableCache(default_table_cache_directory(), terminal_table_observer(true)))) {
    const TableSource& source = r.table->source;
    std::cout << "  " << source.id << ": " << source.title << "; " << table_size_text(r.table->gpu_bytes) << "; "
              << (r.build.generated ? "generated now in " + ms_text(r.build.milliseconds)
                                    : "loaded from the cache in " + ms_text(r.build.milliseconds) +
                                          " (generating took " + ms_text(r.build.generation_ms) + ")")
              << ", uploaded in " << ms_text(r.upload_ms) << "\n"
              << "    settings: " << source.settings << " (generator v" << source.version << "); GLSL: "
              << r.table->sampler << " at unit " << r.table->unit << "\n";
  }
}

int render_command(const CommonOptions& o, const std::string& reference_arg, bool reference_given, int frame) {
  CommonOptions opts = o;
  if (reference_given && !reference_arg.empty()) {
    parse_spp(reference_arg, "--reference", opts);
    opts.spp_text.clear();  // --reference=N wins over --spp
  }
  const auto methods = resolve_methods(o.methods, o.params);
  if (methods.size() != 1) throw InputError("render: --method takes one method; use 'compare' for several");
  if (!o.tile.empty() && !reference_given)
    throw InputError("--tile " + o.tile + ": a tile is of a reference; allowed with --reference only");
  // Every output path is checked before the first frame is rendered.
  const std::string name = reference_given ? "reference" : methods[0].file_stem();
  const FrameOutput target = o.out.empty() ? FrameOutput{default_out("render", o), name} : frame_output(o.out, name);
  const std::filesystem::path& dir = target.dir;
  const std::string& stem = target.stem;
  Session session(opts, Workload{.methods = 1, .reference = reference_given});
  if (frame < 0 || frame >= session.frames())
    throw InputError("--frame " + std::to_string(frame) + ": allowed: 0 .. " + std::to_string(session.frames() - 1));
  if (!o.tile.empty()) {
    // One tile of a reference split over jobs (docs/past-one-machine.md): no method image is needed.
    const ReferenceFrame reference = session.reference(frame);
    write_reference_tile(dir, stem, reference, session.scene().film, reference_tile_identity(session, frame),
                         session.reference_settings().region, session.context().info().renderer);
    std::cout << describe_reference(reference) << ", tile " << o.tile << "\n";
    std::cout << "written " << (dir / stem).string() << ".exr, .png and .json\n";
    return 0;
  }
  const Frame method = session.render(methods[0], frame);
  if (reference_given) {
    // --reference=auto sizes the reference by the method's own error (the --method, default conventional).
    const ReferenceFrame reference = session.reference(frame, {&method});
    write_reference(dir, stem, reference, session.scene().film);
    std::cout << describe_reference(reference);
    if (!session.reference_settings().filter.is_box())
      std::cout << ", pixel filter " << session.reference_settings().filter.text();
    std::cout << "\n";
  } else {
    write_frame(dir, stem, method, session.scene().film);
  }
  std::cout << "written " << (dir / stem).string() << ".exr and .png\n";
  return 0;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"glintlab: sub-pixel specular highlights and glints in real time, measured against ground truth"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "glintlab 0.1.0");

  CommonOptions render_o, compare_o, animate_o, bench_o;
  auto* render = app.add_subcommand("render", "render one frame with one method, or the reference");
  add_common(render, render_o, false);
  std::string reference_arg;
  render->add_option("--reference", reference_arg, "render the ground truth instead, with SPP samples per pixel (default 64)")
      ->expected(0, 1);
  int render_frame = 0;
  render->add_option("--frame", render_frame, "frame of the camera path")->default_str("0");
  render->add_option("-o,--out", render_o.out, "output directory, or a .exr/.png file name");
  render->add_option("--tile", render_o.tile,
                     "INDEX/COLUMNSxROWS: with --reference, only tile INDEX of an even grid over the film, and a .json "
                     "beside the .exr for merge-tiles (docs/past-one-machine.md)");

  auto* merge_tiles = app.add_subcommand("merge-tiles", "put a reference's tiles (render --reference --tile) back together");
  std::vector<std::string> merge_inputs;
  std::string merge_out;
  merge_tiles->add_option("tiles", merge_inputs, "the tiles' .exr files (each with its .json beside it)")->required();
  merge_tiles->add_option("-o,--out", merge_out, "output directory, or a .exr/.png file name")->required();

  auto* compare = app.add_subcommand("compare", "render the reference and each method; images, error maps, metrics");
  add_common(compare, compare_o, true);
  int compare_frame = 0;
  compare->add_option("--frame", compare_frame, "frame of the camera path")->default_str("0");
  compare->add_option("-o,--out", compare_o.out, "output directory (default out/compare/SCENE)");
  add_metric_options(compare, compare_o);

  auto* metrics = app.add_subcommand(
      "metrics", "the metrics of an image file against a reference file: RMSE, FLIP (LDR and HDR), sparkle distance");
  MetricsCommandOptions metrics_o;
  std::string metrics_exposures;
  metrics->add_option("test", metrics_o.test, "the image judged: .exr (radiance) or .png (sRGB picture)")->required();
  metrics->add_option("reference", metrics_o.reference, "the reference, of the same kind and size")->required();
  metrics->add_option("--ppd", metrics_o.pixels_per_degree, "FLIP's pixels per degree (default 67.02)")
      ->check(CLI::Range(1.0, 1000.0));
  metrics->add_option("--display-exposure", metrics_o.display_exposure,
                      "stops before the ACES curve of the displayed picture LDR-FLIP judges (.exr inputs)")
      ->default_str("0");
  metrics->add_option("--hdr-exposures", metrics_exposures,
                      "HDR-FLIP's exposures START,STOP,COUNT (default: automatic from the reference)");
  metrics->add_option("--flip-map", metrics_o.flip_map, "write the FLIP error map (HDR-FLIP for .exr) to this .png");
  metrics->add_option("-o,--out", metrics_o.json, "also write the metrics to this .json file");

  auto* animate = app.add_subcommand("animate", "render the camera path; per-frame RMSE and flicker, videos");
  add_common(animate, animate_o, true);
  animate->add_option("-o,--out", animate_o.out, "output directory (default out/animate/SCENE)");
  add_metric_options(animate, animate_o);

  auto* bench = app.add_subcommand("bench", "time each method's frame (GL timer queries and wall clock), as JSON");
  add_common(bench, bench_o, true);
  int bench_frames = 30, bench_warmup = 3;
  bench->add_option("--bench-frames", bench_frames, "timed frames per method")->default_str("30")->check(CLI::Range(1, 100000));
  bench->add_option("--warmup", bench_warmup, "untimed frames first (at least one is drawn: it compiles the programs)")->default_str("3")->check(CLI::Range(0, 1000));
  bench->add_option("-o,--out", bench_o.out, "also write bench.json into this directory");
  bool floor_breakdown = false;
  bench->add_flag("--floor-breakdown", floor_breakdown,
                  "also time the unshaded floor into two RGBA16F targets, one RGBA32F target and depth only");

  CommonOptions converge_o;
  ConvergeOptions converge_options;
  auto* converge = app.add_subcommand(
      "converge", "how fast backends approach a truth: each at rising samples per pixel, RMSE against the truth "
                  "(--reference-backend at --spp) against samples and seconds; table, convergence.json/.csv/.svg");
  add_common(converge, converge_o, false);
  add_metric_options(converge, converge_o);
  converge->add_option("--backends", converge_options.backends,
                       "the backends timed, separated by commas: ids 'glintlab info' lists, or path:<method>{...}")
      ->required();
  converge->add_option("--steps", converge_options.steps, "samples per pixel of each point, rising")
      ->delimiter(',')
      ->default_str("1,4,16,64");
  converge->add_option("--frame", converge_options.frame, "frame of the camera path")->default_str("0");
  converge->add_option("-o,--out", converge_o.out, "output directory (default out/converge/SCENE)");

  CommonOptions view_o;
  ViewOptions view_options;
  auto* view = app.add_subcommand("view", "open a window: methods switched live, split/flip against another method or the "
                                          "reference, magnifier, error map, camera path and free camera (docs/viewer.md)");
  add_common(view, view_o, false);
  view->add_option("--compare", view_options.compare, "the second image of split and flip: a method id, or reference")
      ->default_str("reference");
  view->add_option("--mode", view_options.mode, "single, split or flip at the start")->default_str("single");
  view->add_option("--frame", view_options.frame, "frame of the camera path to start on")->default_str("0");
  view->add_option("--script", view_options.script,
                   "run commands from FILE, one a frame; the commands:\n" + view_script_reference());
  view->add_option("--window-width", view_options.window_width, "window width in screen pixels")
      ->default_str("1280")->check(CLI::Range(320, 16384));
  view->add_option("--window-height", view_options.window_height, "window height in screen pixels")
      ->default_str("800")->check(CLI::Range(240, 16384));

  auto* methods_cmd = app.add_subcommand("methods", "list every method with its parameters, defaults and ranges");
  bool methods_markdown = false;
  methods_cmd->add_flag("--markdown", methods_markdown,
                        "print the method reference of docs/methods.md (see tools/update-reference-docs.sh)");
  auto* materials_cmd =
      app.add_subcommand("materials", "list every material kind (the [[material]] types) with its keys, defaults and ranges");
  bool materials_markdown = false;
  materials_cmd->add_flag("--markdown", materials_markdown,
                          "print the material-kind reference of docs/scene-format.md (see tools/update-reference-docs.sh)");
  auto* scenes = app.add_subcommand("scenes", "list the built-in scenes");
  std::string print_scene;
  scenes->add_option("--print", print_scene, "print a built-in scene's TOML (a template for your own)");
  app.add_subcommand("info", "print the OpenGL device, version and the limits glintlab uses");
  auto* prefilter = app.add_subcommand(
      "prefilter", "precompute (or read from the cache) deng2022's NDF pyramids of a scene's normal-map-glints "
                   "materials and report them level by level");
  std::string prefilter_scene = std::string(kDefaultScene);
  std::vector<std::string> prefilter_params;
  PrefilterReportOptions prefilter_o;
  std::string prefilter_json;
  bool prefilter_no_cache = false;
  prefilter->add_option("--scene", prefilter_scene, "scene file (.toml) or builtin:NAME")->required();
  std::string precompute_names;
  for (const ParamDecl& p : glintlab::prefilter_params()) precompute_names += (precompute_names.empty() ? "" : ", ") + p.name;
  prefilter->add_option("--param", prefilter_params,
                        "a deng2022 parameter that sets the precompute: " + precompute_names +
                            " (name=value, repeatable)");
  prefilter->add_option("--accuracy", prefilter_o.accuracy_footprints,
                        "also compare this many footprints per level with yan2016's NDF images")
      ->check(CLI::Range(0, 10000));
  prefilter->add_flag("--no-cache", prefilter_no_cache, "precompute even if the cache holds the pyramid");
  prefilter->add_option("-o,--out", prefilter_json, "also write the report as JSON to this file");

  auto* environment_fit = app.add_subcommand(
      "environment-fit", "fit a scene's environment by spherical Gaussian lobes as deng2022 shades it (Deng et al. "
                         "2022 sec. 5.4) and report the fit's error per lobe count");
  std::string environment_fit_scene;
  EnvironmentFitOptions environment_fit_o;
  std::string environment_fit_out;
  environment_fit->add_option("--scene", environment_fit_scene, "scene file (.toml) or builtin:NAME")->required();
  environment_fit->add_option("--lobes", environment_fit_o.lobes, "lobe counts to fit (1 .. 1024)")
      ->delimiter(',')
      ->check(CLI::Range(1, 1024))
      ->default_str("8,16,32,48");
  environment_fit->add_option("--rows", environment_fit_o.grid_height,
                              "rows of the map the fit is made on (the methods': " +
                                  std::to_string(kSphericalGaussianFitRows) + "; at most the map's)")
      ->check(CLI::Range(2, 1024))
      ->default_str(std::to_string(kSphericalGaussianFitRows));
  environment_fit->add_option("-o,--out", environment_fit_out,
                              "also write the fit with the last lobe count as a lat-long EXR (a scene's environment "
                              "file: the truth of the lobes' shading without the fit's error)");

  ProgramOptions program_o;
  auto* program = app.add_subcommand(
      "program", "print a forward program's GLSL as the driver gets it (includes expanded, the variant's defines)");
  program->add_option("--method", program_o.method,
                      "a method or variant (as --methods takes one), or a pass: reference, reference-realisation, "
                      "unshaded")->default_str(program_o.method);
  program->add_option("--param", program_o.params, "a method parameter, as the rendering commands take it");
  program->add_option("--material-kind", program_o.material_kind, "the material's kind (see 'glintlab materials')")
      ->default_str(default_material_kind().id);
  program->add_flag("--normal-map", program_o.normal_map, "the material has a normal map");
  program->add_flag("--textures", program_o.textures, "the material's parameters vary per texel (glTF's textures)");
  program->add_flag("--anisotropic", program_o.anisotropic,
                    "the material's lobe can be anisotropic (unequal alphas, a slope correlation, glTF's anisotropy)");
  program->add_flag("--wang-tiles", program_o.wang_tiles,
                    "the normal map is a surface of Wang tiles (normal-map-glints; docs/scene-format.md)");
  program->add_option("--lights", program_o.lights, "lights of each kind, KIND=COUNT,...")->default_str(program_o.lights);
  program->add_option("--stage", program_o.stage, "fragment or vertex")->default_str(program_o.stage);
  program->add_option("--driver-profile", program_o.driver_profile,
                      "software or hardware (docs/methods.md, \"Driver profiles\")")->default_str(program_o.driver_profile);

  ExportOptions export_o;
  auto* export_cmd = app.add_subcommand(
      "export", "one method as a self-contained shader for an engine: GLSL with the entry point glintlabShade, its "
                "SPIR-V, HLSL and MSL, its tables as files and a README on binding them (docs/export.md)");
  export_cmd->add_option("--method", export_o.method, "a method or variant (as --methods takes one)")
      ->default_str(export_o.method);
  export_cmd->add_option("--param", export_o.params, "a method parameter, baked in as a constant");
  export_cmd->add_option("--material-kind", export_o.material_kind, "the material's kind (see 'glintlab materials')")
      ->default_str(default_material_kind().id);
  export_cmd->add_flag("--normal-map", export_o.normal_map, "the material has a normal map");
  export_cmd->add_flag("--textures", export_o.textures, "the material's parameters vary per texel (glTF's textures)");
  export_cmd->add_flag("--anisotropic", export_o.anisotropic, "the material's lobe can be anisotropic");
  export_cmd->add_option("--light", export_o.light, "the kind of the light glintlabShade takes")
      ->default_str(export_o.light);
  export_cmd->add_option("--driver-profile", export_o.driver_profile,
                         "hardware (GPUs: loops kept rolled) or software (docs/methods.md, \"Driver profiles\")")
      ->default_str(export_o.driver_profile);
  export_cmd->add_option("-o,--out", export_o.out, "the directory it is written into")->required();

  auto* report = app.add_subcommand("report", "a static HTML page (index.html, assets/) of compare, animate, bench and converge "
                                               "outputs: sortable metrics, a reference/method slider, videos, plots");
  std::vector<std::string> report_inputs;
  std::string report_out;
  report->add_option("inputs", report_inputs, "output directories, searched for metrics.json and bench.json")->required();
  report->add_option("-o,--out", report_out, "the report's directory")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  try {
    if (app.got_subcommand("methods")) {
      if (methods_markdown) std::cout << method_reference_markdown(all_methods());
      else print_methods();
    } else if (app.got_subcommand("scenes")) {
      if (!print_scene.empty()) {
        std::cout << builtin_scene_toml(print_scene);
      } else {
        for (const auto& s : builtin_scenes())
          std::cout << "builtin:" << s.name << "\n  " << s.description
                    << ("builtin:" + s.name == kDefaultScene ? " (default)" : "") << "\n";
      }
    } else if (app.got_subcommand("materials")) {
      std::cout << (materials_markdown ? material_reference_markdown(all_material_kinds())
                                       : material_listing(all_material_kinds()));
    } else if (app.got_subcommand("info")) {
      print_info();
    } else if (app.got_subcommand("render")) {
      return render_command(render_o, reference_arg, render->count("--reference") > 0, render_frame);
    } else if (app.got_subcommand("merge-tiles")) {
      run_merge_tiles(merge_inputs, merge_out);
    } else if (app.got_subcommand("compare")) {
      const auto methods = resolve_methods(compare_o.methods, compare_o.params);
      if (!compare_o.out.empty()) check_output_directory(compare_o.out);
      require_ground_truth_backend(compare_o.reference_backend, "compare");
      Session session(compare_o);
      if (compare_frame < 0 || compare_frame >= session.frames())
        throw InputError("--frame " + std::to_string(compare_frame) + ": allowed: 0 .. " + std::to_string(session.frames() - 1));
      run_compare(session, methods, compare_o.out.empty() ? default_out("compare", compare_o) : compare_o.out, compare_frame);
    } else if (app.got_subcommand("metrics")) {
      if (!metrics_exposures.empty()) metrics_o.hdr_exposures = parse_hdr_exposures(metrics_exposures);
      run_metrics_command(metrics_o);
    } else if (app.got_subcommand("animate")) {
      const auto methods = resolve_methods(animate_o.methods, animate_o.params);
      if (!animate_o.out.empty()) check_output_directory(animate_o.out);
      require_ground_truth_backend(animate_o.reference_backend, "animate");
      // Kept from frame to frame: each method's last error, and the reference halves' last difference.
      Session session(animate_o, Workload{.methods = static_cast<int>(methods.size()), .reference = true,
                                          .outputs = true, .kept_images = static_cast<int>(methods.size()) + 1});
      run_animate(session, methods, animate_o.out.empty() ? default_out("animate", animate_o) : animate_o.out);
    } else if (app.got_subcommand("prefilter")) {
      if (!prefilter_json.empty()) check_output_file(prefilter_json, "-o");  // before the precompute
      const auto methods = resolve_methods("deng2022", prefilter_params);
      prefilter_o.settings = prefilter_settings_from(methods.front().params);
      prefilter_o.use_cache = !prefilter_no_cache;
      prefilter_o.json = prefilter_json;
      run_prefilter_report(load_scene(prefilter_scene), prefilter_o);
    } else if (app.got_subcommand("environment-fit")) {
      if (!environment_fit_out.empty()) check_output_file(environment_fit_out, "-o");
      environment_fit_o.out_exr = environment_fit_out;
      run_environment_fit_report(load_scene(environment_fit_scene), environment_fit_o);
    } else if (app.got_subcommand("view")) {
      return run_view(view_o, view_options);
    } else if (app.got_subcommand("export")) {
      for (const std::string& file : run_export(export_o)) std::cout << export_o.out << "/" << file << "\n";
    } else if (app.got_subcommand("program")) {
      std::cout << program_source(program_o);
    } else if (app.got_subcommand("converge")) {
      if (converge_options.steps.empty()) converge_options.steps = {1, 4, 16, 64};
      converge_options.light_samples = std::max(1, converge_o.light_samples);
      check_converge_options(converge_options);
      if (!converge_o.out.empty()) check_output_directory(converge_o.out);
      Session session(converge_o, Workload{.methods = 1, .reference = true, .outputs = true});
      if (converge_options.frame < 0 || converge_options.frame >= session.frames())
        throw InputError("--frame " + std::to_string(converge_options.frame) + ": allowed: 0 .. " +
                         std::to_string(session.frames() - 1));
      run_converge(session, converge_options,
                   converge_o.out.empty() ? default_out("converge", converge_o) : converge_o.out);
    } else if (app.got_subcommand("report")) {
      run_report({report_inputs.begin(), report_inputs.end()}, report_out);
    } else if (app.got_subcommand("bench")) {
      const auto methods = resolve_methods(bench_o.methods, bench_o.params);
      if (!bench_o.out.empty()) check_output_file(std::filesystem::path(bench_o.out) / "bench.json", "-o");
      Session session(bench_o, Workload{.methods = 1});
      run_bench(session, methods, bench_frames, bench_warmup, bench_o.out, floor_breakdown);
    }
  } catch (const InputError& e) {
    std::cerr << "glintlab: error: " << e.what() << "\n";
    return 2;
  } catch (const RuntimeFailure& e) {
    std::cerr << "glintlab: failed: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "glintlab: failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace glintlab
