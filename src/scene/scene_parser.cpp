// The TOML scene format: the file's tables (film, camera and path, shapes, lights); materials,
// normal maps and glTF shapes are read by their own parsers (materials/, normal_maps/, gltf/).
// Every key is documented in docs/scene-format.md; keep the two in step.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "core/file_access.hpp"
#include "scene/gltf/gltf_shape.hpp"
#include "scene/lights/light_kind.hpp"
#include "scene/mesh_io.hpp"
#include "scene/materials/material_parser.hpp"
#include "scene/scene_loader.hpp"
#include "scene/toml_nesting.hpp"
#include "scene/toml_reader.hpp"

namespace glintlab {

namespace {

constexpr double kBig = 1e6;  // bound on positions and lengths, in scene units

void parse_film(TomlReader r, Film& film) {
  film.width = r.get_int("width", film.width, 1, kMaxFilmSide);
  film.height = r.get_int("height", film.height, 1, kMaxFilmSide);
  if (static_cast<double>(film.width) * film.height > kMaxFilmPixels)
    r.fail("height", "film " + std::to_string(film.width) + "x" + std::to_string(film.height) +
                         " has more than 64 Mpixels; allowed: width * height <= 67108864");
  film.exposure = static_cast<float>(r.get_number("exposure", film.exposure, -30, 30));
  film.bloom = static_cast<float>(r.get_number("bloom", film.bloom, 0, 10));
  r.finish();
}

void parse_path(TomlReader r, CameraPath& path) {
  const auto type = r.require_string("type", {"static", "orbit", "dolly", "keyframes"});
  path.frames = r.get_int("frames", 60, 1, kMaxPathFrames);
  if (type == "static") {
    path.type = CameraPathType::Static;
  } else if (type == "orbit") {
    path.type = CameraPathType::Orbit;
    path.orbit_degrees = static_cast<float>(r.get_number("degrees", 10, -3600, 3600));
    path.orbit_axis = r.get_vec3("axis", {0, 1, 0});
    if (glm::length(path.orbit_axis) < 1e-6f) r.fail("axis", "value is a zero vector; allowed: any non-zero vector");
  } else if (type == "dolly") {
    path.type = CameraPathType::Dolly;
    path.dolly_to = r.require_vec3("to");
  } else {
    path.type = CameraPathType::Keyframes;
    for (const toml::table* key : r.get_table_array("keys")) {
      TomlReader k(*key, r.file(), "[camera.path] keys[" + std::to_string(path.keys.size()) + "]");
      path.keys.push_back({k.require_vec3("position"), k.require_vec3("target")});
      k.finish();
    }
    if (path.keys.size() < 2) r.fail("keys", "has " + std::to_string(path.keys.size()) + " keys; allowed: at least 2");
  }
  r.finish();
}

void parse_camera(TomlReader r, Camera& cam, CameraPath& path, const std::vector<GltfCamera>& gltf_cameras) {
  if (r.has("gltf_camera")) {
    // A camera of an imported glTF file as the starting point; the table's other keys override it.
    const auto name = r.require_string("gltf_camera");
    auto it = std::find_if(gltf_cameras.begin(), gltf_cameras.end(), [&](const GltfCamera& c) { return c.name == name; });
    if (it == gltf_cameras.end()) {
      std::string known;
      for (const auto& c : gltf_cameras) known += (known.empty() ? "" : ", ") + c.name;
      r.fail("gltf_camera", "value \"" + name + "\" names no camera of the scene's glTF files; they have: " +
                                (known.empty() ? "none" : known));
    }
    cam = it->camera;
  }
  const auto type = r.get_string("type", cam.projection == Projection::Perspective ? "perspective" : "orthographic",
                                 {"perspective", "orthographic"});
  cam.projection = type == "perspective" ? Projection::Perspective : Projection::Orthographic;
  cam.position = r.get_vec3("position", cam.position);
  cam.target = r.get_vec3("target", cam.target);
  cam.up = r.get_vec3("up", cam.up);
  cam.fov_y_degrees = static_cast<float>(r.get_number("fov", cam.fov_y_degrees, 0.01, 179));
  cam.view_height = static_cast<float>(r.get_number("view_height", cam.view_height, 1e-6, kBig));
  cam.near_plane = static_cast<float>(r.get_number("near", cam.near_plane, 1e-6, kBig));
  cam.far_plane = static_cast<float>(r.get_number("far", cam.far_plane, 1e-6, kBig));
  if (cam.far_plane <= cam.near_plane)
    r.fail("far", "value " + std::to_string(cam.far_plane) + " is not greater than near (" +
                      std::to_string(cam.near_plane) + ")");
  const glm::vec3 forward = cam.target - cam.position;
  if (glm::length(forward) < 1e-9f) r.fail("target", "equals the position; the camera needs a direction");
  if (glm::length(glm::cross(forward, cam.up)) < 1e-9f * glm::length(forward))
    r.fail("up", "is parallel to the viewing direction");
  if (const toml::table* p = r.get_table("path")) {
    parse_path(TomlReader(*p, r.file(), "[camera.path]"), path);
    // Every frame of the path obeys the rules of a static camera (a direction, an up not along it).
    for (int t = 0; t < path.frames; ++t) {
      const Camera c = path.at(cam, t);
      const glm::vec3 f = c.target - c.position;
      if (glm::length(f) < 1e-9f)
        r.fail("path", "frame " + std::to_string(t) + " puts the camera at its target; every frame needs a direction");
      if (glm::length(glm::cross(f, c.up)) < 1e-9f * glm::length(f))
        r.fail("path", "frame " + std::to_string(t) + " looks along `up`; every frame needs an up not parallel to its view");
    }
  }
  r.finish();
}

glm::mat4 parse_transform(TomlReader& r) {
  const glm::vec3 t = r.get_vec3("translate", glm::vec3(0.0f));
  const glm::vec3 rot = r.get_vec3("rotate", glm::vec3(0.0f));
  const glm::vec3 s = r.get_colour("scale", glm::vec3(1.0f), 1e-6, kBig);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), t);
  m = glm::rotate(m, glm::radians(rot.z), {0, 0, 1});
  m = glm::rotate(m, glm::radians(rot.y), {0, 1, 0});
  m = glm::rotate(m, glm::radians(rot.x), {1, 0, 0});
  return glm::scale(m, s);
}

void parse_shape(TomlReader r, const std::map<std::string, int>& materials, const std::filesystem::path& base_dir,
                 Scene& scene, std::vector<GltfCamera>& cameras) {
  Shape shape;
  shape.type = r.require_string("type", {"sphere", "plane", "disk", "torus", "tube", "cylinder", "mesh"});
  if (shape.type == "mesh" && r.has("file") && is_gltf(r.require_string("file"))) {
    add_gltf(r, parse_transform(r), materials, base_dir, scene, cameras);
    return;
  }
  shape.material = material_named(r, "material", r.require_string("material"), materials);
  shape.transform = parse_transform(r);
  Mesh mesh;
  const std::string& type = shape.type;
  if (type == "sphere") {
    const auto radius = static_cast<float>(r.get_number("radius", 1.0, 1e-6, kBig));
    const int segments = r.get_int("segments", 128, 3, 4096);
    mesh = make_sphere(radius, segments, r.get_int("rings", segments / 2, 2, 4096));
  } else if (type == "plane") {
    const glm::vec2 size = r.get_vec2("size", glm::vec2(2.0f), 1e-6, kBig);
    const auto uv_scale = static_cast<float>(r.get_number("uv_scale", 1.0, 1e-6, kBig));
    mesh = make_plane(size, uv_scale, r.get_int("subdivisions", 1, 1, 4096));
  } else if (type == "disk") {
    const auto radius = static_cast<float>(r.get_number("radius", 1.0, 1e-6, kBig));
    mesh = make_disk(radius, r.get_int("segments", 128, 3, 65536));
  } else if (type == "torus") {
    const auto major = static_cast<float>(r.get_number("major_radius", 1.0, 1e-6, kBig));
    const auto minor = static_cast<float>(r.get_number("minor_radius", 0.25, 1e-6, kBig));
    const int segments = r.get_int("segments", 128, 3, 4096);
    mesh = make_torus(major, minor, segments, r.get_int("sides", 48, 3, 4096));
  } else if (type == "tube") {
    const auto points = r.require_vec3_list("points", 2);
    // The tube's frame starts from the direction between points: coincident points have none.
    if (std::all_of(points.begin(), points.end(), [&](const glm::vec3& p) { return p == points.front(); })) {
      std::ostringstream s;
      s << "all " << points.size() << " points are [" << points[0].x << ", " << points[0].y << ", " << points[0].z
        << "]; allowed: at least two different points";
      r.fail("points", s.str());
    }
    const auto radius = static_cast<float>(r.get_number("radius", 0.05, 1e-6, kBig));
    const int segments = r.get_int("segments", 16, 1, 1024);
    const int sides = r.get_int("sides", 16, 3, 1024);
    if (const auto vertices = tube_vertex_count(points.size(), segments, sides); vertices > kMaxShapeVertices)
      r.fail("points", std::to_string(points.size()) + " points x " + std::to_string(segments) + " segments x " +
                           std::to_string(sides + 1) + " vertices around make " + std::to_string(vertices) +
                           " vertices; allowed: at most " + std::to_string(kMaxShapeVertices) +
                           " per shape (fewer points, segments or sides)");
    mesh = make_tube(points, radius, segments, sides);
  } else if (type == "cylinder") {
    const auto radius = static_cast<float>(r.get_number("radius", 0.5, 1e-6, kBig));
    const auto height = static_cast<float>(r.get_number("height", 1.0, 1e-6, kBig));
    mesh = make_tube({{0, -0.5f * height, 0}, {0, 0.5f * height, 0}}, radius, 1, r.get_int("sides", 64, 3, 4096));
  } else {
    const auto file = r.require_string("file");
    try {
      mesh = load_mesh_file(base_dir / file);
    } catch (const InputError& e) {
      r.fail("file", e.what());
    }
  }
  r.finish();
  shape.mesh = std::make_shared<Mesh>(std::move(mesh));
  // A generator's broken output comes from the key that shapes it (a tube's points), else from the type.
  if (const auto problem = shape.mesh->validate(); !problem.empty())
    r.fail(type == "tube" ? "points" : "type", "broken geometry: " + problem);
  scene.shapes.push_back(std::move(shape));
}

// The light's kind from `type` (the registered kinds), which reads its own keys.
Light parse_light(TomlReader r, const std::filesystem::path& base_dir) {
  const LightKind& kind = find_light_kind(r.require_string("type", light_kind_ids()));
  Light l = kind.parse(r, base_dir);
  if (!l.kind) l.kind = &kind;
  r.finish();
  return l;
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& file, const std::filesystem::path& base_dir) {
  check_toml_key_depth(text, file);
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    std::ostringstream s;
    s << file << ':' << e.source().begin.line << ':' << e.source().begin.column << ": malformed TOML: " << e.description();
    throw InputError(s.str());
  }
  Scene scene;
  scene.source = file;
  scene.name = std::filesystem::path(file).stem().string();
  TomlReader r(root, file, "");
  scene.description = r.get_string("description", "");
  if (const toml::table* film = r.get_table("film")) parse_film(TomlReader(*film, file, "[film]"), scene.film);
  std::map<std::string, int> material_index;
  for (const toml::table* t : r.get_table_array("material")) {
    TomlReader mr(*t, file, "[[material]] #" + std::to_string(scene.materials.size() + 1));
    Material m = parse_material(mr, base_dir);
    if (material_index.contains(m.name)) mr.fail("name", "value \"" + m.name + "\" is defined twice; names must be unique");
    material_index[m.name] = static_cast<int>(scene.materials.size());
    scene.materials.push_back(std::move(m));
  }
  const std::size_t scene_file_materials = scene.materials.size();
  std::vector<GltfCamera> gltf_cameras;
  const auto shape_tables = r.get_table_array("shape");
  for (std::size_t i = 0; i < shape_tables.size(); ++i)
    parse_shape(TomlReader(*shape_tables[i], file, "[[shape]] #" + std::to_string(i + 1)), material_index, base_dir,
                scene, gltf_cameras);
  const std::size_t gltf_lights = scene.lights.size();
  for (const toml::table* t : r.get_table_array("light"))
    scene.lights.push_back(
        parse_light(TomlReader(*t, file, "[[light]] #" + std::to_string(scene.lights.size() - gltf_lights + 1)),
                    base_dir));
  // The camera: the [camera] table (which may start from a glTF camera), else the first camera of
  // the glTF files, else the default.
  if (const toml::table* cam = r.get_table("camera"))
    parse_camera(TomlReader(*cam, file, "[camera]"), scene.camera, scene.path, gltf_cameras);
  else if (!gltf_cameras.empty())
    scene.camera = gltf_cameras.front().camera;
  r.finish();
  if (scene.shapes.empty()) throw InputError(file + ": the scene has no [[shape]]; at least one is required");
  if (scene.lights.empty())
    throw InputError(file + ": the scene has no light ([[light]] or a glTF file's); at least one is required");
  // The environment's maps are bound once (its resource), not per light.
  if (std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return !l.kind->compact; }) > 1)
    throw InputError(file + ": more than one light of type \"environment\"; allowed: at most one");
  if (scene.lights.size() > static_cast<std::size_t>(kMaxLights))
    throw InputError(file + ": " + std::to_string(scene.lights.size()) + " lights (" + std::to_string(gltf_lights) +
                     " from glTF files); allowed: at most " + std::to_string(kMaxLights));
  if (scene.materials.size() > static_cast<std::size_t>(kMaxMaterials))
    throw InputError(file + ": " + std::to_string(scene.materials.size()) + " materials (" +
                     std::to_string(scene.materials.size() - scene_file_materials) +
                     " from glTF files); allowed: at most " + std::to_string(kMaxMaterials));
  return scene;
}

Scene load_scene(const std::string& spec) {
  if (spec.rfind("builtin:", 0) == 0) {
    const std::string name = spec.substr(8);
    Scene scene = parse_scene(builtin_scene_toml(name), spec, ".");
    scene.name = name;
    return scene;
  }
  const std::filesystem::path path(spec);
  if (file_kind(path) == FileKind::missing)
    throw InputError(spec + ": scene file does not exist (or use builtin:NAME; see 'glintlab scenes')");
  require_regular_file(path, "scene file");
  if (is_gltf(spec)) {
    // A glTF file alone is the scene of one mesh shape: its materials, lights and first camera.
    std::string file = path.filename().string(), quoted;
    for (char ch : file) quoted += (ch == '"' || ch == '\\') ? std::string("\\") + ch : std::string(1, ch);
    try {
      return parse_scene("[[shape]]\ntype = \"mesh\"\nfile = \"" + quoted + "\"\n", spec, path.parent_path());
    } catch (const InputError& e) {
      // The importer names the file itself; the one-shape scene's own place ("x.gltf:3: [[shape]]
      // #1 key 'file'") is no line of any file the user has.
      const std::string message = e.what();
      if (const auto own = message.find(spec + ": ", 1); own != std::string::npos) throw InputError(message.substr(own));
      throw;
    }
  }
  return parse_scene(read_regular_file(path, "scene file", kMaxTextFileBytes), spec, path.parent_path());
}

}  // namespace glintlab
